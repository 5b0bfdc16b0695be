#include "schemes/pave/corner_picks.h"

#include "schemes/pave/quad_quality_2d.h"

#include <algorithm>
#include <cmath>

namespace cooperage::pave::detail {

double interior_angle(const std::vector<Eigen::Vector2d>& P, const std::vector<int>& L, size_t k) {
  const size_t n = L.size();
  const Eigen::Vector2d& a = P[static_cast<size_t>(L[(k + n - 1) % n])];
  const Eigen::Vector2d& b = P[static_cast<size_t>(L[k % n])];
  const Eigen::Vector2d& c = P[static_cast<size_t>(L[(k + 1) % n])];
  return M_PI - std::atan2(cross2(b - a, c - b), (b - a).dot(c - b));
}

bool is_corner(double interior, double sharp, double reflex_limit) {
  return interior < sharp || (interior > 2 * M_PI - sharp && interior <= reflex_limit);
}

double skipped_quality_of_picks(const std::vector<Eigen::Vector2d>& P, const std::vector<int>& L,
                                const std::vector<size_t>& picks) {
  std::vector<char> coarse(L.size(), 0);
  for (size_t k : picks) coarse[k % L.size()] = 1;
  double worst = 1.0;
  for (size_t k = 0; k < L.size(); ++k) {
    if (!coarse[k]) worst = std::min(worst, std::sin(0.5 * interior_angle(P, L, k)));
  }
  return worst;
}

namespace {

/// Even offset s in [0, g) of the odd edge (from c + s to c + s + 1) in the
/// run of g (odd) fine edges starting at corner c: the worst skipped node
/// best (within 0.01, so straight and gently curved runs count as equal),
/// then nearest the middle, then first along the loop.
size_t odd_edge_offset(const std::vector<double>& q, size_t c, size_t g) {
  const size_t n = q.size();
  // Skipped with the odd edge at s: odd offsets below s, even offsets above s + 1.
  std::vector<double> before(g + 2, 1.0), after(g + 2, 1.0);
  for (size_t s = 0; s + 2 <= g + 1; s += 2)
    before[s + 2] = std::min(before[s], s + 1 < g ? q[(c + s + 1) % n] : 1.0);
  for (size_t t = g - 1; t >= 2; t -= 2) after[t - 2] = std::min(after[t], q[(c + t) % n]);
  double best = -1.0;
  for (size_t s = 0; s < g; s += 2) best = std::max(best, std::min(before[s], after[s]));
  size_t pick = 0;
  double pick_dist = 1e300;
  for (size_t s = 0; s < g; s += 2) {
    if (std::min(before[s], after[s]) < best - 0.01) continue;
    const double dist = std::abs(static_cast<double>(s) + 0.5 - 0.5 * static_cast<double>(g));
    if (dist < pick_dist - 1e-9) {
      pick = s;
      pick_dist = dist;
    }
  }
  return pick;
}

}  // namespace

std::vector<size_t> corner_picks(const std::vector<Eigen::Vector2d>& P, const std::vector<int>& L,
                                 double sharp, double reflex_limit) {
  const size_t n = L.size();
  std::vector<double> q(n);
  std::vector<size_t> corners;
  for (size_t k = 0; k < n; ++k) {
    const double angle = interior_angle(P, L, k);
    q[k] = std::sin(0.5 * angle);
    if (is_corner(angle, sharp, reflex_limit)) corners.push_back(k);
  }
  std::vector<size_t> picks;
  for (size_t i = 0; i < corners.size(); ++i) {
    const size_t c = corners[i];
    const size_t g = i + 1 < corners.size() ? corners[i + 1] - c : corners[0] + n - c;
    const size_t odd_at = g % 2 == 1 ? odd_edge_offset(q, c, g) : g;
    // Every other node; after the odd edge's start, the very next node.
    for (size_t s = 0; s < g; s += s == odd_at ? 1 : 2) picks.push_back((c + s) % n);
  }
  return picks;
}

}  // namespace cooperage::pave::detail
