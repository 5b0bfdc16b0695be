// Triangle metrics after Verdict (sandialabs/verdict V_TriMetric.cpp).
// Written from the definitions, not copied.
#include "framework/quality/tri_metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Geometry>

#include "framework/quality/metric.h"

namespace cooperage::quality {

namespace {

using Eigen::Vector3d;

constexpr double kTiny = std::numeric_limits<double>::min();
const double kSqrt3 = std::sqrt(3.0);

Vector3d area_vector(const TriNodes& p) { return (p[1] - p[0]).cross(p[2] - p[0]); }

double sign_against(const Vector3d& area, const Vector3d& normal) {
  return area.dot(normal) < 0.0 ? -1.0 : 1.0;
}

}  // namespace

double tri_scaled_jacobian(const TriNodes& p) {
  const double l0 = (p[1] - p[0]).norm(), l1 = (p[2] - p[0]).norm(), l2 = (p[2] - p[1]).norm();
  const double max_product = std::max({l0 * l1, l1 * l2, l0 * l2});
  if (max_product < kTiny) return 0.0;
  return 2.0 / kSqrt3 * area_vector(p).norm() / max_product;
}

double tri_scaled_jacobian(const TriNodes& p, const Vector3d& normal) {
  return sign_against(area_vector(p), normal) * tri_scaled_jacobian(p);
}

double tri_jacobian(const TriNodes& p) { return area_vector(p).norm(); }

double tri_jacobian(const TriNodes& p, const Vector3d& normal) {
  const Vector3d a = area_vector(p);
  return sign_against(a, normal) * a.norm();
}

double tri_aspect_frobenius(const TriNodes& p) {
  const double sum =
      (p[1] - p[0]).squaredNorm() + (p[2] - p[1]).squaredNorm() + (p[0] - p[2]).squaredNorm();
  const double area2 = area_vector(p).norm();
  if (area2 == 0.0) return kDegenerate;
  return std::min(sum / (2.0 * kSqrt3 * area2), kDegenerate);
}

double tri_edge_ratio(const TriNodes& p) {
  const double a = (p[1] - p[0]).squaredNorm(), b = (p[2] - p[1]).squaredNorm(),
               c = (p[0] - p[2]).squaredNorm();
  const double lo = std::min({a, b, c}), hi = std::max({a, b, c});
  if (lo < kTiny) return kDegenerate;
  return std::min(std::sqrt(hi / lo), kDegenerate);
}

double tri_shape(const TriNodes& p) {
  const Vector3d v1 = p[1] - p[0], v2 = p[2] - p[0];
  const double area2 = v1.cross(v2).norm();
  if (area2 == 0.0) return 0.0;
  const double condition = (v1.squaredNorm() + v2.squaredNorm() - v1.dot(v2)) / (area2 * kSqrt3);
  if (condition <= kTiny) return 0.0;
  return std::min(1.0 / condition, 1.0);
}

double tri_shape(const TriNodes& p, const Vector3d& normal) {
  if (area_vector(p).dot(normal) <= 0.0) return 0.0;
  return tri_shape(p);
}

double tri_size(const TriNodes& p) { return 0.5 * area_vector(p).norm(); }

double tri_relative_size(const TriNodes& p, double average_area) {
  if (!(average_area > kTiny)) return 0.0;
  const double area = tri_size(p);
  if (area == 0.0) return 0.0;
  const double r = (area / average_area) * (area / average_area);
  return std::min(r, 1.0 / r);
}

}  // namespace cooperage::quality
