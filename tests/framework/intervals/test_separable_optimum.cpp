#include "framework/intervals/separable_optimum.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "framework/intervals/deviation.h"

namespace cooperage::intervals::detail {
namespace {

// The program's objective as solve_ilp states it to CBC: per cost, the
// maximum of the secants of the deviation cost between its breakpoints
// (equal to the deviation cost at the breakpoints, above it between them).
double objective(const std::vector<Column>& columns, const std::vector<int>& x) {
  double sum = 0.0;
  for (size_t j = 0; j < columns.size(); ++j) {
    for (const Cost& c : columns[j].costs) {
      double h = -1e300;
      for (auto [slope, intercept] :
           cost_lines(c.target, cost_breakpoints(c.target, columns[j].lo, columns[j].hi)))
        h = std::max(h, slope * x[j] + intercept);
      sum += c.weight * h;
    }
  }
  return sum;
}

Row even(std::vector<std::pair<int, int>> terms) {
  Row r;
  r.kind = Constraint::Kind::Even;
  r.terms = std::move(terms);
  return r;
}

Row linear(std::vector<std::pair<int, int>> terms, Sense sense, int rhs) {
  Row r;
  r.terms = std::move(terms);
  r.sense = sense;
  r.rhs = rhs;
  return r;
}

TEST(SeparableOptimum, EveryColumnAtItsGoalWhenTheRowsAllowIt) {
  const std::vector<Column> columns{{1, 40, {{4.2, 1.0}}}, {1, 40, {{7.8, 1.0}}}};
  const auto x = separable_optimum(columns, {even({{0, 1}, {1, 1}})});
  ASSERT_TRUE(x);
  EXPECT_EQ(*x, (std::vector<int>{4, 8}));
}

TEST(SeparableOptimum, LeavesToTheSolverWhatNeedsASearch) {
  // The goals break the row: CBC must trade one column against the other.
  const std::vector<Column> columns{{1, 40, {{4.2, 1.0}}}, {1, 40, {{7.8, 1.0}}}};
  EXPECT_FALSE(separable_optimum(columns, {linear({{0, 1}, {1, -1}}, Sense::Equal, 0)}));
  const std::vector<Column> odd_sum{{1, 40, {{4.2, 1.0}}}, {1, 40, {{6.8, 1.0}}}};
  EXPECT_FALSE(separable_optimum(odd_sum, {even({{0, 1}, {1, 1}})}));
  // A column without costs: every value is as good (a feasibility solve).
  EXPECT_FALSE(separable_optimum({{1, 40, {}}}, {}));
  // A tie: goal sqrt(20) deviates as much from 4 (below) as from 5 (above).
  const std::vector<Column> tie{{1, 40, {{std::sqrt(20.0), 1.0}}}};
  ASSERT_NEAR(objective(tie, {4}), objective(tie, {5}), 1e-12);
  EXPECT_FALSE(separable_optimum(tie, {}));
}

TEST(SeparableOptimum, AFixedColumnKeepsItsValue) {
  const auto x = separable_optimum({{6, 6, {}}, {1, 40, {{3.0, 2.0}}}}, {});
  ASSERT_TRUE(x);
  EXPECT_EQ(*x, (std::vector<int>{6, 3}));
}

TEST(SeparableOptimum, AgreesWithAnExhaustiveSearchOnRandomPrograms) {
  // Three columns with one or two goals each, a parity row and a bound on
  // their sum. Whenever an answer is given, it is the only minimiser of the
  // objective over every feasible vector in the box.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> goal(1.5, 9.5), weight(0.5, 2.0);
  int answered = 0;
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<Column> columns(3);
    for (Column& c : columns) {
      c.lo = 1;
      c.hi = 14;
      c.costs.push_back({goal(rng), weight(rng)});
      if (trial % 3 == 0) c.costs.push_back({goal(rng), weight(rng)});
    }
    const std::vector<Row> rows{even({{0, 1}, {1, 1}, {2, 1}}),
                                linear({{0, 1}, {1, 1}, {2, 1}}, Sense::LessEqual, 20)};
    const auto x = separable_optimum(columns, rows);
    if (!x) continue;
    ++answered;
    ASSERT_TRUE(satisfies(columns, rows, *x));
    const double best = objective(columns, *x);
    std::vector<int> y(3);
    for (y[0] = 1; y[0] <= 14; ++y[0]) {
      for (y[1] = 1; y[1] <= 14; ++y[1]) {
        for (y[2] = 1; y[2] <= 14; ++y[2]) {
          if (y == *x || !satisfies(columns, rows, y)) continue;
          ASSERT_GT(objective(columns, y), best) << "trial " << trial;
        }
      }
    }
  }
  EXPECT_GT(answered, 50) << "too few programs answered to test anything";
  EXPECT_LT(answered, 300) << "the parity row should defeat some goals";
}

}  // namespace
}  // namespace cooperage::intervals::detail
