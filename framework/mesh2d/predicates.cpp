#include "framework/mesh2d/predicates.h"

#include <cmath>
#include <limits>
#include <vector>

namespace cooperage::mesh2d {
namespace {

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

namespace detail {

double orient2d_ambiguous(const Point2& a, const Point2& b, const Point2& c, double det) {
  const double s = orient2d_exact(a, b, c);
  if (s == 0.0) return 0.0;
  // Keep the exact sign; report a magnitude no larger than the bound.
  const double mag = std::max(std::abs(det), std::numeric_limits<double>::denorm_min());
  return s > 0.0 ? mag : -mag;
}

double incircle_ambiguous(const Point2& a, const Point2& b, const Point2& c, const Point2& d,
                          double det) {
  const double s = incircle_exact(a, b, c, d);
  if (s == 0.0) return 0.0;
  const double mag = std::max(std::abs(det), std::numeric_limits<double>::denorm_min());
  return s > 0.0 ? mag : -mag;
}

}  // namespace detail

}  // namespace cooperage::mesh2d
