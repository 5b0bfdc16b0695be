// Sized curve spacing (a size function along the curve, from curve_sizing):
// nodes equidistributed under it, checked against the integral computed
// independently by the midpoint rule.
#include "framework/mesh/curve_spacing.h"

#include <gtest/gtest.h>

#include <cmath>

namespace cooperage::mesh {
namespace {

// The integral of ds / size between two arc lengths, by a fine midpoint rule.
double midpoint_integral(const SizeFunction& f, double length, double a, double b) {
  const int n = 20000;
  double sum = 0;
  for (int i = 0; i < n; ++i) {
    const double s = a + (b - a) * (i + 0.5) / n;
    const double x = s / length;
    size_t k = 0;
    while (k + 2 < f.at.size() && f.at[k + 1] < x) ++k;
    const double t = (x - f.at[k]) / (f.at[k + 1] - f.at[k]);
    sum += (b - a) / n / ((1 - t) * f.size[k] + t * f.size[k + 1]);
  }
  return sum;
}

TEST(SizedSpacing, ConstantSizeIsUniform) {
  SizeFunction f{{0.0, 0.5, 1.0}, {2.0, 2.0, 2.0}};
  EXPECT_NEAR(f.intervals(10.0), 5.0, 1e-12);
  CurveSpacing sp;
  sp.kind = CurveSpacing::Kind::Sized;
  sp.sizes = f;
  const auto s = spacing_fractions(5, 10.0, sp);
  for (int i = 0; i <= 5; ++i) EXPECT_NEAR(s[static_cast<size_t>(i)], i / 5.0, 1e-12);
}

TEST(SizedSpacing, IntervalsGrowFromASmallEndAndCarryEqualShares) {
  // 0.5 at the start, growing by 0.5 per unit length up to 10 at s = 19,
  // then constant: a small feature at the start of a 50-long curve.
  SizeFunction f;
  for (int k = 0; k <= 50; ++k) {
    f.at.push_back(k / 50.0);
    f.size.push_back(std::min(10.0, 0.5 + 0.5 * k));
  }
  const double total = f.intervals(50.0);
  EXPECT_NEAR(total, midpoint_integral(f, 50.0, 0.0, 50.0), 1e-6);
  EXPECT_NEAR(total, 2.0 * std::log(10.0 / 0.5) + 31.0 / 10.0, 1e-9);
  const int n = static_cast<int>(std::lround(total));
  CurveSpacing sp;
  sp.kind = CurveSpacing::Kind::Sized;
  sp.sizes = f;
  const auto s = spacing_fractions(n, 50.0, sp);
  ASSERT_EQ(s.size(), static_cast<size_t>(n) + 1);
  EXPECT_EQ(s.front(), 0.0);
  EXPECT_EQ(s.back(), 1.0);
  for (int i = 0; i < n; ++i) {
    const double a = s[static_cast<size_t>(i)] * 50.0, b = s[static_cast<size_t>(i) + 1] * 50.0;
    EXPECT_NEAR(midpoint_integral(f, 50.0, a, b), total / n, 1e-4) << "interval " << i;
    if (i > 0) {
      EXPECT_GE(b - a, (s[static_cast<size_t>(i)] - s[static_cast<size_t>(i) - 1]) * 50.0 - 1e-9);
    }
  }
  EXPECT_LT(s[1] * 50.0, 1.5);  // the first interval is near the feature's size
}

}  // namespace
}  // namespace cooperage::mesh
