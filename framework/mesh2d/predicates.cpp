#include "framework/mesh2d/predicates.h"

#include <cmath>
#include <limits>
#include <vector>

namespace cooperage::mesh2d {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon() * 0.5;  // 2^-53
// Shewchuk's first-stage error bounds (sec. 4.3 of the paper).
constexpr double kCcwErrBound = (3.0 + 16.0 * kEps) * kEps;
constexpr double kIccErrBound = (10.0 + 96.0 * kEps) * kEps;

// Exact a + b = x + y (Knuth's two-sum).
inline void two_sum(double a, double b, double& x, double& y) {
  x = a + b;
  const double bv = x - a;
  const double av = x - bv;
  y = (a - av) + (b - bv);
}

// Exact a * b = x + y, using a fused multiply-add for the error term.
inline void two_product(double a, double b, double& x, double& y) {
  x = a * b;
  y = std::fma(a, b, -x);
}

/// A non-overlapping expansion, components in increasing magnitude, no zeros.
using Expansion = std::vector<double>;

// Grow-Expansion with zero elimination: e + b.
Expansion grow(const Expansion& e, double b) {
  Expansion h;
  h.reserve(e.size() + 1);
  double q = b;
  for (double ei : e) {
    double sum = 0.0;
    double err = 0.0;
    two_sum(q, ei, sum, err);
    if (err != 0.0) h.push_back(err);
    q = sum;
  }
  if (q != 0.0 || h.empty()) h.push_back(q);
  return h;
}

Expansion add(const Expansion& e, const Expansion& f) {
  Expansion h = e;
  for (double fi : f) h = grow(h, fi);
  return h;
}

Expansion negate(Expansion e) {
  for (double& x : e) x = -x;
  return e;
}

Expansion mul(const Expansion& e, const Expansion& f) {
  Expansion h{0.0};
  for (double ei : e) {
    for (double fj : f) {
      double x = 0.0;
      double y = 0.0;
      two_product(ei, fj, x, y);
      h = grow(h, y);
      h = grow(h, x);
    }
  }
  return h;
}

Expansion diff(double a, double b) {
  double x = 0.0;
  double y = 0.0;
  two_sum(a, -b, x, y);
  Expansion e;
  if (y != 0.0) e.push_back(y);
  e.push_back(x);
  return e;
}

double sign_of(const Expansion& e) {
  for (auto it = e.rbegin(); it != e.rend(); ++it) {
    if (*it != 0.0) return *it;
  }
  return 0.0;
}

double orient2d_exact(const Point2& a, const Point2& b, const Point2& c) {
  const Expansion acx = diff(a.x(), c.x());
  const Expansion acy = diff(a.y(), c.y());
  const Expansion bcx = diff(b.x(), c.x());
  const Expansion bcy = diff(b.y(), c.y());
  return sign_of(add(mul(acx, bcy), negate(mul(acy, bcx))));
}

double incircle_exact(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  const Expansion adx = diff(a.x(), d.x()), ady = diff(a.y(), d.y());
  const Expansion bdx = diff(b.x(), d.x()), bdy = diff(b.y(), d.y());
  const Expansion cdx = diff(c.x(), d.x()), cdy = diff(c.y(), d.y());
  const Expansion alift = add(mul(adx, adx), mul(ady, ady));
  const Expansion blift = add(mul(bdx, bdx), mul(bdy, bdy));
  const Expansion clift = add(mul(cdx, cdx), mul(cdy, cdy));
  const Expansion bc = add(mul(bdx, cdy), negate(mul(cdx, bdy)));
  const Expansion ca = add(mul(cdx, ady), negate(mul(adx, cdy)));
  const Expansion ab = add(mul(adx, bdy), negate(mul(bdx, ady)));
  return sign_of(add(add(mul(alift, bc), mul(blift, ca)), mul(clift, ab)));
}

}  // namespace

double orient2d(const Point2& a, const Point2& b, const Point2& c) {
  const double detleft = (a.x() - c.x()) * (b.y() - c.y());
  const double detright = (a.y() - c.y()) * (b.x() - c.x());
  const double det = detleft - detright;
  const double detsum = std::abs(detleft) + std::abs(detright);
  if (std::abs(det) > kCcwErrBound * detsum) return det;
  const double s = orient2d_exact(a, b, c);
  if (s == 0.0) return 0.0;
  // Keep the exact sign; report a magnitude no larger than the bound.
  const double mag = std::max(std::abs(det), std::numeric_limits<double>::denorm_min());
  return s > 0.0 ? mag : -mag;
}

double incircle_fast(const Point2& a, const Point2& b, const Point2& c, const Point2& d,
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

double incircle(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  double permanent = 0.0;
  const double det = incircle_fast(a, b, c, d, permanent);
  if (std::abs(det) > kIccErrBound * permanent) return det;
  const double s = incircle_exact(a, b, c, d);
  if (s == 0.0) return 0.0;
  const double mag = std::max(std::abs(det), std::numeric_limits<double>::denorm_min());
  return s > 0.0 ? mag : -mag;
}

}  // namespace cooperage::mesh2d
