#include "schemes/cooper/side_corner_types.h"

#include "framework/scheme/vertex_angles.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cooperage::cooper {
namespace {

using scheme::VertexType;

// Types a corner may take: its angle's own first (when it has one), then
// any other within kCornerRetypeDeg of its ideal.
std::vector<int> corner_options(double angle) {
  std::vector<int> out;
  const auto own = scheme::classify_angle(angle);
  if (own && *own != VertexType::Reversal) out.push_back(static_cast<int>(*own));
  for (VertexType t : {VertexType::End, VertexType::Side, VertexType::Corner}) {
    const int v = static_cast<int>(t);
    if (own && *own == t) continue;
    if (std::abs(angle - scheme::ideal_angle_degrees(t)) <= kCornerRetypeDeg) out.push_back(v);
  }
  return out;
}

double departure(double angle, int turn) {
  return std::abs(angle - scheme::ideal_angle_degrees(static_cast<VertexType>(turn)));
}

std::vector<int> directions_of(const std::vector<int>& turn) {
  std::vector<int> d(turn.size());
  for (size_t k = 1; k < turn.size(); ++k) d[k] = ((d[k - 1] + turn[k]) % 4 + 4) % 4;
  return d;
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
    const auto options = corner_options(a);
    if (options.size() > 1) return true;
    if (!options.empty()) sum += options.front();
  }
  return sum != 4;
}

std::optional<SideTyping> type_side_corners(const std::vector<double>& angles,
                                            const std::vector<int>& decided) {
  const size_t n = angles.size();
  if (n == 0 || decided.size() != n) return std::nullopt;
  std::vector<std::vector<int>> options(n);
  std::vector<size_t> free;
  for (size_t k = 0; k < n; ++k) {
    options[k] = corner_options(angles[k]);
    if (options[k].empty()) return std::nullopt;
    if (options[k].size() > 1) free.push_back(k);
  }
  if (free.size() > kMaxAmbiguous) free.clear();  // the angles' own types only
  std::optional<SideTyping> best;
  double best_cost = std::numeric_limits<double>::infinity();
  std::vector<int> turn(n);
  for (size_t k = 0; k < n; ++k) turn[k] = options[k].front();
  // Mixed-radix count over the free corners, the angles' own types first.
  std::vector<size_t> pick(free.size(), 0);
  for (;;) {
    for (size_t f = 0; f < free.size(); ++f) turn[free[f]] = options[free[f]][pick[f]];
    int sum = 0;
    double cost = 0;
    for (size_t k = 0; k < n; ++k) {
      sum += turn[k];
      cost += departure(angles[k], turn[k]);
    }
    if (sum == 4 && cost < best_cost) {
      const std::vector<int> d = directions_of(turn);
      const int parity = agreeing_parity(d, decided);
      if (parity >= 0) {
        best = SideTyping{turn, d, parity};
        best_cost = cost;
        if (free.empty() || std::all_of(pick.begin(), pick.end(), [](size_t p) { return p == 0; }))
          return best;  // the angles' own types agree: nothing to choose
      }
    }
    size_t f = 0;
    while (f < free.size() && ++pick[f] == options[free[f]].size()) pick[f++] = 0;
    if (f == free.size()) break;
  }
  return best;
}

}  // namespace cooperage::cooper
