// Smoothing the subcaps of one exterior face (Blacker 1996, sec. 6.1):
// interior nodes move, fixed ones do not, quality never drops.
#include "schemes/cooper/smooth_cap.h"
#include "unit_grid.h"

#include <gtest/gtest.h>

namespace cooperage::cooper {
namespace {

using mesh::Vec3;

// A 4 x 4 grid of unit quads in z = 0 (counter-clockwise about +z).
struct Grid : test_meshes::UnitGrid {
  Grid() : UnitGrid(4) {}
};

TEST(SmoothCap, ImprovesADistortedGridAndKeepsTheBoundary) {
  Grid g;
  g.points[6] += Vec3(0.45, 0.4, 0);  // an interior node pulled towards a neighbour
  const double before = min_quad_corner_quality(g.points, g.quads, Vec3::UnitZ());
  const std::vector<Vec3> original = g.points;
  auto flat = [](const Vec3& x) { return Vec3(x.x(), x.y(), 0.0); };
  EXPECT_TRUE(smooth_cap(g.points, g.quads, g.movable, Vec3::UnitZ(), flat));
  EXPECT_GT(min_quad_corner_quality(g.points, g.quads, Vec3::UnitZ()), before);
  for (size_t i = 0; i < g.points.size(); ++i) {
    if (!g.movable[i]) {
      EXPECT_EQ(g.points[i], original[i]);
    }
    EXPECT_EQ(g.points[i].z(), 0.0);
  }
  EXPECT_NEAR((g.points[6] - Vec3(1, 1, 0)).norm(), 0, 0.05);
}

TEST(SmoothCap, KeepsAPerfectGridAndRejectsWorsening) {
  Grid g;
  const std::vector<Vec3> original = g.points;
  smooth_cap(g.points, g.quads, g.movable, Vec3::UnitZ(), nullptr);
  for (size_t i = 0; i < g.points.size(); ++i)
    EXPECT_NEAR((g.points[i] - original[i]).norm(), 0, 1e-12);
  EXPECT_NEAR(min_quad_corner_quality(g.points, g.quads, Vec3::UnitZ()), 1.0, 1e-12);
  EXPECT_LT(min_quad_corner_quality(g.points, g.quads, -Vec3::UnitZ()),
            0.0);  // seen from below: inverted
}

}  // namespace
}  // namespace cooperage::cooper
