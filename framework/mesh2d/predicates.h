// Robust 2D geometric predicates: orientation and in-circle tests whose sign
// is exact for any double input. A floating-point filter with a
// Shewchuk-style error bound answers almost every query; the rare ambiguous
// ones are re-evaluated exactly with expansion arithmetic (sums of
// non-overlapping doubles).
// cite: J. R. Shewchuk, "Adaptive Precision Floating-Point Arithmetic and Fast
// Robust Geometric Predicates", Discrete Comput. Geom. 18 (1997).
#pragma once

#include <Eigen/Core>

namespace cooperage::mesh2d {

using Point2 = Eigen::Vector2d;

/// Twice the signed area of (a, b, c): > 0 counter-clockwise, < 0 clockwise,
/// 0 collinear. The sign is exact; the magnitude is a double approximation.
double orient2d(const Point2& a, const Point2& b, const Point2& c);

/// > 0 when d lies strictly inside the circle through a, b, c (a, b, c
/// counter-clockwise), < 0 outside, 0 on it. Sign exact, magnitude approximate.
double incircle(const Point2& a, const Point2& b, const Point2& c, const Point2& d);

/// The in-circle determinant in plain double together with its permanent
/// (the sum of the absolute values of its terms), so callers can compare
/// the determinant with a tolerance relative to its own scale.
/// [out] permanent >= 0.
double incircle_fast(const Point2& a, const Point2& b, const Point2& c, const Point2& d,
                     double& permanent);

}  // namespace cooperage::mesh2d
