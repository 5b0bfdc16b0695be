// Seaming a gap onto an opposing boundary arc (Blacker 1996, sec. 5.4). A
// gap r0 -> gap -> r1 whose ends are ribbed to x and y of one opposing
// subcap is normally projected into that subcap and splits it. When the
// projection would leave the subcap (the ends were combined onto nodes a
// crossing passed close to, sec. 5.3), the split would cut a loop through
// its own outside and the subcaps then ping-pong slivers for ever. The
// opposing boundary already runs from x to y, though: when one of its arcs
// has as many free nodes as the gap, the gap's nodes are seamed onto them.
// The rib leans by up to the crossing's offset; no sliver is cut.
#include "schemes/cooper/imprinter.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cooperage::cooper::detail {
namespace {

double distance_to_segment(const Vec2& p, const Vec2& a, const Vec2& b) {
  return (p - closest_on_segment(p, a, b)).norm();
}

double distance_to_loop(const Vec2& p, const Loop& l, const std::map<int, Vec2>& xy) {
  double best = std::numeric_limits<double>::infinity();
  for (size_t k = 0; k < l.size(); ++k)
    best = std::min(best, distance_to_segment(p, xy.at(l[k]), xy.at(l[(k + 1) % l.size()])));
  return best;
}

// The nodes of `outer` strictly between positions i and j, forward or back.
Loop arc_between(const Loop& outer, size_t i, size_t j, bool forward) {
  Loop out;
  const size_t n = outer.size();
  auto next = [&](size_t k) { return forward ? (k + 1) % n : (k + n - 1) % n; };
  for (size_t k = next(i); k != j; k = next(k)) out.push_back(outer[k]);
  return out;
}

}  // namespace

bool Imprinter::gap_leaves_subcap(int e, const Loop& gap, const Loop& around, size_t bi) {
  const Subcap& b = caps(1 - e)[bi];
  for (int v : gap) {
    const Vec2& p = xy().at(v);
    if (point_in_subcap(p, b, xy())) continue;
    // Off by a tenth of an edge: no rounding error on b's boundary.
    const int i = index_in(around, v);
    const size_t n = around.size();
    const double h =
        i < 0 ? 0.0
              : std::min((xy().at(around[(static_cast<size_t>(i) + 1) % n]) - p).norm(),
                         (xy().at(around[(static_cast<size_t>(i) + n - 1) % n]) - p).norm());
    if (distance_to_loop(p, b.loops.front(), xy()) > 0.1 * h) return true;
  }
  return false;
}

bool Imprinter::seam_gap_to_arc(int e, const Loop& gap, int x, int y,
                                const std::vector<int>& common) {
  if (options_.seam_fraction <= 0.0) return false;  // seaming off
  const int o = 1 - e;
  Loop best;
  double best_cost = std::numeric_limits<double>::infinity();
  for (int c : common) {
    const Loop& outer = caps(o)[static_cast<size_t>(c)].loops.front();
    const int ix = index_in(outer, x), iy = index_in(outer, y);
    if (ix < 0 || iy < 0 || ix == iy) continue;
    for (const bool forward : {true, false}) {
      const Loop arc =
          arc_between(outer, static_cast<size_t>(ix), static_cast<size_t>(iy), forward);
      if (arc.size() != gap.size()) continue;
      const bool free = std::none_of(arc.begin(), arc.end(), [&](int w) {
        return partner_[o].count(w) > 0 || exterior_.count(w) > 0;
      });
      if (!free) continue;
      double cost = 0.0;
      for (size_t k = 0; k < gap.size(); ++k) cost += (xy().at(gap[k]) - xy().at(arc[k])).norm();
      if (cost < best_cost) {
        best_cost = cost;
        best = arc;
      }
    }
  }
  if (best.empty()) return false;
  for (size_t k = 0; k < gap.size(); ++k) {
    link(e, gap[k], best[k]);
    r_.interior_ribs.pop_back();  // seams, not new rib nodes
    r_.interior_ribs.push_back(e == 0 ? std::make_pair(gap[k], best[k])
                                      : std::make_pair(best[k], gap[k]));
    r_.seams.push_back({gap[k], best[k]});
  }
  r_.steps.push_back(ImprintStep::Seam);
  return true;
}

}  // namespace cooperage::cooper::detail
