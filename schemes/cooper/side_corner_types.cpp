#include "schemes/cooper/side_corner_types.h"

#include "framework/scheme/vertex_angles.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace cooperage::cooper {
namespace {

using scheme::VertexType;

// Types a corner may take: its angle's own first (when it has one), then
// any other within kCornerRetypeDeg of its ideal. The ideals lie 90 degrees
// apart, so there are at most two, and they are consecutive turns.
struct CornerOptions {
  int turn[2] = {0, 0};
  int count = 0;
};

CornerOptions corner_options(double angle) {
  CornerOptions out;
  const auto own = scheme::classify_angle(angle);
  if (own && *own != VertexType::Reversal) out.turn[out.count++] = static_cast<int>(*own);
  for (VertexType t : {VertexType::End, VertexType::Side, VertexType::Corner}) {
    if (out.count == 2 || (own && *own == t)) continue;
    if (std::abs(angle - scheme::ideal_angle_degrees(t)) <= kCornerRetypeDeg)
      out.turn[out.count++] = static_cast<int>(t);
  }
  return out;
}

double departure(double angle, int turn) {
  return std::abs(angle - scheme::ideal_angle_degrees(static_cast<VertexType>(turn)));
}

void directions_of(const std::vector<int>& turn, std::vector<int>& d) {
  d.assign(turn.size(), 0);
  for (size_t k = 1; k < turn.size(); ++k) d[k] = ((d[k - 1] + turn[k]) % 4 + 4) % 4;
}

// The parity that makes the directions agree with `decided` (0 when
// nothing is decided), or -1.
int agreeing_parity(const std::vector<int>& d, const std::vector<int>& decided) {
  int parity = -1;
  for (size_t k = 0; k < d.size(); ++k) {
    if (decided[k] < 0) continue;
    const int p = (d[k] + (decided[k] ? 0 : 1)) % 2;
    if (parity < 0) parity = p;
    if (p != parity) return -1;
  }
  return parity < 0 ? 0 : parity;
}

constexpr size_t kMaxAmbiguous = 12;  // 4,096 typings at most

}  // namespace

bool has_ambiguous_corner(const std::vector<double>& angles) {
  int sum = 0;
  for (double a : angles) {
    const CornerOptions o = corner_options(a);
    if (o.count > 1) return true;
    if (o.count == 1) sum += o.turn[0];
  }
  return sum != 4;
}

bool can_turn_four(const std::vector<double>& angles) {
  int lo = 0, hi = 0;
  for (double a : angles) {
    const CornerOptions o = corner_options(a);
    if (o.count == 0) return false;
    lo += std::min(o.turn[0], o.turn[o.count - 1]);
    hi += std::max(o.turn[0], o.turn[o.count - 1]);
  }
  return lo <= 4 && 4 <= hi;  // options are consecutive turns: every sum between
}

std::optional<SideTyping> type_side_corners(const std::vector<double>& angles,
                                            const std::vector<int>& decided) {
  const size_t n = angles.size();
  if (n == 0 || decided.size() != n) return std::nullopt;
  std::vector<CornerOptions> options(n);
  std::vector<size_t> free;
  for (size_t k = 0; k < n; ++k) {
    options[k] = corner_options(angles[k]);
    if (options[k].count == 0) return std::nullopt;
    if (options[k].count > 1) free.push_back(k);
  }
  if (free.size() > kMaxAmbiguous) free.clear();  // the angles' own types only
  std::optional<SideTyping> best;
  double best_cost = std::numeric_limits<double>::infinity();
  std::vector<int> turn(n), choice(n, 0), d;
  for (size_t k = 0; k < n; ++k) turn[k] = options[k].turn[0];
  // Each corner's departure for each of its types, taken once: a typing's
  // cost sums them in corner order, as before (a side of many corners tries
  // thousands of typings).
  std::vector<std::array<double, 2>> dep(n);
  for (size_t k = 0; k < n; ++k)
    for (int o = 0; o < options[k].count; ++o)
      dep[k][static_cast<size_t>(o)] = departure(angles[k], options[k].turn[o]);
  // Binary count over the free corners, the angles' own types first.
  for (unsigned long pick = 0; pick < (1UL << free.size()); ++pick) {
    for (size_t f = 0; f < free.size(); ++f) {
      choice[free[f]] = static_cast<int>((pick >> f) & 1);
      turn[free[f]] = options[free[f]].turn[choice[free[f]]];
    }
    int sum = 0;
    double cost = 0;
    for (size_t k = 0; k < n; ++k) {
      sum += turn[k];
      cost += dep[k][static_cast<size_t>(choice[k])];
    }
    if (sum != 4 || cost >= best_cost) continue;
    directions_of(turn, d);
    const int parity = agreeing_parity(d, decided);
    if (parity < 0) continue;
    best = SideTyping{turn, d, parity};
    best_cost = cost;
    if (pick == 0) return best;  // the angles' own types agree: nothing to choose
  }
  return best;
}

}  // namespace cooperage::cooper
