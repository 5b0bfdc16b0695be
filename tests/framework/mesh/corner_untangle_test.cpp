// Untangling a quad mesh by its corners' areas (framework/mesh/
// corner_untangle.h; value types, no CAD).
#include "framework/mesh/corner_untangle.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace cooperage::mesh {
namespace {

// An n x n grid of unit quads on the plane z = 0, boundary nodes fixed.
struct Grid {
  explicit Grid(int cells) : n(cells) {
    for (int i = 0; i <= n; ++i) {
      for (int j = 0; j <= n; ++j) {
        x.emplace_back(i, j, 0);
        fixed.push_back(i == 0 || j == 0 || i == n || j == n);
      }
    }
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        quads.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
    normals.assign(x.size(), Vec3(0, 0, 1));
  }
  int id(int i, int j) const { return i * (n + 1) + j; }
  Vec3& at(int i, int j) { return x[static_cast<size_t>(id(i, j))]; }
  // The smallest signed corner area (z component of the edges' cross product).
  double worst_corner() const {
    double m = 1e300;
    for (const auto& q : quads) {
      for (size_t k = 0; k < 4; ++k) {
        const Vec3& p = x[static_cast<size_t>(q[k])];
        const Vec3 a = x[static_cast<size_t>(q[(k + 1) % 4])] - p;
        const Vec3 b = x[static_cast<size_t>(q[(k + 3) % 4])] - p;
        m = std::min(m, a.x() * b.y() - a.y() * b.x());
      }
    }
    return m;
  }
  int n;
  std::vector<Vec3> x, normals;
  std::vector<bool> fixed;
  std::vector<Quad> quads;
};

const CornerProjector kPlane = [](const Vec3& p, size_t) {
  return geom::SurfaceProjection{Vec3(p.x(), p.y(), 0), Vec3(0, 0, 1), geom::Vec2(p.x(), p.y()),
                                 std::abs(p.z())};
};

TEST(CornerUntangle, ScrambledGridsComeUntangled) {
  for (unsigned seed = 1; seed <= 5; ++seed) {
    Grid g(10);
    std::mt19937 random(seed);
    const auto offset = [&] { return 1.6 * (static_cast<double>(random()) / random.max() - 0.5); };
    for (size_t k = 0; k < g.x.size(); ++k) {
      if (g.fixed[k]) continue;
      const double dx = offset();
      g.x[k] += Vec3(dx, offset(), 0);
    }
    ASSERT_LT(g.worst_corner(), 0.0) << seed;
    const std::vector<Vec3> before = g.x;
    EXPECT_TRUE(untangle_corners(g.x, g.normals, g.fixed, g.quads, kPlane)) << seed;
    EXPECT_GT(g.worst_corner(), 0.0) << seed;
    for (size_t k = 0; k < g.x.size(); ++k) {
      EXPECT_EQ(g.x[k].z(), 0.0) << "projected onto the plane";
      if (g.fixed[k]) {
        EXPECT_EQ(g.x[k], before[k]);
      }
    }
  }
}

TEST(CornerUntangle, AGoodMeshIsLeftAsItIs) {
  Grid g(5);
  g.at(2, 3) = Vec3(2.2, 2.9, 0);  // a little off: every corner above beta
  const std::vector<Vec3> before = g.x;
  EXPECT_TRUE(untangle_corners(g.x, g.normals, g.fixed, g.quads, kPlane));
  EXPECT_EQ(g.x, before);
}

TEST(CornerUntangle, AFoldOfFixedNodesIsReportedNotHidden) {
  Grid g(3);
  g.at(1, 1) = Vec3(2.5, 2.5, 0);
  g.fixed.assign(g.x.size(), true);
  const std::vector<Vec3> before = g.x;
  EXPECT_FALSE(untangle_corners(g.x, g.normals, g.fixed, g.quads, kPlane));
  EXPECT_EQ(g.x, before);
}

}  // namespace
}  // namespace cooperage::mesh
