// Untangling a quad mesh by its corners' areas (framework/mesh/
// corner_untangle.h; value types, no CAD).
#include "framework/mesh/corner_untangle.h"

#include "support/quad_grid.h"

#include <gtest/gtest.h>

#include <cmath>

namespace cooperage::mesh {
namespace {

using testing::QuadGrid;

// The smallest signed corner area (z component of the edges' cross product).
double worst_corner(const QuadGrid& g) {
  double m = 1e300;
  for (const auto& q : g.quads) {
    for (size_t k = 0; k < 4; ++k) {
      const Vec3& p = g.x[static_cast<size_t>(q[k])];
      const Vec3 a = g.x[static_cast<size_t>(q[(k + 1) % 4])] - p;
      const Vec3 b = g.x[static_cast<size_t>(q[(k + 3) % 4])] - p;
      m = std::min(m, a.x() * b.y() - a.y() * b.x());
    }
  }
  return m;
}

const CornerProjector kPlane = testing::onto_plane;

TEST(CornerUntangle, ScrambledGridsComeUntangled) {
  for (unsigned seed = 1; seed <= 5; ++seed) {
    QuadGrid g = testing::scrambled_grid(seed);
    ASSERT_LT(worst_corner(g), 0.0) << seed;
    const std::vector<Vec3> before = g.x;
    EXPECT_TRUE(untangle_corners(g.x, g.normals, g.fixed, g.quads, kPlane)) << seed;
    EXPECT_GT(worst_corner(g), 0.0) << seed;
    for (size_t k = 0; k < g.x.size(); ++k) {
      EXPECT_EQ(g.x[k].z(), 0.0) << "projected onto the plane";
      if (g.fixed[k]) {
        EXPECT_EQ(g.x[k], before[k]);
      }
    }
  }
}

TEST(CornerUntangle, AGoodMeshIsLeftAsItIs) {
  QuadGrid g(5);
  g.at(2, 3) = Vec3(2.2, 2.9, 0);  // a little off: every corner above beta
  const std::vector<Vec3> before = g.x;
  EXPECT_TRUE(untangle_corners(g.x, g.normals, g.fixed, g.quads, kPlane));
  EXPECT_EQ(g.x, before);
}

TEST(CornerUntangle, AFoldOfFixedNodesIsReportedNotHidden) {
  QuadGrid g(3);
  g.at(1, 1) = Vec3(2.5, 2.5, 0);
  g.fixed.assign(g.x.size(), true);
  const std::vector<Vec3> before = g.x;
  EXPECT_FALSE(untangle_corners(g.x, g.normals, g.fixed, g.quads, kPlane));
  EXPECT_EQ(g.x, before);
}

}  // namespace
}  // namespace cooperage::mesh
