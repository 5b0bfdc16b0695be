// Shape measures of 2D quadrilaterals used inside the pave scheme (2D
// counterparts of Verdict's quad scaled Jacobian; quality/quad_metrics.h
// holds the 3D reference versions).
#pragma once

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

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

// Two quads' scaled Jacobians (scaled_jacobian_2d) at once, one per lane of a two-double
// vector: the same operations in the same order as the scalar function (and
// square roots and quotients are correctly rounded either way), so the same
// bits. Node smoothing evaluates every quad around a node for every trial
// position; this is most of a large paved face's time.
typedef double Pair2d __attribute__((vector_size(16)));

inline Pair2d sqrt_pair(Pair2d v) {
#if defined(__SSE2__)
  return reinterpret_cast<Pair2d>(_mm_sqrt_pd(reinterpret_cast<__m128d>(v)));
#else
  return Pair2d{std::sqrt(v[0]), std::sqrt(v[1])};
#endif
}

/// Corners (counter-clockwise) of two quads: lane 0 is `p`, lane 1 is `q`.
inline void scaled_jacobian_2d_pair(const Eigen::Vector2d* const p[4],
                                    const Eigen::Vector2d* const q[4], double out[2]) {
  Pair2d ex[4], ey[4], l[4];
  for (int k = 0; k < 4; ++k) {
    const int n = (k + 1) % 4;
    ex[k] = Pair2d{p[n]->x() - p[k]->x(), q[n]->x() - q[k]->x()};
    ey[k] = Pair2d{p[n]->y() - p[k]->y(), q[n]->y() - q[k]->y()};
    l[k] = sqrt_pair(ex[k] * ex[k] + ey[k] * ey[k]);
  }
  const auto valid = (l[0] > 0) & (l[1] > 0) & (l[2] > 0) & (l[3] > 0);
  Pair2d m = {1.0, 1.0};
  for (int k = 0; k < 4; ++k) {
    const int j = (k + 3) % 4;
    const Pair2d v = (ex[j] * ey[k] - ey[j] * ex[k]) / (l[j] * l[k]);
    m = v < m ? v : m;
  }
  out[0] = valid[0] ? m[0] : -1.0;
  out[1] = valid[1] ? m[1] : -1.0;
}

}  // namespace cooperage::pave::detail
