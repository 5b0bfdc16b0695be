// Shape measures of 2D quadrilaterals used inside the pave scheme (2D
// counterparts of Verdict's quad scaled Jacobian; quality/quad_metrics.h
// holds the 3D reference versions).
#pragma once

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace cooperage::pave::detail {

using Quad = std::array<int, 4>;

inline double cross2(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

/// Scaled Jacobian of the counter-clockwise quad a, b, c, d: min over corners
/// of sin(angle) with sign (negative at a reflex or inverted corner). Square 1.
inline double scaled_jacobian_2d(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                                 const Eigen::Vector2d& c, const Eigen::Vector2d& d) {
  const Eigen::Vector2d e[4] = {b - a, c - b, d - c, a - d};
  double l[4];
  for (int k = 0; k < 4; ++k) {
    l[k] = e[k].norm();
    if (!(l[k] > 0)) return -1.0;
  }
  // Corner k lies between e[k-1] (incoming) and e[k] (outgoing).
  double m = 1.0;
  for (int k = 0; k < 4; ++k) {
    const int j = (k + 3) % 4;
    m = std::min(m, cross2(e[j], e[k]) / (l[j] * l[k]));
  }
  return m;
}

inline double scaled_jacobian_2d(const std::vector<Eigen::Vector2d>& pts, const Quad& q) {
  return scaled_jacobian_2d(pts[static_cast<size_t>(q[0])], pts[static_cast<size_t>(q[1])],
                            pts[static_cast<size_t>(q[2])], pts[static_cast<size_t>(q[3])]);
}

}  // namespace cooperage::pave::detail
