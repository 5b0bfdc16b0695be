// Quad metrics after Verdict (sandialabs/verdict V_QuadMetric.cpp).
// Written from the definitions, not copied.
#include "framework/quality/quad_metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Geometry>

#include "framework/quality/metric.h"
#include "framework/quality/tri_metrics.h"

namespace cooperage::quality {

namespace {

using Eigen::Vector3d;

constexpr double kTiny = std::numeric_limits<double>::min();

struct Edges {
  std::array<Vector3d, 4> e;
  std::array<double, 4> len2;
};

Edges edges(const QuadNodes& p) {
  Edges r;
  for (int i = 0; i < 4; ++i) {
    r.e[i] = p[(i + 1) % 4] - p[i];
    r.len2[i] = r.e[i].squaredNorm();
  }
  return r;
}

// Corner k sits between edge (k+3)%4 (incoming) and edge k (outgoing).
std::array<double, 4> corner_areas(const Edges& ed, const Vector3d* reference) {
  Vector3d n;
  if (reference) {
    n = *reference;
  } else {
    n = (ed.e[0] - ed.e[2]).cross(ed.e[1] - ed.e[3]);
  }
  const double nn = n.norm();
  std::array<double, 4> a{0.0, 0.0, 0.0, 0.0};
  if (nn <= kTiny) return a;
  n /= nn;
  for (int k = 0; k < 4; ++k) a[k] = n.dot(ed.e[(k + 3) % 4].cross(ed.e[k]));
  return a;
}

bool collapsed(const QuadNodes& p) { return p[2] == p[3]; }

TriNodes first_tri(const QuadNodes& p) { return {p[0], p[1], p[2]}; }

double scaled_jacobian_impl(const QuadNodes& p, const Vector3d* normal) {
  if (collapsed(p)) {
    return normal ? tri_scaled_jacobian(first_tri(p), *normal) : tri_scaled_jacobian(first_tri(p));
  }
  const Edges ed = edges(p);
  for (double l2 : ed.len2) {
    if (std::sqrt(l2) < kTiny) return 0.0;
  }
  const auto a = corner_areas(ed, normal);
  double best = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 4; ++k) {
    best = std::min(best, a[k] / std::sqrt(ed.len2[(k + 3) % 4] * ed.len2[k]));
  }
  return best;
}

double jacobian_impl(const QuadNodes& p, const Vector3d* normal) {
  if (collapsed(p)) {
    return normal ? tri_jacobian(first_tri(p), *normal) : tri_jacobian(first_tri(p));
  }
  const auto a = corner_areas(edges(p), normal);
  return std::min({a[0], a[1], a[2], a[3]});
}

double shape_impl(const QuadNodes& p, const Vector3d* normal) {
  const Edges ed = edges(p);
  for (double l2 : ed.len2) {
    if (l2 <= kTiny) return 0.0;
  }
  const auto a = corner_areas(ed, normal);
  double best = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 4; ++k) best = std::min(best, a[k] / (ed.len2[(k + 3) % 4] + ed.len2[k]));
  best *= 2.0;
  return best < kTiny ? 0.0 : best;
}

}  // namespace

double quad_scaled_jacobian(const QuadNodes& p) { return scaled_jacobian_impl(p, nullptr); }
double quad_scaled_jacobian(const QuadNodes& p, const Vector3d& normal) {
  return scaled_jacobian_impl(p, &normal);
}

double quad_jacobian(const QuadNodes& p) { return jacobian_impl(p, nullptr); }
double quad_jacobian(const QuadNodes& p, const Vector3d& normal) {
  return jacobian_impl(p, &normal);
}

double quad_shape(const QuadNodes& p) { return shape_impl(p, nullptr); }
double quad_shape(const QuadNodes& p, const Vector3d& normal) { return shape_impl(p, &normal); }

double quad_skew(const QuadNodes& p) {
  Vector3d x1 = p[1] + p[2] - p[3] - p[0];
  Vector3d x2 = p[2] + p[3] - p[0] - p[1];
  const double n1 = x1.norm(), n2 = x2.norm();
  if (n1 < kTiny || n2 < kTiny) return 0.0;
  return std::abs((x1 / n1).dot(x2 / n2));
}

double quad_taper(const QuadNodes& p) {
  const Vector3d x1 = p[1] + p[2] - p[3] - p[0];
  const Vector3d x2 = p[2] + p[3] - p[0] - p[1];
  const Vector3d x12 = p[0] + p[2] - p[1] - p[3];
  const double m = std::min(x1.norm(), x2.norm());
  if (m < kTiny) return kDegenerate;
  return std::min(x12.norm() / m, kDegenerate);
}

double quad_max_aspect_frobenius(const QuadNodes& p) {
  const Edges ed = edges(p);
  double worst = 0.0;
  for (int k = 0; k < 4; ++k) {
    const int in = (k + 3) % 4;
    const double c = ed.e[in].cross(ed.e[k]).norm();
    if (c < kTiny) return kDegenerate;
    worst = std::max(worst, (ed.len2[in] + ed.len2[k]) / c);
  }
  return std::min(0.5 * worst, kDegenerate);
}

double quad_edge_ratio(const QuadNodes& p) {
  const Edges ed = edges(p);
  const double lo = *std::min_element(ed.len2.begin(), ed.len2.end());
  const double hi = *std::max_element(ed.len2.begin(), ed.len2.end());
  if (lo < kTiny) return kDegenerate;
  return std::min(std::sqrt(hi / lo), kDegenerate);
}

double quad_size(const QuadNodes& p) {
  const auto a = corner_areas(edges(p), nullptr);
  return 0.25 * (a[0] + a[1] + a[2] + a[3]);
}

double quad_relative_size(const QuadNodes& p, double average_area) {
  if (!(average_area > kTiny)) return 0.0;
  const double r = quad_size(p) / average_area;
  if (r <= kTiny) return 0.0;
  const double m = std::min(r, 1.0 / r);
  return m * m;
}

}  // namespace cooperage::quality
