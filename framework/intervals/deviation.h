// The per-curve cost of an interval count (Mitchell 1997, 2013; ALGORITHMS.md
// sec. 2 [V]) and its convex piecewise-linear form for the integer program.
#pragma once

#include <optional>
#include <utility>
#include <vector>

namespace cooperage::intervals {

/// Relative deviation of count x from goal g > 0 (Mitchell):
/// f(x) = (x - g) / g for x >= g, (g - x) / x for x < g. Convex on x > 0,
/// zero at the goal; going below the goal costs more than going above.
double relative_deviation(double x, double goal);

/// The cost minimised per curve (before its firmness weight):
/// h(x) = f + f^3. The f^3 term is Mitchell's min-sum-of-cubes, which is
/// close to lexicographic max-min (one big deviation costs more than several
/// small ones); the linear term keeps small deviations distinguishable.
/// Convex in x because f is convex and t -> t + t^3 is convex increasing.
double deviation_cost(double x, double goal);

namespace detail {

/// Integer breakpoints of the piecewise-linear cost of one curve: every
/// integer within 4 of round(goal), then 6, 8, 12, 16, 24, ... away, clipped
/// to [lo, hi] and to max(2 round(goal), lo) + 16 above; always contains lo and that
/// top end. Ascending, unique.
std::vector<int> cost_breakpoints(double goal, int lo, std::optional<int> hi);

/// The secant lines (slope, intercept) of deviation_cost between consecutive
/// breakpoints: t >= slope * x + intercept for all of them is, at integer x,
/// exactly h(x) at every breakpoint and the linear interpolation between
/// them (h convex), and the last segment extended beyond. One line for a
/// single breakpoint (slope 0).
std::vector<std::pair<double, double>> cost_lines(double goal, const std::vector<int>& breakpoints);

}  // namespace detail
}  // namespace cooperage::intervals
