#include "schemes/submap/classify.h"

#include <cmath>
#include <limits>

namespace cooperage::submap {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kTie = 1e-9;

// Cost of giving type value t to a corner with angle theta and raw type t0.
double change_cost(double theta, int t0, int t, bool pinned, const ClassifyOptions& options) {
  if (t == t0) return 0.0;
  if (pinned) return kInf;
  const double deviation = std::abs(theta - 90.0 * (2 - t));
  if (deviation > options.max_repair_deviation) return kInf;
  return (deviation + 1e-6) * std::abs(t - t0);
}

}  // namespace

VertexType type_of(int t) {
  switch (t) {
    case 1: return VertexType::End;
    case 0: return VertexType::Side;
    case -1: return VertexType::Corner;
    default: return VertexType::Reversal;
  }
}

std::optional<std::vector<VertexType>> repair_loop(const std::vector<double>& angles,
                                                   const std::vector<VertexType>& raw,
                                                   const std::vector<bool>& pinned, int target_sum,
                                                   const ClassifyOptions& options) {
  const int n = static_cast<int>(angles.size());
  // Running sums lie in [-2 n, n]; index s + 2 n.
  const int width = 3 * n + 1;
  auto idx = [&](int s) { return s + 2 * n; };
  if (target_sum < -2 * n || target_sum > n) return std::nullopt;
  // best[i][s]: least cost of corners i..n-1 whose types sum to s.
  std::vector<std::vector<double>> best(static_cast<size_t>(n + 1),
                                        std::vector<double>(static_cast<size_t>(width), kInf));
  best[static_cast<size_t>(n)][static_cast<size_t>(idx(0))] = 0.0;
  for (int i = n - 1; i >= 0; --i) {
    const size_t ui = static_cast<size_t>(i);
    const int t0 = t_of(raw[ui]);
    for (int s = -2 * n; s <= n; ++s) {
      double b = kInf;
      for (int t = -2; t <= 1; ++t) {
        const int rest = s - t;
        if (rest < -2 * n || rest > n) continue;
        const double tail = best[ui + 1][static_cast<size_t>(idx(rest))];
        if (tail == kInf) continue;
        const double c = change_cost(angles[ui], t0, t, pinned[ui], options);
        if (c == kInf) continue;
        b = std::min(b, c + tail);
      }
      best[ui][static_cast<size_t>(idx(s))] = b;
    }
  }
  if (best[0][static_cast<size_t>(idx(target_sum))] == kInf) return std::nullopt;
  // Forward reconstruction: at each corner prefer the raw type, then the
  // cheaper change, then the smaller |t - t0|, then the larger t.
  std::vector<VertexType> types;
  types.reserve(static_cast<size_t>(n));
  int s = target_sum;
  for (int i = 0; i < n; ++i) {
    const size_t ui = static_cast<size_t>(i);
    const int t0 = t_of(raw[ui]);
    const double goal = best[ui][static_cast<size_t>(idx(s))];
    int chosen = t0;
    double chosen_cost = kInf;
    for (int t : {t0, 1, 0, -1, -2}) {
      const int rest = s - t;
      if (rest < -2 * n || rest > n) continue;
      const double tail = best[ui + 1][static_cast<size_t>(idx(rest))];
      const double c = change_cost(angles[ui], t0, t, pinned[ui], options);
      if (tail == kInf || c == kInf) continue;
      if (std::abs(c + tail - goal) <= kTie * (1.0 + goal) &&
          (chosen_cost == kInf || c < chosen_cost - kTie ||
           (std::abs(c - chosen_cost) <= kTie && std::abs(t - t0) < std::abs(chosen - t0)))) {
        chosen = t;
        chosen_cost = c;
      }
    }
    types.push_back(type_of(chosen));
    s -= chosen;
  }
  return types;
}

LoopTypes classify_loop(const std::vector<CornerInput>& corners, int target_sum,
                        const ClassifyOptions& options) {
  LoopTypes out;
  out.target_sum = target_sum;
  std::vector<double> angles;
  std::vector<bool> pinned;
  for (size_t k = 0; k < corners.size(); ++k) {
    const CornerInput& c = corners[k];
    angles.push_back(c.angle);
    pinned.push_back(c.pinned.has_value());
    if (c.pinned) {
      out.raw.push_back(*c.pinned);
      continue;
    }
    const auto type = scheme::classify_angle(c.angle);
    if (!type) {
      out.bad_corner = static_cast<int>(k);
      out.why = "at " + std::to_string(static_cast<int>(std::lround(c.angle))) +
                " degrees cannot be END/SIDE/CORNER/REVERSAL";
      return out;
    }
    out.raw.push_back(*type);
  }
  for (VertexType t : out.raw) out.raw_sum += t_of(t);
  if (corners.empty()) {
    out.why = "loop has no vertices";
    return out;
  }
  if (out.raw_sum == target_sum) {
    out.ok = true;
    out.types = out.raw;
    return out;
  }
  auto repaired = repair_loop(angles, out.raw, pinned, target_sum, options);
  if (!repaired) {
    out.why = "loop sum " + std::to_string(out.raw_sum) + ", needs " + std::to_string(target_sum) +
              " (no classification within " +
              std::to_string(static_cast<int>(options.max_repair_deviation)) +
              " degrees of the angles repairs it)";
    return out;
  }
  out.ok = true;
  out.types = std::move(*repaired);
  for (size_t k = 0; k < corners.size(); ++k) {
    const int dt = std::abs(t_of(out.types[k]) - t_of(out.raw[k]));
    if (dt != 0) {
      ++out.changed;
      out.cost += std::abs(angles[k] - scheme::ideal_angle_degrees(out.types[k])) * dt;
    }
  }
  return out;
}

}  // namespace cooperage::submap
