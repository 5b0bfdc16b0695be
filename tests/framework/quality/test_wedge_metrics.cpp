// Wedge metrics against hand-computed values. Verdict normalises wedge
// metrics to the equilateral unit wedge; the right-angle unit wedge is not
// ideal under that normalisation (see wedge_metrics.h).
#include <cmath>

#include <gtest/gtest.h>

#include "framework/quality/metric.h"
#include "framework/quality/wedge_metrics.h"

namespace cooperage::quality {
namespace {

using Eigen::Vector3d;

WedgeNodes prism(const Vector3d& p2, double h = 1.0) {
  return {Vector3d(0, 0, 0), Vector3d(1, 0, 0), p2,
          Vector3d(0, 0, h), Vector3d(1, 0, h), p2 + Vector3d(0, 0, h)};
}

const double kSqrt3 = std::sqrt(3.0);

TEST(WedgeMetrics, EquilateralUnitWedgeIsTheReference) {
  const WedgeNodes w = prism(Vector3d(0.5, kSqrt3 / 2, 0));
  EXPECT_NEAR(wedge_scaled_jacobian(w), 1.0, 1e-12);  // (2/sqrt3) sin 60 = 1
  EXPECT_NEAR(wedge_jacobian(w), kSqrt3 / 2, 1e-12);
  EXPECT_NEAR(wedge_shape(w), 1.0, 1e-12);
  EXPECT_NEAR(wedge_max_aspect_frobenius(w), 1.0, 1e-12);
  EXPECT_NEAR(wedge_edge_ratio(w), 1.0, 1e-12);
}

TEST(WedgeMetrics, RightAngleUnitWedge) {
  const WedgeNodes w = prism(Vector3d(0, 1, 0));
  // Corner 0: det 1, unit edges -> 2/sqrt3; corners 1, 2: 45-degree corners,
  // det 1, edges sqrt2, 1, 1 -> (2/sqrt3)/sqrt2 = sqrt(2/3). Minimum sqrt(2/3).
  EXPECT_NEAR(wedge_scaled_jacobian(w), std::sqrt(2.0 / 3.0), 1e-12);
  EXPECT_NEAR(wedge_jacobian(w), 1.0, 1e-12);  // every corner det is 1
  // Shape at a 45-degree corner: 3 (2/sqrt3 * 1)^(2/3) / (2+1+1).
  EXPECT_NEAR(wedge_shape(w), 3 * std::pow(2 / kSqrt3, 2.0 / 3.0) / 4, 1e-12);
  // Corner tets: P0P1P2P3 numerator 1.5*3 = 4.5; P1P2P0P4 and P2P0P1P5:
  // 1.5*(2+1+1) - 1 = 5; det^2 = 1 -> denominator 3 cbrt(2). Reference
  // 4 / (3 cbrt(1.5)).
  const double expected = (5.0 / (3 * std::cbrt(2.0))) / (4.0 / (3 * std::cbrt(1.5)));
  EXPECT_NEAR(wedge_max_aspect_frobenius(w), expected, 1e-12);
  EXPECT_NEAR(wedge_edge_ratio(w), std::sqrt(2.0), 1e-12);
}

TEST(WedgeMetrics, TallWedge) {
  const WedgeNodes w = prism(Vector3d(0.5, kSqrt3 / 2, 0), 3.0);
  EXPECT_NEAR(wedge_scaled_jacobian(w), 1.0, 1e-12);
  EXPECT_NEAR(wedge_jacobian(w), 3 * kSqrt3 / 2, 1e-12);
  EXPECT_NEAR(wedge_edge_ratio(w), 3.0, 1e-12);
  // Shape: 3 (3)^(2/3) / (1+9+1) at every corner.
  EXPECT_NEAR(wedge_shape(w), 3 * std::pow(3.0, 2.0 / 3.0) / 11, 1e-12);
}

TEST(WedgeMetrics, InvertedWedge) {
  const WedgeNodes w = prism(Vector3d(0.5, kSqrt3 / 2, 0), -1.0);
  EXPECT_NEAR(wedge_scaled_jacobian(w), -1.0, 1e-12);
  EXPECT_NEAR(wedge_jacobian(w), -kSqrt3 / 2, 1e-12);
  EXPECT_DOUBLE_EQ(wedge_shape(w), 0.0);
}

TEST(WedgeMetrics, DegenerateWedge) {
  WedgeNodes w = prism(Vector3d(0.5, kSqrt3 / 2, 0));
  w[3] = w[0];  // collapsed vertical edge
  EXPECT_DOUBLE_EQ(wedge_scaled_jacobian(w), 0.0);
  EXPECT_DOUBLE_EQ(wedge_shape(w), 0.0);
  EXPECT_DOUBLE_EQ(wedge_edge_ratio(w), kDegenerate);
  EXPECT_DOUBLE_EQ(wedge_max_aspect_frobenius(w), kDegenerate);
}

}  // namespace
}  // namespace cooperage::quality
