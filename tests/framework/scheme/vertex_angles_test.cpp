// Corner angles where tangents cannot tell: curves leaving a vertex along one
// line (a tangent cusp) and loops touching at a vertex (a pinched face).
// The expected angles follow from the construction: a circle tangent to a
// line meets it at 0 degrees, whatever the rotation of the model.
#include "analytic_model.h"

#include "framework/scheme/vertex_angles.h"

#include <Eigen/Geometry>

#include <gtest/gtest.h>

#include <cmath>

namespace cooperage {
namespace {

using geom::Vec3;

// The face between the x axis, the line x = 1 and the circle of radius 2
// about (0, 2) that touches the axis at the origin, all rotated by `turn`
// about z: corners 0 (the cusp at the origin), 90 and 60 degrees (the circle
// crosses x = 1 at 60 degrees below its centre).
geom::Model cusp_model(double turn) {
  const Eigen::AngleAxisd r(turn, Vec3::UnitZ());
  testing::ModelBuilder m;
  const int o = m.vertex(r * Vec3(0, 0, 0));
  const int a = m.vertex(r * Vec3(1, 0, 0));
  const int b = m.vertex(r * Vec3(1, 2 - std::sqrt(3.0), 0));
  m.line(o, a);
  m.line(a, b);
  m.arc(b, o, r * Vec3(0, 2, 0), -Vec3::UnitZ());  // clockwise: down to the origin
  m.planar({o, a, b});
  return m.finish();
}

TEST(LoopCorners, TangentCuspIsZeroDegreesAtAnyRotation) {
  for (int k = 0; k < 24; ++k) {
    const geom::Model model = cusp_model(k * 0.2617993877991494 + 0.01);
    const auto corners = scheme::loop_corners(model, 1, 0);
    ASSERT_EQ(corners.size(), 3u);
    EXPECT_LT(corners[0].angle, 1.0) << "rotation " << k;  // at the origin
    EXPECT_FALSE(corners[0].type.has_value());
    EXPECT_NEAR(corners[1].angle, 90.0, 1e-6);
    EXPECT_NEAR(corners[2].angle, 60.0, 1e-6);
    const auto sharpest = scheme::sharpest_corner(model, 1);
    ASSERT_TRUE(sharpest);
    EXPECT_EQ(sharpest->vertex, corners[0].vertex);
  }
}

// A 4 x 4 square whose bottom edge is split at (2, 0), with a circular hole
// of radius `r` about (2, r): it touches the edge at (2, 0) when the hole's
// loop starts there, pinching the face into two cusps.
geom::Model square_with_touching_hole(double r, bool touching) {
  testing::ModelBuilder m;
  const int v1 = m.vertex({0, 0, 0}), v2 = m.vertex({2, 0, 0}), v3 = m.vertex({4, 0, 0});
  const int v4 = m.vertex({4, 4, 0}), v5 = m.vertex({0, 4, 0});
  const int h = touching ? v2 : m.vertex({2, 0.5, 0});
  const Vec3 centre(2, touching ? r : 0.5 + r, 0);
  const int hole = m.circle(h, centre, -Vec3::UnitZ());  // clockwise: a hole
  std::vector<geom::Loop> loops{m.loop({v1, v2, v3, v4, v5})};
  loops.push_back(geom::Loop{{{hole, geom::Sense::Forward}}});
  m.surface(std::make_shared<testing::PlaneSurface>(Vec3::Zero(), Vec3::UnitZ()), loops);
  return m.finish();
}

TEST(SharpestCorner, HoleTouchingTheOuterLoopPinchesTheFaceToZero) {
  const geom::Model model = square_with_touching_hole(1.0, true);
  // Each loop alone passes straight through the touching point...
  for (int l = 0; l < 2; ++l) {
    for (const auto& c : scheme::loop_corners(model, 1, l)) {
      if (c.vertex == 2) {
        EXPECT_NEAR(c.angle, 180.0, 1e-6);
      }
    }
  }
  // ...but the face between them closes to nothing there.
  const auto sharpest = scheme::sharpest_corner(model, 1);
  ASSERT_TRUE(sharpest);
  EXPECT_EQ(sharpest->vertex, 2);
  EXPECT_LT(sharpest->angle, 0.1);
}

TEST(SharpestCorner, HoleClearOfTheOuterLoopLeavesTheSquaresCorners) {
  const geom::Model model = square_with_touching_hole(1.0, false);
  const auto sharpest = scheme::sharpest_corner(model, 1);
  ASSERT_TRUE(sharpest);
  EXPECT_NEAR(sharpest->angle, 90.0, 1e-6);
}

TEST(SharpestCorner, SeamOfACylinderIsNoCusp) {
  // One loop visits each seam vertex twice; its corners there stay 90.
  const geom::Model model = testing::cylinder_side_model(1.0, 2.0);
  const auto sharpest = scheme::sharpest_corner(model, 1);
  ASSERT_TRUE(sharpest);
  EXPECT_NEAR(sharpest->angle, 90.0, 1e-3);
}

}  // namespace
}  // namespace cooperage
