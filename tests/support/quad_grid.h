// An n x n grid of unit quads on the plane z = 0, for the untangling tests
// (tests only): boundary nodes fixed, normals +z, and a scrambled copy with
// every free node thrown up to 0.8 cells off its place (dozens of folds side
// by side).
#pragma once

#include "framework/geometry/evaluators.h"
#include "framework/mesh/mesh_db.h"

#include <cmath>
#include <random>
#include <vector>

namespace cooperage::testing {

struct QuadGrid {
  explicit QuadGrid(int cells) : n(cells) {
    for (int i = 0; i <= n; ++i) {
      for (int j = 0; j <= n; ++j) {
        x.emplace_back(i, j, 0);
        fixed.push_back(i == 0 || j == 0 || i == n || j == n);
      }
    }
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        quads.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
    normals.assign(x.size(), geom::Vec3(0, 0, 1));
  }
  int id(int i, int j) const { return i * (n + 1) + j; }
  geom::Vec3& at(int i, int j) { return x[static_cast<size_t>(id(i, j))]; }

  int n;
  std::vector<geom::Vec3> x, normals;
  std::vector<bool> fixed;
  std::vector<mesh::Quad> quads;
};

/// A 10 x 10 grid whose free nodes are moved by up to 0.8 cells in x and y
/// (std::mt19937's raw numbers: the same grid on every standard library).
inline QuadGrid scrambled_grid(unsigned seed) {
  QuadGrid g(10);
  std::mt19937 random(seed);
  const auto offset = [&] { return 1.6 * (static_cast<double>(random()) / random.max() - 0.5); };
  for (size_t k = 0; k < g.x.size(); ++k) {
    if (g.fixed[k]) continue;
    const double dx = offset();
    g.x[k] += geom::Vec3(dx, offset(), 0);
  }
  return g;
}

/// Projection onto the plane z = 0.
inline geom::SurfaceProjection onto_plane(const geom::Vec3& p, size_t) {
  return {geom::Vec3(p.x(), p.y(), 0), geom::Vec3(0, 0, 1), geom::Vec2(p.x(), p.y()),
          std::abs(p.z())};
}

}  // namespace cooperage::testing
