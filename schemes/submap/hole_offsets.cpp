#include "schemes/submap/hole_offsets.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace cooperage::submap {

std::vector<LatticePoint> rank_hole_offsets(const Vec2& predicted, const LatticePoint& lo,
                                            const LatticePoint& hi, double tie) {
  std::vector<std::pair<double, LatticePoint>> candidates;
  for (int oi = lo[0]; oi <= hi[0]; ++oi) {
    for (int oj = lo[1]; oj <= hi[1]; ++oj) {
      candidates.push_back({std::hypot(oi - predicted.x(), oj - predicted.y()), {oi, oj}});
    }
  }
  std::sort(candidates.begin(), candidates.end());
  // Groups of (numerically) equal distance, anchored at their nearest member,
  // re-ranked by the offsets alone.
  std::vector<LatticePoint> out;
  out.reserve(candidates.size());
  for (size_t start = 0; start < candidates.size();) {
    size_t end = start + 1;
    while (end < candidates.size() && candidates[end].first - candidates[start].first <= tie) {
      ++end;
    }
    std::vector<LatticePoint> group;
    for (size_t k = start; k < end; ++k) group.push_back(candidates[k].second);
    std::sort(group.begin(), group.end());
    out.insert(out.end(), group.begin(), group.end());
    start = end;
  }
  return out;
}

}  // namespace cooperage::submap
