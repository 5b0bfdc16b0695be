#include "framework/mesh2d/predicates.h"

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

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

/// A non-overlapping expansion of at most N components, in increasing
/// magnitude, zeros eliminated (n may be 0: the value 0). Fixed-size
/// buffers on the stack: the exact path runs about once per quad in pave's
/// frontal fill, and heap-allocated expansions made it the CDT's main cost.
/// The bounds follow from Shewchuk's: a sum has at most m + n components, a
/// product at most 2mn.
template <std::size_t N>
struct Expansion {
  std::array<double, N> v;
  std::size_t n = 0;
};

// e + f, merged by magnitude and compressed with a chain of two-sums
// (Shewchuk's Fast-Expansion-Sum, zeros eliminated; exact under
// round-to-even arithmetic).
template <std::size_t M, std::size_t N>
Expansion<M + N> add(const Expansion<M>& e, const Expansion<N>& f) {
  Expansion<M + N> h;
  if (e.n == 0 || f.n == 0) {
    const auto& g = e.n == 0 ? f.v.data() : e.v.data();
    h.n = e.n == 0 ? f.n : e.n;
    for (std::size_t i = 0; i < h.n; ++i) h.v[i] = g[i];
    return h;
  }
  // Merge by increasing magnitude.
  std::array<double, M + N> g;
  std::size_t i = 0, j = 0, k = 0;
  while (i < e.n && j < f.n) {
    g[k++] = std::abs(f.v[j]) < std::abs(e.v[i]) ? f.v[j++] : e.v[i++];
  }
  while (i < e.n) g[k++] = e.v[i++];
  while (j < f.n) g[k++] = f.v[j++];
  double q = g[0];
  for (std::size_t m = 1; m < k; ++m) {
    double sum = 0.0, err = 0.0;
    two_sum(q, g[m], sum, err);
    if (err != 0.0) h.v[h.n++] = err;
    q = sum;
  }
  if (q != 0.0) h.v[h.n++] = q;
  return h;
}

// e * b (Shewchuk's Scale-Expansion, zeros eliminated).
template <std::size_t N>
Expansion<2 * N> scale(const Expansion<N>& e, double b) {
  Expansion<2 * N> h;
  if (e.n == 0 || b == 0.0) return h;
  double q = 0.0, lo = 0.0;
  two_product(e.v[0], b, q, lo);
  if (lo != 0.0) h.v[h.n++] = lo;
  for (std::size_t i = 1; i < e.n; ++i) {
    double p_hi = 0.0, p_lo = 0.0;
    two_product(e.v[i], b, p_hi, p_lo);
    double sum = 0.0, err = 0.0;
    two_sum(q, p_lo, sum, err);
    if (err != 0.0) h.v[h.n++] = err;
    two_sum(p_hi, sum, q, err);  // p_hi + sum is exact as q + err
    if (err != 0.0) h.v[h.n++] = err;
  }
  if (q != 0.0) h.v[h.n++] = q;
  return h;
}

// e * f: the sum of e scaled by each component of f.
template <std::size_t M, std::size_t N>
Expansion<2 * M * N> mul(const Expansion<M>& e, const Expansion<N>& f) {
  Expansion<2 * M * N> h;
  for (std::size_t j = 0; j < f.n; ++j) {
    const Expansion<2 * M> t = scale(e, f.v[j]);
    const Expansion<2 * M* N + 2 * M> s = add(h, t);
    for (std::size_t i = 0; i < s.n; ++i) h.v[i] = s.v[i];  // s.n <= 2 M (j + 1)
    h.n = s.n;
  }
  return h;
}

template <std::size_t N>
Expansion<N> negate(Expansion<N> e) {
  for (std::size_t i = 0; i < e.n; ++i) e.v[i] = -e.v[i];
  return e;
}

Expansion<2> diff(double a, double b) {
  Expansion<2> e;
  double x = 0.0, y = 0.0;
  two_sum(a, -b, x, y);
  if (y != 0.0) e.v[e.n++] = y;
  if (x != 0.0) e.v[e.n++] = x;
  return e;
}

// The largest component carries the sign.
template <std::size_t N>
double sign_of(const Expansion<N>& e) {
  return e.n == 0 ? 0.0 : e.v[e.n - 1];
}

double orient2d_exact(const Point2& a, const Point2& b, const Point2& c) {
  const auto acx = diff(a.x(), c.x()), acy = diff(a.y(), c.y());
  const auto bcx = diff(b.x(), c.x()), bcy = diff(b.y(), c.y());
  return sign_of(add(mul(acx, bcy), negate(mul(acy, bcx))));
}

double incircle_exact(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  const auto adx = diff(a.x(), d.x()), ady = diff(a.y(), d.y());
  const auto bdx = diff(b.x(), d.x()), bdy = diff(b.y(), d.y());
  const auto cdx = diff(c.x(), d.x()), cdy = diff(c.y(), d.y());
  const auto alift = add(mul(adx, adx), mul(ady, ady));
  const auto blift = add(mul(bdx, bdx), mul(bdy, bdy));
  const auto clift = add(mul(cdx, cdx), mul(cdy, cdy));
  const auto bc = add(mul(bdx, cdy), negate(mul(cdx, bdy)));
  const auto ca = add(mul(cdx, ady), negate(mul(adx, cdy)));
  const auto ab = add(mul(adx, bdy), negate(mul(bdx, ady)));
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
