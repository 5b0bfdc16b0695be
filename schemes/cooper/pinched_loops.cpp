#include "schemes/cooper/pinched_loops.h"

#include <cmath>
#include <set>

namespace cooperage::cooper {
namespace {

using detail::index_in;
using detail::Loop;

// Joins loop b into loop a at node v (in both): a up to v, b around from v
// back to v, the rest of a. Both keep the domain on their left, so does
// the result.
Loop join_at(const Loop& a, const Loop& b, int v) {
  const size_t ia = static_cast<size_t>(index_in(a, v)), ib = static_cast<size_t>(index_in(b, v));
  Loop out(a.begin(), a.begin() + static_cast<long>(ia) + 1);
  for (size_t k = 1; k <= b.size(); ++k) out.push_back(b[(ib + k) % b.size()]);
  out.insert(out.end(), a.begin() + static_cast<long>(ia) + 1, a.end());
  return out;
}

// A node that two loops share: joins them; false when none does.
bool join_one(std::vector<Loop>& loops) {
  for (size_t i = 0; i < loops.size(); ++i) {
    const std::set<int> in_i(loops[i].begin(), loops[i].end());
    for (size_t j = i + 1; j < loops.size(); ++j) {
      for (int v : loops[j]) {
        if (!in_i.count(v)) continue;
        loops[i] = join_at(loops[i], loops[j], v);
        loops.erase(loops.begin() + static_cast<long>(j));
        return true;
      }
    }
  }
  return false;
}

}  // namespace

UnpinchedLoops unpinch_loops(const std::vector<std::vector<int>>& loops,
                             const std::map<int, Vec2>& xy, double nudge) {
  std::vector<Loop> work = loops;
  while (join_one(work)) {
  }
  UnpinchedLoops out;
  std::set<int> pinched;
  for (const Loop& l : work) {
    std::map<int, int> passes;
    for (int v : l) ++passes[v];
    out.points.emplace_back();
    const size_t n = l.size();
    for (size_t k = 0; k < n; ++k) {
      const int v = l[k];
      Vec2 p = xy.at(v);
      if (passes.at(v) > 1) {
        // Into the wedge on the left of u -> v -> w: the bisector of the
        // angle from (w - v) counter-clockwise to (u - v).
        const Vec2 d1 = xy.at(l[(k + 1) % n]) - p, d2 = xy.at(l[(k + n - 1) % n]) - p;
        double turn = std::atan2(detail::cross(d1, d2), d1.dot(d2));
        if (turn <= 0) turn += 2 * M_PI;
        const double c = std::cos(turn / 2), s = std::sin(turn / 2);
        const Vec2 u = d1.normalized();
        p += nudge * std::min(d1.norm(), d2.norm()) *
             Vec2(c * u.x() - s * u.y(), s * u.x() + c * u.y());
        pinched.insert(v);
      }
      out.points.back().push_back(p);
      out.nodes.push_back(v);
    }
  }
  out.pinches = static_cast<int>(pinched.size());
  return out;
}

}  // namespace cooperage::cooper
