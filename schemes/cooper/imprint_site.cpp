#include "schemes/cooper/imprint_site.h"

#include "schemes/cooper/imprint_polygons.h"

#include <algorithm>
#include <set>
#include <vector>

namespace cooperage::cooper {
namespace {

// The loops of the subcaps listed, of one end.
std::vector<const std::vector<int>*> loops_of(const std::vector<Subcap>& caps,
                                              const std::vector<int>& ids) {
  const std::set<int> wanted(ids.begin(), ids.end());
  std::vector<const std::vector<int>*> out;
  for (const Subcap& c : caps) {
    if (!wanted.count(c.id)) continue;
    for (const auto& l : c.loops) out.push_back(&l);
  }
  return out;
}

// Every node of `from` against every edge of `to`: the closest approach
// above `touch`, kept in `site` when closer than what it holds.
// Nodes of the exterior ring (joined to the other end by the barrel's own
// ribs) and edges between two of them are settled: where the two ends' outer
// rims run together (a wall charted twice) is no place to name.
void approach(const std::vector<const std::vector<int>*>& from,
              const std::vector<const std::vector<int>*>& to, const std::map<int, Vec2>& xy,
              const std::set<int>& linked, double touch, ImprintSite& site) {
  for (const auto* lf : from) {
    for (int n : *lf) {
      if (linked.count(n)) continue;
      const Vec2& p = xy.at(n);
      for (const auto* lt : to) {
        const size_t m = lt->size();
        for (size_t k = 0; k < m; ++k) {
          const int a = (*lt)[k], b = (*lt)[(k + 1) % m];
          if (a == n || b == n) continue;  // a shared node: a contact
          if (linked.count(a) && linked.count(b)) continue;
          const double d = (p - detail::closest_on_segment(p, xy.at(a), xy.at(b))).norm();
          if (d > touch && d < site.gap) {
            site.gap = d;
            site.node = n;
            site.at = p;
          }
        }
      }
    }
  }
}

}  // namespace

ImprintSite narrowest_gap(const ImprintResult& r) {
  ImprintSite site;
  const auto upper = loops_of(r.ends.upper, r.unmatched[0]);
  const auto lower = loops_of(r.ends.lower, r.unmatched[1]);
  if (upper.empty() || lower.empty()) return site;
  double length = 0.0;
  size_t edges = 0;
  for (const auto* list : {&upper, &lower}) {
    for (const auto* l : *list) {
      for (size_t k = 0; k < l->size(); ++k) {
        length += (r.ends.xy.at((*l)[(k + 1) % l->size()]) - r.ends.xy.at((*l)[k])).norm();
        ++edges;
      }
    }
  }
  site.edge = edges ? length / static_cast<double>(edges) : 0.0;
  const double touch = 1e-6 * site.edge;
  // The exterior ribs: all ribs but those the imprint made.
  const std::set<std::pair<int, int>> made(r.interior_ribs.begin(), r.interior_ribs.end());
  std::set<int> linked;
  for (const auto& rib : r.ends.ribs) {
    if (made.count(rib)) continue;
    linked.insert(rib.first);
    linked.insert(rib.second);
  }
  approach(upper, lower, r.ends.xy, linked, touch, site);
  approach(lower, upper, r.ends.xy, linked, touch, site);
  return site;
}

}  // namespace cooperage::cooper
