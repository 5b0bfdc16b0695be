#include "framework/intervals/separable_optimum.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "framework/intervals/deviation.h"

namespace cooperage::intervals::detail {
namespace {

/// One column's cost as CBC sees it: per cost term, its weight and the
/// secant lines whose maximum is the term (the function solve_ilp's
/// increments add up to).
struct ColumnCost {
  std::vector<std::pair<double, std::vector<std::pair<double, double>>>> terms;

  double at(long x) const {
    double sum = 0.0;
    for (const auto& [weight, lines] : terms) {
      double h = -std::numeric_limits<double>::infinity();
      for (auto [slope, intercept] : lines)
        h = std::max(h, slope * static_cast<double>(x) + intercept);
      sum += weight * h;
    }
    return sum;
  }
};

/// Two costs closer than this are a tie: CBC's own tolerances could pick
/// either, so such a column is left to it.
bool clearly_below(double a, double b) { return a < b - 1e-9 * (1.0 + std::abs(b)); }

/// The unique integer minimiser of a convex cost over [lo, hi], walking
/// downhill from `x`; nullopt on a tie.
std::optional<int> unique_minimiser(const ColumnCost& cost, long x, long lo, long hi) {
  double g = cost.at(x);
  const int step = x < hi && clearly_below(cost.at(x + 1), g) ? 1 : -1;
  while (x + step >= lo && x + step <= hi) {
    const double next = cost.at(x + step);
    if (!clearly_below(next, g)) break;
    x += step;
    g = next;
  }
  // Convexity: a strict local minimum on the integers is the only minimum.
  for (long n : {x - 1, x + 1})
    if (n >= lo && n <= hi && !clearly_below(g, cost.at(n))) return std::nullopt;
  return static_cast<int>(x);
}

}  // namespace

std::optional<std::vector<int>> separable_optimum(const std::vector<Column>& columns,
                                                  const std::vector<Row>& rows) {
  std::vector<int> x(columns.size());
  for (size_t j = 0; j < columns.size(); ++j) {
    const Column& c = columns[j];
    if (c.hi && *c.hi == c.lo) {  // a constant
      x[j] = c.lo;
      continue;
    }
    if (c.costs.empty()) return std::nullopt;  // any value is as good: CBC picks
    ColumnCost cost;
    for (const Cost& term : c.costs)
      cost.terms.emplace_back(term.weight,
                              cost_lines(term.target, cost_breakpoints(term.target, c.lo, c.hi)));
    const long lo = c.lo;
    const long hi = c.hi ? *c.hi : std::numeric_limits<int>::max();
    const long start = std::clamp<long>(std::lround(c.costs.front().target), lo, hi);
    const std::optional<int> best = unique_minimiser(cost, start, lo, hi);
    if (!best) return std::nullopt;
    x[j] = *best;
  }
  if (!satisfies(columns, rows, x)) return std::nullopt;
  return x;
}

}  // namespace cooperage::intervals::detail
