#include <gtest/gtest.h>

#include <cmath>

#include "framework/mesh2d/predicates.h"

namespace cooperage::mesh2d {
namespace {

TEST(Mesh2dPredicates, OrientationSigns) {
  EXPECT_GT(orient2d({0, 0}, {1, 0}, {0, 1}), 0.0);
  EXPECT_LT(orient2d({0, 0}, {0, 1}, {1, 0}), 0.0);
  EXPECT_EQ(orient2d({0, 0}, {1, 1}, {2, 2}), 0.0);
}

// Near-collinear points where naive evaluation gets the sign wrong
// (Kettner et al., "Classroom examples of robustness problems").
TEST(Mesh2dPredicates, OrientationExactNearCollinear) {
  const Point2 b(12.0, 12.0);
  const Point2 c(24.0, 24.0);
  for (int i = 0; i < 64; ++i) {
    for (int j = 0; j < 64; ++j) {
      const Point2 a(0.5 + i * std::ldexp(1.0, -53), 0.5 + j * std::ldexp(1.0, -53));
      const double s = orient2d(a, b, c);
      // Exact sign: a is left of b->c iff a.y > a.x (the line is y = x).
      const double expected = a.y() > a.x() ? 1.0 : (a.y() < a.x() ? -1.0 : 0.0);
      EXPECT_EQ((s > 0) - (s < 0), static_cast<int>(expected)) << i << " " << j;
      // Permutation consistency.
      const double s2 = orient2d(b, c, a);
      EXPECT_EQ((s > 0) - (s < 0), (s2 > 0) - (s2 < 0));
    }
  }
}

TEST(Mesh2dPredicates, IncircleExactOnCircle) {
  // Points exactly on the unit circle (Pythagorean triples).
  const Point2 a(5, 0), b(0, 5), c(-5, 0);
  EXPECT_EQ(incircle(a, b, c, {0, -5}), 0.0);
  EXPECT_EQ(incircle(a, b, c, {3, 4}), 0.0);
  EXPECT_GT(incircle(a, b, c, {0, 0}), 0.0);
  EXPECT_LT(incircle(a, b, c, {6, 0}), 0.0);
  // Tiny perturbations off the circle are resolved exactly.
  const double e = std::ldexp(1.0, -50);
  EXPECT_GT(incircle(a, b, c, {3 - e, 4}), 0.0);
  EXPECT_LT(incircle(a, b, c, {3 + e, 4}), 0.0);
  // Large offsets (exactly representable sums): the sign stays exact.
  const Point2 o(1099511627776.0, 1099511627776.0);
  EXPECT_EQ(incircle(o + a, o + b, o + c, o + Point2(3, -4)), 0.0);
  EXPECT_GT(incircle(o + a, o + b, o + c, o + Point2(3, 3.75)), 0.0);
}

}  // namespace
}  // namespace cooperage::mesh2d
