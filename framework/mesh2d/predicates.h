// Robust 2D geometric predicates: orientation and in-circle tests whose sign
// is exact for any double input. A floating-point filter with a
// Shewchuk-style error bound answers almost every query; the rare ambiguous
// ones are re-evaluated exactly with expansion arithmetic (sums of
// non-overlapping doubles).
// cite: J. R. Shewchuk, "Adaptive Precision Floating-Point Arithmetic and Fast
// Robust Geometric Predicates", Discrete Comput. Geom. 18 (1997).
#pragma once

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <limits>

namespace cooperage::mesh2d {

using Point2 = Eigen::Vector2d;

namespace detail {
inline constexpr double kEps = 0.5 * std::numeric_limits<double>::epsilon();  // 2^-53
// Shewchuk's first-stage error bounds (sec. 4.3 of the paper).
inline constexpr double kCcwErrBound = (3.0 + 16.0 * kEps) * kEps;
inline constexpr double kIccErrBound = (10.0 + 96.0 * kEps) * kEps;
// The exact answers for the rare queries the filters cannot decide (out of
// line; the filters are inline because triangulators call them millions of
// times). `det` is the filter's approximate value.
double orient2d_ambiguous(const Point2& a, const Point2& b, const Point2& c, double det);
double incircle_ambiguous(const Point2& a, const Point2& b, const Point2& c, const Point2& d,
                          double det);
}  // namespace detail

/// Twice the signed area of (a, b, c): > 0 counter-clockwise, < 0 clockwise,
/// 0 collinear. The sign is exact; the magnitude is a double approximation.
inline double orient2d(const Point2& a, const Point2& b, const Point2& c) {
  const double detleft = (a.x() - c.x()) * (b.y() - c.y());
  const double detright = (a.y() - c.y()) * (b.x() - c.x());
  const double det = detleft - detright;
  const double detsum = std::abs(detleft) + std::abs(detright);
  if (std::abs(det) > detail::kCcwErrBound * detsum) return det;
  return detail::orient2d_ambiguous(a, b, c, det);
}

/// The closed segments ab and cd share a point (exact signs).
inline bool segments_touch(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  const auto on = [](const Point2& p, const Point2& q, const Point2& x) {  // given collinear
    return std::min(p.x(), q.x()) <= x.x() && x.x() <= std::max(p.x(), q.x()) &&
           std::min(p.y(), q.y()) <= x.y() && x.y() <= std::max(p.y(), q.y());
  };
  const double o1 = orient2d(a, b, c), o2 = orient2d(a, b, d);
  const double o3 = orient2d(c, d, a), o4 = orient2d(c, d, b);
  if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0)))
    return true;
  return (o1 == 0 && on(a, b, c)) || (o2 == 0 && on(a, b, d)) || (o3 == 0 && on(c, d, a)) ||
         (o4 == 0 && on(c, d, b));
}

/// The in-circle determinant in plain double together with its permanent
/// (the sum of the absolute values of its terms), so callers can compare
/// the determinant with a tolerance relative to its own scale.
/// [out] permanent >= 0.
inline double incircle_fast(const Point2& a, const Point2& b, const Point2& c, const Point2& d,
                            double& permanent) {
  const double adx = a.x() - d.x(), ady = a.y() - d.y();
  const double bdx = b.x() - d.x(), bdy = b.y() - d.y();
  const double cdx = c.x() - d.x(), cdy = c.y() - d.y();
  const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
  const double alift = adx * adx + ady * ady;
  const double cdxady = cdx * ady, adxcdy = adx * cdy;
  const double blift = bdx * bdx + bdy * bdy;
  const double adxbdy = adx * bdy, bdxady = bdx * ady;
  const double clift = cdx * cdx + cdy * cdy;
  permanent = (std::abs(bdxcdy) + std::abs(cdxbdy)) * alift +
              (std::abs(cdxady) + std::abs(adxcdy)) * blift +
              (std::abs(adxbdy) + std::abs(bdxady)) * clift;
  return alift * (bdxcdy - cdxbdy) + blift * (cdxady - adxcdy) + clift * (adxbdy - bdxady);
}

/// > 0 when d lies strictly inside the circle through a, b, c (a, b, c
/// counter-clockwise), < 0 outside, 0 on it. Sign exact, magnitude approximate.
inline double incircle(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  double permanent = 0.0;
  const double det = incircle_fast(a, b, c, d, permanent);
  if (std::abs(det) > detail::kIccErrBound * permanent) return det;
  return detail::incircle_ambiguous(a, b, c, d, det);
}

}  // namespace cooperage::mesh2d
