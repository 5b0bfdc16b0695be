// Quad and triangle metrics against hand-computed values, including
// inversion against a reference surface normal.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "framework/quality/metric.h"
#include "framework/quality/quad_metrics.h"
#include "framework/quality/tri_metrics.h"

namespace cooperage::quality {
namespace {

using Eigen::Vector3d;

const double kPi = std::acos(-1.0);
const double kRoot3 = std::sqrt(3.0);

QuadNodes rhombus(double a) {
  const Vector3d u(1, 0, 0), v(std::cos(a), std::sin(a), 0);
  return {Vector3d::Zero(), u, u + v, v};
}

struct QuadCase {
  std::string name;
  QuadNodes nodes;
  double scaled_jacobian, jacobian, skew, taper, aspect, edge_ratio, shape;
};

TEST(QuadMetrics, TableOfHandComputedValues) {
  const double a = kPi / 3;  // 60-degree rhombus
  const std::vector<QuadCase> cases = {
      // unit square
      {"square",
       {Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(1, 1, 0), Vector3d(0, 1, 0)},
       1,
       1,
       0,
       0,
       1,
       1,
       1},
      // 1 x 2 rectangle: aspect (1+4)/(2*2) = 1.25, shape 2*2/(1+4) = 0.8
      {"rectangle",
       {Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(1, 2, 0), Vector3d(0, 2, 0)},
       1,
       2,
       0,
       0,
       1.25,
       2,
       0.8},
      // rhombus, unit sides, angle a: corner areas sin a, X1 = 2u, X2 = 2v,
      // aspect (1+1)/(2 sin a), shape 2 sin a / 2.
      {"rhombus60", rhombus(a), std::sin(a), std::sin(a), std::cos(a), 0, 1 / std::sin(a), 1,
       std::sin(a)},
  };
  for (const auto& t : cases) {
    SCOPED_TRACE(t.name);
    EXPECT_NEAR(quad_scaled_jacobian(t.nodes), t.scaled_jacobian, 1e-12);
    EXPECT_NEAR(quad_jacobian(t.nodes), t.jacobian, 1e-12);
    EXPECT_NEAR(quad_skew(t.nodes), t.skew, 1e-12);
    EXPECT_NEAR(quad_taper(t.nodes), t.taper, 1e-12);
    EXPECT_NEAR(quad_max_aspect_frobenius(t.nodes), t.aspect, 1e-12);
    EXPECT_NEAR(quad_edge_ratio(t.nodes), t.edge_ratio, 1e-12);
    EXPECT_NEAR(quad_shape(t.nodes), t.shape, 1e-12);
    // Same values against the matching surface normal.
    EXPECT_NEAR(quad_scaled_jacobian(t.nodes, Vector3d(0, 0, 1)), t.scaled_jacobian, 1e-12);
  }
}

TEST(QuadMetrics, RhombusScaledJacobianIsSinOfAngle) {
  for (double deg : {30.0, 45.0, 75.0, 90.0, 120.0}) {
    const double a = deg * kPi / 180;
    EXPECT_NEAR(quad_scaled_jacobian(rhombus(a)), std::sin(a), 1e-12) << deg;
  }
}

TEST(QuadMetrics, TrapezoidTaper) {
  // Bottom [0,2], top [0.5,1.5] at y=1: X1 = (1,0)+(2,0)... = P1+P2-P0-P3 =
  // (2,0)+(1.5,1)-(0,0)-(0.5,1) = (3,0); X2 = P2+P3-P0-P1 = (0,2);
  // X12 = P0+P2-P1-P3 = (-1,0) -> taper 1/2.
  const QuadNodes q = {Vector3d(0, 0, 0), Vector3d(2, 0, 0), Vector3d(1.5, 1, 0),
                       Vector3d(0.5, 1, 0)};
  EXPECT_NEAR(quad_taper(q), 0.5, 1e-12);
}

TEST(QuadMetrics, InvertedAgainstSurfaceNormal) {
  // Clockwise seen from +z: Verdict's own normal says valid, the surface says inverted.
  const QuadNodes q = {Vector3d(0, 0, 0), Vector3d(0, 1, 0), Vector3d(1, 1, 0), Vector3d(1, 0, 0)};
  EXPECT_NEAR(quad_scaled_jacobian(q), 1.0, 1e-12);
  EXPECT_NEAR(quad_scaled_jacobian(q, Vector3d(0, 0, 1)), -1.0, 1e-12);
  EXPECT_NEAR(quad_jacobian(q, Vector3d(0, 0, 2)), -1.0, 1e-12);  // normal need not be unit
  EXPECT_DOUBLE_EQ(quad_shape(q, Vector3d(0, 0, 1)), 0.0);
}

TEST(QuadMetrics, RelativeSizeAndDegenerate) {
  const QuadNodes r = {Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(1, 2, 0), Vector3d(0, 2, 0)};
  EXPECT_NEAR(quad_size(r), 2.0, 1e-12);
  EXPECT_NEAR(quad_relative_size(r, 2.0), 1.0, 1e-12);
  EXPECT_NEAR(quad_relative_size(r, 4.0), 0.25, 1e-12);
  QuadNodes d = r;
  d[1] = d[0];
  EXPECT_DOUBLE_EQ(quad_scaled_jacobian(d), 0.0);
  EXPECT_DOUBLE_EQ(quad_edge_ratio(d), kDegenerate);
  EXPECT_DOUBLE_EQ(quad_max_aspect_frobenius(d), kDegenerate);
  // Collapsed quad (P2 == P3) is measured as the triangle P0 P1 P2.
  const QuadNodes c = {Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(0.5, kRoot3 / 2, 0),
                       Vector3d(0.5, kRoot3 / 2, 0)};
  EXPECT_NEAR(quad_scaled_jacobian(c), 1.0, 1e-12);
}

TEST(TriMetrics, Equilateral) {
  const TriNodes t = {Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(0.5, kRoot3 / 2, 0)};
  EXPECT_NEAR(tri_scaled_jacobian(t), 1.0, 1e-12);
  EXPECT_NEAR(tri_shape(t), 1.0, 1e-12);
  EXPECT_NEAR(tri_aspect_frobenius(t), 1.0, 1e-12);
  EXPECT_NEAR(tri_edge_ratio(t), 1.0, 1e-12);
  EXPECT_NEAR(tri_jacobian(t), kRoot3 / 2, 1e-12);
  EXPECT_NEAR(tri_size(t), kRoot3 / 4, 1e-12);
  EXPECT_NEAR(tri_relative_size(t, kRoot3 / 4), 1.0, 1e-12);
  EXPECT_NEAR(tri_relative_size(t, kRoot3 / 2), 0.25, 1e-12);  // R = 1/4 -> min(1/4, 4)
}

TEST(TriMetrics, RightIsosceles) {
  // Verdict: |cross| (2/sqrt3) / max edge product = 1 * (2/sqrt3) / sqrt2 = sqrt(2/3)
  // (the 45-degree corners), not sin 90 * 2/sqrt3.
  const TriNodes t = {Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(0, 1, 0)};
  EXPECT_NEAR(tri_scaled_jacobian(t), std::sqrt(2.0 / 3.0), 1e-12);
  // condition = (1 + 1 - 0) / (1 * sqrt3) -> shape sqrt3/2
  EXPECT_NEAR(tri_shape(t), kRoot3 / 2, 1e-12);
  // aspect = (1 + 2 + 1) / (2 sqrt3 * 1)
  EXPECT_NEAR(tri_aspect_frobenius(t), 2 / kRoot3, 1e-12);
  EXPECT_NEAR(tri_edge_ratio(t), std::sqrt(2.0), 1e-12);
}

TEST(TriMetrics, InvertedAgainstSurfaceNormal) {
  const TriNodes t = {Vector3d(0, 0, 0), Vector3d(0.5, kRoot3 / 2, 0), Vector3d(1, 0, 0)};  // CW
  EXPECT_NEAR(tri_scaled_jacobian(t), 1.0, 1e-12);
  EXPECT_NEAR(tri_scaled_jacobian(t, Vector3d(0, 0, 1)), -1.0, 1e-12);
  EXPECT_NEAR(tri_scaled_jacobian(t, Vector3d(0, 0, -1)), 1.0, 1e-12);
  EXPECT_LT(tri_jacobian(t, Vector3d(0, 0, 1)), 0.0);
  EXPECT_DOUBLE_EQ(tri_shape(t, Vector3d(0, 0, 1)), 0.0);
}

TEST(TriMetrics, Degenerate) {
  const TriNodes t = {Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(2, 0, 0)};  // collinear
  EXPECT_DOUBLE_EQ(tri_scaled_jacobian(t), 0.0);
  EXPECT_DOUBLE_EQ(tri_shape(t), 0.0);
  EXPECT_DOUBLE_EQ(tri_aspect_frobenius(t), kDegenerate);
  TriNodes p;
  p.fill(Vector3d(1, 1, 1));
  EXPECT_DOUBLE_EQ(tri_scaled_jacobian(p), 0.0);
  EXPECT_DOUBLE_EQ(tri_edge_ratio(p), kDegenerate);
}

}  // namespace
}  // namespace cooperage::quality
