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

// Two-double vectors for the quads around a node being smoothed: the same
// operations in the same order as the scalar function (and square roots and
// quotients are correctly rounded either way), so the same bits. Node
// smoothing evaluates every quad around a node for every trial position;
// this is most of a large paved face's time.
typedef double Pair2d __attribute__((vector_size(16)));

inline Pair2d sqrt_pair(Pair2d v) {
#if defined(__SSE2__)
  return reinterpret_cast<Pair2d>(_mm_sqrt_pd(reinterpret_cast<__m128d>(v)));
#else
  return Pair2d{std::sqrt(v[0]), std::sqrt(v[1])};
#endif
}

/// A quad x, next, opp, prev with x about to move (a node being smoothed):
/// what does not move with it, taken once while its neighbours stay put --
/// the next and previous corners, the two edges at the opposite corner, their
/// lengths and that corner's value.
struct MovingCornerQuad {
  double nx, ny, px, py;
  double e1x, e1y, e2x, e2y, l1, l2, opp;
};

inline MovingCornerQuad moving_corner_quad(const Eigen::Vector2d& next, const Eigen::Vector2d& opp,
                                           const Eigen::Vector2d& prev) {
  MovingCornerQuad k;
  k.nx = next.x();
  k.ny = next.y();
  k.px = prev.x();
  k.py = prev.y();
  k.e1x = opp.x() - next.x();
  k.e1y = opp.y() - next.y();
  k.e2x = prev.x() - opp.x();
  k.e2y = prev.y() - opp.y();
  k.l1 = std::sqrt(k.e1x * k.e1x + k.e1y * k.e1y);
  k.l2 = std::sqrt(k.e2x * k.e2x + k.e2y * k.e2y);
  k.opp = (k.e1x * k.e2y - k.e1y * k.e2x) / (k.l1 * k.l2);
  return k;
}

/// scaled_jacobian_2d(x, next, opp, prev) of quads q[0..n), two at a time (one
/// per lane of a two-double vector): the moving corners in the scalar
/// function's operations and order, so the same bits.
inline void scaled_jacobians_at(const MovingCornerQuad* q, size_t n, const Eigen::Vector2d& x,
                                double* out) {
  const Pair2d xx = {x.x(), x.x()};
  const Pair2d xy = {x.y(), x.y()};
  size_t k = 0;
  for (; k + 2 <= n; k += 2) {
    const MovingCornerQuad& a = q[k];
    const MovingCornerQuad& b = q[k + 1];
    const Pair2d e0x = Pair2d{a.nx, b.nx} - xx;
    const Pair2d e0y = Pair2d{a.ny, b.ny} - xy;
    const Pair2d e3x = xx - Pair2d{a.px, b.px};
    const Pair2d e3y = xy - Pair2d{a.py, b.py};
    const Pair2d l0 = sqrt_pair(e0x * e0x + e0y * e0y);
    const Pair2d l3 = sqrt_pair(e3x * e3x + e3y * e3y);
    const Pair2d e1x = {a.e1x, b.e1x}, e1y = {a.e1y, b.e1y};
    const Pair2d e2x = {a.e2x, b.e2x}, e2y = {a.e2y, b.e2y};
    const Pair2d l1 = {a.l1, b.l1}, l2 = {a.l2, b.l2};
    const auto valid = (l0 > 0) & (l1 > 0) & (l2 > 0) & (l3 > 0);
    Pair2d m = {1.0, 1.0};
    const Pair2d v0 = (e3x * e0y - e3y * e0x) / (l3 * l0);
    m = v0 < m ? v0 : m;
    const Pair2d v1 = (e0x * e1y - e0y * e1x) / (l0 * l1);
    m = v1 < m ? v1 : m;
    const Pair2d v2 = {a.opp, b.opp};
    m = v2 < m ? v2 : m;
    const Pair2d v3 = (e2x * e3y - e2y * e3x) / (l2 * l3);
    m = v3 < m ? v3 : m;
    out[k] = valid[0] ? m[0] : -1.0;
    out[k + 1] = valid[1] ? m[1] : -1.0;
  }
  if (k < n) {
    const MovingCornerQuad& a = q[k];
    const double e0x = a.nx - x.x(), e0y = a.ny - x.y();
    const double e3x = x.x() - a.px, e3y = x.y() - a.py;
    const double l0 = std::sqrt(e0x * e0x + e0y * e0y);
    const double l3 = std::sqrt(e3x * e3x + e3y * e3y);
    if (!(l0 > 0) || !(a.l1 > 0) || !(a.l2 > 0) || !(l3 > 0)) {
      out[k] = -1.0;
    } else {
      double m = 1.0;
      m = std::min(m, (e3x * e0y - e3y * e0x) / (l3 * l0));
      m = std::min(m, (e0x * a.e1y - e0y * a.e1x) / (l0 * a.l1));
      m = std::min(m, a.opp);
      m = std::min(m, (a.e2x * e3y - a.e2y * e3x) / (a.l2 * l3));
      out[k] = m;
    }
  }
}

}  // namespace cooperage::pave::detail
