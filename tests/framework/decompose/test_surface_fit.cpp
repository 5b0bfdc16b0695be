// surface_fit.h and cut_surface.h: planes and cylinders read back from the
// evaluators of OCCT faces, signed distances, descriptions.
#include "framework/decompose/cut_surface.h"
#include "framework/decompose/surface_fit.h"
#include "framework/geometry/occ/workbench.h"

#include <gtest/gtest.h>

#include <cmath>

namespace cooperage::decompose {
namespace {

TEST(SurfaceFit, CircleThroughThreePoints) {
  const auto c = circle_through({3, 0, 1}, {0, 3, 1}, {-3, 0, 1});
  ASSERT_TRUE(c);
  EXPECT_NEAR(c->radius, 3.0, 1e-12);
  EXPECT_NEAR((c->point - Vec3(0, 0, 1)).norm(), 0.0, 1e-12);
  EXPECT_NEAR(std::abs(c->axis.z()), 1.0, 1e-12);
  EXPECT_FALSE(circle_through({0, 0, 0}, {1, 1, 1}, {2, 2, 2}));
}

TEST(SurfaceFit, TheCylinderOfARotatedCylindricalFace) {
  occ::Workbench bench;
  const Vec3 axis = Vec3(1, 2, 2).normalized();
  bench.cylinder("c", {1, -1, 2}, axis, 0.75, 3);
  const geom::Model m = bench.build_model();
  int cylinders = 0, planes = 0;
  for (const auto& s : m.surfaces()) {
    if (auto c = cylinder_of(s)) {
      ++cylinders;
      EXPECT_NEAR(c->radius, 0.75, 1e-9);
      EXPECT_NEAR(std::abs(c->axis.dot(axis)), 1.0, 1e-9);
      const Vec3 r = Vec3(1, -1, 2) - c->point;
      EXPECT_NEAR((r - r.dot(c->axis) * c->axis).norm(), 0.0, 1e-9);
      EXPECT_FALSE(plane_of(s));
    }
    if (auto p = plane_of(s)) {
      ++planes;
      EXPECT_NEAR(std::abs(p->normal.dot(axis)), 1.0, 1e-9);
    }
  }
  EXPECT_EQ(cylinders, 1);
  EXPECT_EQ(planes, 2);
}

TEST(SurfaceFit, ThePlanesOfABrickAreItsFaces) {
  occ::Workbench bench;
  bench.brick("b", {0, 0, 0}, {1, 2, 3});
  const geom::Model m = bench.build_model();
  for (const auto& s : m.surfaces()) {
    auto p = plane_of(s);
    ASSERT_TRUE(p);
    // Every corner of the face lies in the plane.
    for (const auto& loop : s.loops)
      for (const auto& use : loop.uses) {
        const auto& c = m.curve(use.curve);
        EXPECT_NEAR(signed_distance(*p, m.vertex(c.start_vertex).point), 0.0, 1e-9);
      }
  }
}

TEST(CutSurface, SignedDistancesAndSpan) {
  const CutSurface plane{CutSurface::Kind::Plane, {0, 0, 1}, {0, 0, 2}, 0};
  EXPECT_NEAR(signed_distance(plane, {5, 5, 3}), 2.0, 1e-12);
  const CutSurface cyl{CutSurface::Kind::Cylinder, {0, 0, 0}, {0, 0, 1}, 1};
  EXPECT_NEAR(signed_distance(cyl, {3, 0, 7}), 2.0, 1e-12);
  EXPECT_NEAR(signed_distance(cyl, {0, 0.5, -7}), -0.5, 1e-12);
  const Span s = span(plane, {{0, 0, 0}, {0, 0, 4}});
  EXPECT_NEAR(s.below, -1.0, 1e-12);
  EXPECT_NEAR(s.above, 3.0, 1e-12);
}

TEST(CutSurface, SameSurfaceIgnoresTheSignOfTheNormalAndTheOriginInThePlane) {
  const CutSurface a{CutSurface::Kind::Plane, {0, 0, 1}, {0, 0, 1}, 0};
  const CutSurface b{CutSurface::Kind::Plane, {4, 3, 1}, {0, 0, -1}, 0};
  const CutSurface c{CutSurface::Kind::Plane, {4, 3, 1.1}, {0, 0, -1}, 0};
  EXPECT_TRUE(same_surface(a, b, 1e-9));
  EXPECT_FALSE(same_surface(a, c, 1e-9));
}

TEST(CutSurface, Descriptions) {
  EXPECT_EQ(describe({CutSurface::Kind::Plane, {1, 2.5, 3}, {0, -1, 0}, 0}), "plane y = 2.5");
  EXPECT_EQ(describe({CutSurface::Kind::Cylinder, {0, 0, 0}, {0, 0, 1}, 2}),
            "cylinder r = 2 about the axis through (0 0 0) along z");
}

}  // namespace
}  // namespace cooperage::decompose
