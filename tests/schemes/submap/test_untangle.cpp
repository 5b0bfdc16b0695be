// Untangling a folded quad mesh around its folds (value types, no CAD).
#include "schemes/submap/untangle.h"

#include "framework/mesh/corner_untangle.h"
#include "support/quad_grid.h"

#include <gtest/gtest.h>

#include <cmath>

namespace cooperage::submap {
namespace {

using testing::QuadGrid;

// The worst scaled Jacobian of the grid's quads (about +z).
double worst_quad(const QuadGrid& g) {
  double m = 1;
  for (const auto& q : g.quads) {
    std::array<Vec3, 4> p, nn;
    for (size_t k = 0; k < 4; ++k) {
      p[k] = g.x[static_cast<size_t>(q[k])];
      nn[k] = Vec3(0, 0, 1);
    }
    m = std::min(m, quad_scaled_jacobian(p, nn));
  }
  return m;
}

const Projector kPlane = testing::onto_plane;

TEST(SubmapUntangle, AFoldIsUndoneAndNodesFarFromItStay) {
  QuadGrid g(8);
  g.at(2, 2) = Vec3(3.6, 3.4, 0);  // past its neighbour (3, 3): four quads fold
  ASSERT_LE(worst_quad(g), 0.0);
  const std::vector<Vec3> before = g.x;
  const double worst = untangle_quads(g.x, g.normals, g.fixed, g.quads, kPlane);
  EXPECT_GT(worst, 0.0);
  EXPECT_NEAR(worst, worst_quad(g), 1e-12) << "the value returned is the mesh's";
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
  QuadGrid g(5);
  g.at(2, 3) = Vec3(2.2, 2.9, 0);  // a little off, not poor
  const std::vector<Vec3> before = g.x;
  EXPECT_GT(untangle_quads(g.x, g.normals, g.fixed, g.quads, kPlane), 0.2);
  EXPECT_EQ(g.x, before);
}

TEST(SubmapUntangle, AFoldOfFixedNodesIsReportedNotHidden) {
  QuadGrid g(3);
  g.at(1, 1) = Vec3(2.5, 2.5, 0);
  g.fixed.assign(g.x.size(), true);  // nothing may move
  const std::vector<Vec3> before = g.x;
  EXPECT_LE(untangle_quads(g.x, g.normals, g.fixed, g.quads, kPlane), 0.0);
  EXPECT_EQ(g.x, before);
}

// A scrambled grid (dozens of folds side by side), where a node mending its
// own worst quad breaks its neighbour's. The side's fallback
// (submap_scheme.cpp): corner areas untangled first (mesh::untangle_corners),
// then the quads lifted.
TEST(SubmapUntangle, AScrambledGridComesUntangledByCornersThenQuads) {
  int alone_folded = 0;
  for (unsigned seed = 1; seed <= 5; ++seed) {
    QuadGrid alone = testing::scrambled_grid(seed);
    ASSERT_LE(worst_quad(alone), 0.0) << seed;
    if (untangle_quads(alone.x, alone.normals, alone.fixed, alone.quads, kPlane) <= 0.0)
      ++alone_folded;
    QuadGrid g = testing::scrambled_grid(seed);
    EXPECT_TRUE(mesh::untangle_corners(g.x, g.normals, g.fixed, g.quads, kPlane)) << seed;
    const double lifted = untangle_quads(g.x, g.normals, g.fixed, g.quads, kPlane);
    EXPECT_GT(lifted, 0.0) << seed;
    EXPECT_NEAR(lifted, worst_quad(g), 1e-12);
  }
  EXPECT_GT(alone_folded, 0) << "the grids no longer need the corners' untangling";
}

}  // namespace
}  // namespace cooperage::submap
