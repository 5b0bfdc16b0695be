#include "framework/intervals/deviation.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace cooperage::intervals {
namespace {

TEST(RelativeDeviation, MitchellFormula) {
  EXPECT_DOUBLE_EQ(relative_deviation(10, 10), 0.0);
  EXPECT_DOUBLE_EQ(relative_deviation(11, 10), 0.1);       // (x - g) / g
  EXPECT_DOUBLE_EQ(relative_deviation(11, 12), 1.0 / 11);  // (g - x) / x
  EXPECT_DOUBLE_EQ(relative_deviation(5, 10), 1.0);        // halving costs like doubling
  EXPECT_DOUBLE_EQ(relative_deviation(20, 10), 1.0);
  EXPECT_DOUBLE_EQ(deviation_cost(20, 10), 2.0);  // f + f^3
}

TEST(CostBreakpoints, DenseNearGoalSparseFarAndWithinBounds) {
  const auto points = detail::cost_breakpoints(10.0, 1, std::nullopt);
  EXPECT_TRUE(std::is_sorted(points.begin(), points.end()));
  EXPECT_EQ(points.front(), 1);
  for (int k = 6; k <= 14; ++k)
    EXPECT_TRUE(std::binary_search(points.begin(), points.end(), k)) << k;
  EXPECT_LT(points.size(), 30u);

  const auto bounded = detail::cost_breakpoints(10.0, 8, 11);
  EXPECT_EQ(bounded, (std::vector<int>{8, 9, 10, 11}));

  const auto high_min = detail::cost_breakpoints(2.0, 50, std::nullopt);
  EXPECT_EQ(high_min.front(), 50);
  EXPECT_GE(high_min.size(), 2u);  // still increasing beyond the minimum
}

TEST(CostLines, MaxOfSecantsIsExactAtBreakpoints) {
  const double goal = 7.3;
  const auto points = detail::cost_breakpoints(goal, 1, std::nullopt);
  const auto lines = detail::cost_lines(goal, points);
  for (int x : points) {
    double t = -1e300;
    for (auto [slope, intercept] : lines) t = std::max(t, slope * x + intercept);
    EXPECT_NEAR(t, deviation_cost(x, goal), 1e-9) << x;
  }
}

}  // namespace
}  // namespace cooperage::intervals
