#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "framework/mesh2d/predicates.h"

namespace cooperage::mesh2d {
namespace {

TEST(Mesh2dPredicates, OrientationSigns) {
  EXPECT_GT(orient2d({0, 0}, {1, 0}, {0, 1}), 0.0);
  EXPECT_LT(orient2d({0, 0}, {0, 1}, {1, 0}), 0.0);
  EXPECT_EQ(orient2d({0, 0}, {1, 1}, {2, 2}), 0.0);
}

// Near-collinear points where naive evaluation gets the sign wrong
// (Kettner et al., "Classroom examples of robustness problems").
TEST(Mesh2dPredicates, OrientationExactNearCollinear) {
  const Point2 b(12.0, 12.0);
  const Point2 c(24.0, 24.0);
  for (int i = 0; i < 64; ++i) {
    for (int j = 0; j < 64; ++j) {
      const Point2 a(0.5 + i * std::ldexp(1.0, -53), 0.5 + j * std::ldexp(1.0, -53));
      const double s = orient2d(a, b, c);
      // Exact sign: a is left of b->c iff a.y > a.x (the line is y = x).
      const double expected = a.y() > a.x() ? 1.0 : (a.y() < a.x() ? -1.0 : 0.0);
      EXPECT_EQ((s > 0) - (s < 0), static_cast<int>(expected)) << i << " " << j;
      // Permutation consistency.
      const double s2 = orient2d(b, c, a);
      EXPECT_EQ((s > 0) - (s < 0), (s2 > 0) - (s2 < 0));
    }
  }
}

TEST(Mesh2dPredicates, IncircleExactOnCircle) {
  // Points exactly on the unit circle (Pythagorean triples).
  const Point2 a(5, 0), b(0, 5), c(-5, 0);
  EXPECT_EQ(incircle(a, b, c, {0, -5}), 0.0);
  EXPECT_EQ(incircle(a, b, c, {3, 4}), 0.0);
  EXPECT_GT(incircle(a, b, c, {0, 0}), 0.0);
  EXPECT_LT(incircle(a, b, c, {6, 0}), 0.0);
  // Tiny perturbations off the circle are resolved exactly.
  const double e = std::ldexp(1.0, -50);
  EXPECT_GT(incircle(a, b, c, {3 - e, 4}), 0.0);
  EXPECT_LT(incircle(a, b, c, {3 + e, 4}), 0.0);
  // Large offsets (exactly representable sums): the sign stays exact.
  const Point2 o(1099511627776.0, 1099511627776.0);
  EXPECT_EQ(incircle(o + a, o + b, o + c, o + Point2(3, -4)), 0.0);
  EXPECT_GT(incircle(o + a, o + b, o + c, o + Point2(3, 3.75)), 0.0);
}

// The exact path against integer arithmetic: points with integer
// coordinates (|x| < 2^20) have determinants that __int128 holds exactly;
// moving them by a large exact offset and scaling by a power of two keeps
// the sign. Collinear and cocircular sets make most queries ambiguous to the
// filter, so the expansions decide them.
__extension__ typedef __int128 Int128;  // a GCC/Clang extension: exact here

int sign128(Int128 v) { return (v > 0) - (v < 0); }

Int128 orient_int(const long long* a, const long long* b, const long long* c) {
  return static_cast<Int128>(a[0] - c[0]) * (b[1] - c[1]) -
         static_cast<Int128>(a[1] - c[1]) * (b[0] - c[0]);
}

Int128 incircle_int(const long long* a, const long long* b, const long long* c,
                    const long long* d) {
  const Int128 adx = a[0] - d[0], ady = a[1] - d[1];
  const Int128 bdx = b[0] - d[0], bdy = b[1] - d[1];
  const Int128 cdx = c[0] - d[0], cdy = c[1] - d[1];
  return (adx * adx + ady * ady) * (bdx * cdy - cdx * bdy) +
         (bdx * bdx + bdy * bdy) * (cdx * ady - adx * cdy) +
         (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady);
}

TEST(Mesh2dPredicates, ExactSignsAgreeWithIntegerArithmetic) {
  std::mt19937_64 rng(20261202);
  std::uniform_int_distribution<long long> small(-40, 40);
  std::uniform_int_distribution<long long> big(-(1LL << 19), 1LL << 19);
  // Integer points on circles x^2 + y^2 = r^2 (r = 5, 25, 65, 325: many
  // lattice points) and on lines through the origin.
  std::vector<std::array<long long, 2>> circle;
  for (long long r : {5LL, 25LL, 65LL, 325LL}) {
    for (long long x = -r; x <= r; ++x) {
      const long long y2 = r * r - x * x;
      const long long y = std::llround(std::sqrt(static_cast<double>(y2)));
      if (y * y == y2) {
        circle.push_back({x * (1000 / r + 1), y * (1000 / r + 1)});  // same circle scaled
        if (y != 0) circle.push_back({x * (1000 / r + 1), -y * (1000 / r + 1)});
      }
    }
  }
  int orient_zero = 0, incircle_zero = 0, checked = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    long long p[4][2];
    const int kind = trial % 3;
    if (kind == 0) {  // collinear-ish: a line with small perturbations
      const long long dx = small(rng), dy = small(rng), x0 = big(rng), y0 = big(rng);
      for (auto& q : p) {
        const long long t = small(rng) * 97;
        q[0] = x0 + t * dx + (rng() % 8 == 0 ? small(rng) % 2 : 0);
        q[1] = y0 + t * dy;
      }
    } else if (kind == 1) {  // cocircular-ish
      const long long cx = big(rng), cy = big(rng);
      std::uniform_int_distribution<size_t> pick(0, circle.size() - 1);
      for (auto& q : p) {
        const auto& c = circle[pick(rng)];
        q[0] = cx + c[0] + (rng() % 8 == 0 ? small(rng) % 2 : 0);
        q[1] = cy + c[1];
      }
    } else {  // general position
      for (auto& q : p) q[0] = big(rng), q[1] = big(rng);
    }
    const double offset = std::ldexp(1.0, 30) * static_cast<double>(trial % 5);
    const double unit = std::ldexp(1.0, -10 * (trial % 7));
    Point2 d[4];
    for (int i = 0; i < 4; ++i) {
      d[i] = Point2((static_cast<double>(p[i][0]) + offset) * unit,
                    (static_cast<double>(p[i][1]) + offset) * unit);
    }
    const int so = sign128(orient_int(p[0], p[1], p[2]));
    const double o = orient2d(d[0], d[1], d[2]);
    ASSERT_EQ((o > 0) - (o < 0), so) << "trial " << trial;
    orient_zero += so == 0;
    if (so > 0) {  // incircle needs a counter-clockwise triangle
      const int si = sign128(incircle_int(p[0], p[1], p[2], p[3]));
      const double ic = incircle(d[0], d[1], d[2], d[3]);
      ASSERT_EQ((ic > 0) - (ic < 0), si) << "trial " << trial;
      incircle_zero += si == 0;
      ++checked;
    }
  }
  // The sets really are degenerate often enough to reach the exact path.
  EXPECT_GT(orient_zero, 1000);
  EXPECT_GT(incircle_zero, 200);
  EXPECT_GT(checked, 5000);
}

// A second, plainer exact evaluation to compare with: every operation is a
// chain of Grow-Expansion steps on heap vectors (Shewchuk's simplest
// algorithm; quadratic, but each step is easy to check by eye). The
// predicates use merged sums and scaled products on fixed buffers.
using Slow = std::vector<double>;

Slow slow_grow(const Slow& e, double b) {
  Slow h;
  double q = b;
  for (double x : e) {
    const double sum = q + x;
    const double bv = sum - q;
    const double err = (q - (sum - bv)) + (x - bv);
    if (err != 0.0) h.push_back(err);
    q = sum;
  }
  h.push_back(q);
  return h;
}

Slow slow_add(Slow e, const Slow& f) {
  for (double x : f) e = slow_grow(e, x);
  return e;
}

Slow slow_mul(const Slow& e, const Slow& f) {
  Slow h{0.0};
  for (double x : e) {
    for (double y : f) {
      const double p = x * y;
      h = slow_grow(slow_grow(h, std::fma(x, y, -p)), p);
    }
  }
  return h;
}

Slow slow_diff(double a, double b) { return slow_grow(Slow{a}, -b); }

Slow slow_neg(Slow e) {
  for (double& x : e) x = -x;
  return e;
}

int slow_sign(const Slow& e) {
  for (auto it = e.rbegin(); it != e.rend(); ++it) {
    if (*it != 0.0) return (*it > 0) - (*it < 0);
  }
  return 0;
}

int slow_incircle(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  const Slow adx = slow_diff(a.x(), d.x()), ady = slow_diff(a.y(), d.y());
  const Slow bdx = slow_diff(b.x(), d.x()), bdy = slow_diff(b.y(), d.y());
  const Slow cdx = slow_diff(c.x(), d.x()), cdy = slow_diff(c.y(), d.y());
  const Slow al = slow_add(slow_mul(adx, adx), slow_mul(ady, ady));
  const Slow bl = slow_add(slow_mul(bdx, bdx), slow_mul(bdy, bdy));
  const Slow cl = slow_add(slow_mul(cdx, cdx), slow_mul(cdy, cdy));
  const Slow bc = slow_add(slow_mul(bdx, cdy), slow_neg(slow_mul(cdx, bdy)));
  const Slow ca = slow_add(slow_mul(cdx, ady), slow_neg(slow_mul(adx, cdy)));
  const Slow ab = slow_add(slow_mul(adx, bdy), slow_neg(slow_mul(bdx, ady)));
  return slow_sign(slow_add(slow_add(slow_mul(al, bc), slow_mul(bl, ca)), slow_mul(cl, ab)));
}

int slow_orient(const Point2& a, const Point2& b, const Point2& c) {
  return slow_sign(slow_add(slow_mul(slow_diff(a.x(), c.x()), slow_diff(b.y(), c.y())),
                            slow_neg(slow_mul(slow_diff(a.y(), c.y()), slow_diff(b.x(), c.x())))));
}

TEST(Mesh2dPredicates, ExactSignsAgreeWithAPlainerEvaluationOnRoundedPoints) {
  // Points computed on a circle and on a line in floating point: rounding
  // leaves residuals far below the filter's bound, of either sign, spread
  // over several expansion components.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> angle(0.0, 6.283185307179586);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int nonzero = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const double scale = std::ldexp(1.0, static_cast<int>(rng() % 41) - 20);
    const Point2 centre(unit(rng) * 1e3 * scale, unit(rng) * 1e3 * scale);
    const double r = (0.5 + std::abs(unit(rng))) * scale;
    Point2 p[4];
    for (auto& q : p) {
      const double t = angle(rng);
      q = centre + r * Point2(std::cos(t), std::sin(t));
    }
    const int so = slow_orient(p[0], p[1], p[2]);
    const double o = orient2d(p[0], p[1], p[2]);
    ASSERT_EQ((o > 0) - (o < 0), so) << "trial " << trial;
    if (so > 0) {
      const int si = slow_incircle(p[0], p[1], p[2], p[3]);
      const double ic = incircle(p[0], p[1], p[2], p[3]);
      ASSERT_EQ((ic > 0) - (ic < 0), si) << "trial " << trial;
      nonzero += si != 0;
    }
    // Three points on a line through two of them, rounded.
    const double s = unit(rng);
    const Point2 q = p[0] + s * (p[1] - p[0]);
    const double ol = orient2d(p[0], p[1], q);
    ASSERT_EQ((ol > 0) - (ol < 0), slow_orient(p[0], p[1], q)) << "line trial " << trial;
  }
  EXPECT_GT(nonzero, 5000);  // rounding rarely lands exactly on the circle
}

}  // namespace
}  // namespace cooperage::mesh2d
