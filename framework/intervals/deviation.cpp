#include "framework/intervals/deviation.h"

#include <algorithm>
#include <cmath>

namespace cooperage::intervals {

double relative_deviation(double x, double goal) {
  return x >= goal ? (x - goal) / goal : (goal - x) / x;
}

double deviation_cost(double x, double goal) {
  const double f = relative_deviation(x, goal);
  return f + f * f * f;
}

namespace detail {

std::vector<int> cost_breakpoints(double goal, int lo, std::optional<int> hi) {
  const long center_raw = std::max(1L, std::lround(goal));
  const long cap = 2 * center_raw + 16;  // beyond: the last secant, extended
  const long reach = std::max<long>(cap, static_cast<long>(lo) + 16);
  const long top = hi ? std::min<long>(*hi, reach) : reach;
  const long center = std::clamp<long>(center_raw, lo, std::max<long>(lo, top));
  std::vector<int> points{lo};
  if (top >= lo) points.push_back(static_cast<int>(top));
  // Offsets 0..4, then 6, 8, 12, 16, 24, 32, ... (x1.5 / x1.33 alternating).
  std::vector<long> offsets{0, 1, 2, 3, 4};
  for (long a = 6, b = 8; a <= center + top; a *= 2, b *= 2) {
    offsets.push_back(a);
    offsets.push_back(b);
  }
  for (long d : offsets) {
    if (center - d >= lo) points.push_back(static_cast<int>(center - d));
    if (center + d <= top) points.push_back(static_cast<int>(center + d));
  }
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  return points;
}

std::vector<std::pair<double, double>> cost_lines(double goal,
                                                  const std::vector<int>& breakpoints) {
  std::vector<std::pair<double, double>> lines;
  if (breakpoints.size() == 1) {
    lines.emplace_back(0.0, deviation_cost(breakpoints.front(), goal));
    return lines;
  }
  for (size_t k = 0; k + 1 < breakpoints.size(); ++k) {
    const double a = breakpoints[k], b = breakpoints[k + 1];
    const double ha = deviation_cost(a, goal), hb = deviation_cost(b, goal);
    const double slope = (hb - ha) / (b - a);
    lines.emplace_back(slope, ha - slope * a);
  }
  return lines;
}

}  // namespace detail
}  // namespace cooperage::intervals
