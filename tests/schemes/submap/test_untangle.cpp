// Untangling a folded quad mesh around its folds (value types, no CAD).
#include "schemes/submap/untangle.h"

#include "framework/mesh/corner_untangle.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace cooperage::submap {
namespace {

using Vec2 = Eigen::Vector2d;

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
  double worst() const {
    double m = 1;
    for (const auto& q : quads) {
      std::array<Vec3, 4> p, nn;
      for (size_t k = 0; k < 4; ++k) {
        p[k] = x[static_cast<size_t>(q[k])];
        nn[k] = Vec3(0, 0, 1);
      }
      m = std::min(m, quad_scaled_jacobian(p, nn));
    }
    return m;
  }
  int n;
  std::vector<Vec3> x, normals;
  std::vector<bool> fixed;
  std::vector<mesh::Quad> quads;
};

const Projector kPlane = [](const Vec3& p, size_t) {
  return geom::SurfaceProjection{Vec3(p.x(), p.y(), 0), Vec3(0, 0, 1), Vec2(p.x(), p.y()),
                                 std::abs(p.z())};
};

TEST(SubmapUntangle, AFoldIsUndoneAndNodesFarFromItStay) {
  Grid g(8);
  g.at(2, 2) = Vec3(3.6, 3.4, 0);  // past its neighbour (3, 3): four quads fold
  ASSERT_LE(g.worst(), 0.0);
  const std::vector<Vec3> before = g.x;
  const double worst = untangle_quads(g.x, g.normals, g.fixed, g.quads, kPlane);
  EXPECT_GT(worst, 0.0);
  EXPECT_NEAR(worst, g.worst(), 1e-12) << "the value returned is the mesh's";
  EXPECT_LT((g.at(2, 2) - Vec3(2, 2, 0)).norm(), 0.5) << "back near its place in the grid";
  for (int i = 0; i <= 8; ++i) {
    for (int j = 0; j <= 8; ++j) {
      const size_t k = static_cast<size_t>(g.id(i, j));
      if (g.fixed[k] || std::max(std::abs(i - 2), std::abs(j - 2)) > 3) {
        EXPECT_EQ(g.x[k], before[k]) << i << " " << j;
      }
    }
  }
}

TEST(SubmapUntangle, AGoodMeshIsLeftAsItIs) {
  Grid g(5);
  g.at(2, 3) = Vec3(2.2, 2.9, 0);  // a little off, not poor
  const std::vector<Vec3> before = g.x;
  EXPECT_GT(untangle_quads(g.x, g.normals, g.fixed, g.quads, kPlane), 0.2);
  EXPECT_EQ(g.x, before);
}

TEST(SubmapUntangle, AFoldOfFixedNodesIsReportedNotHidden) {
  Grid g(3);
  g.at(1, 1) = Vec3(2.5, 2.5, 0);
  g.fixed.assign(g.x.size(), true);  // nothing may move
  const std::vector<Vec3> before = g.x;
  EXPECT_LE(untangle_quads(g.x, g.normals, g.fixed, g.quads, kPlane), 0.0);
  EXPECT_EQ(g.x, before);
}

// Every free node of a 10 x 10 grid thrown up to 0.8 cells off its place:
// dozens of folds side by side, where a node mending its own worst quad
// breaks its neighbour's. The side's fallback (submap_scheme.cpp): corner
// areas untangled first (mesh::untangle_corners), then the quads lifted.
Grid scrambled(unsigned seed) {
  Grid g(10);
  std::mt19937 random(seed);
  const auto offset = [&] { return 1.6 * (static_cast<double>(random()) / random.max() - 0.5); };
  for (size_t k = 0; k < g.x.size(); ++k) {
    if (g.fixed[k]) continue;
    const double dx = offset();
    g.x[k] += Vec3(dx, offset(), 0);
  }
  return g;
}

TEST(SubmapUntangle, AScrambledGridComesUntangledByCornersThenQuads) {
  int alone_folded = 0;
  for (unsigned seed = 1; seed <= 5; ++seed) {
    Grid alone = scrambled(seed);
    ASSERT_LE(alone.worst(), 0.0) << seed;
    if (untangle_quads(alone.x, alone.normals, alone.fixed, alone.quads, kPlane) <= 0.0)
      ++alone_folded;
    Grid g = scrambled(seed);
    EXPECT_TRUE(mesh::untangle_corners(g.x, g.normals, g.fixed, g.quads, kPlane)) << seed;
    const double lifted = untangle_quads(g.x, g.normals, g.fixed, g.quads, kPlane);
    EXPECT_GT(lifted, 0.0) << seed;
    EXPECT_NEAR(lifted, g.worst(), 1e-12);
  }
  EXPECT_GT(alone_folded, 0) << "the grids no longer need the corners' untangling";
}

}  // namespace
}  // namespace cooperage::submap
