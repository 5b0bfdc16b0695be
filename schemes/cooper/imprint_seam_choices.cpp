#include "schemes/cooper/imprint_seam_choices.h"

#include <algorithm>

namespace cooperage::cooper::detail {

std::vector<ChainCrossing> chain_crossings(const Loop& chain, const Loop& loop,
                                           const std::map<int, Vec2>& xy) {
  std::vector<ChainCrossing> found;
  for (size_t s = 0; s + 1 < chain.size(); ++s) {
    for (size_t k = 0; k < loop.size(); ++k) {
      const int q0 = loop[k], q1 = loop[(k + 1) % loop.size()];
      if (chain[s] == q0 || chain[s] == q1 || chain[s + 1] == q0 || chain[s + 1] == q1) continue;
      const auto t = segment_hit(xy.at(chain[s]), xy.at(chain[s + 1]), xy.at(q0), xy.at(q1));
      if (t) found.push_back({s, k, *t});
    }
  }
  return found;
}

void sort_along_chain(std::vector<ChainCrossing>& crossings) {
  std::sort(crossings.begin(), crossings.end(), [](const ChainCrossing& p, const ChainCrossing& q) {
    return p.s != q.s ? p.s < q.s : p.t < q.t;
  });
}

std::vector<SeamChoice> seam_choices(const ChainCrossing& first, const ChainCrossing& second,
                                     const Loop& hole, const Loop& gap, size_t apart,
                                     const std::function<bool(int)>& free,
                                     const std::map<int, Vec2>& xy) {
  std::vector<SeamChoice> choices;
  const long m = static_cast<long>(gap.size());
  for (int mask = 0; mask < 16; ++mask) {
    const long j1 = static_cast<long>(first.s) - 1 + (mask & 1);
    const long j2 = static_cast<long>(second.s) - 1 + ((mask >> 1) & 1);
    const int h1 = hole[(first.k + ((mask >> 2) & 1)) % hole.size()];
    const int h2 = hole[(second.k + ((mask >> 3) & 1)) % hole.size()];
    if (j1 < 0 || j2 >= m || j2 - j1 < static_cast<long>(apart) || h1 == h2) continue;
    if (!free(h1) || !free(h2)) continue;
    const double cost = (xy.at(gap[static_cast<size_t>(j1)]) - xy.at(h1)).norm() +
                        (xy.at(gap[static_cast<size_t>(j2)]) - xy.at(h2)).norm();
    choices.push_back({static_cast<size_t>(j1), static_cast<size_t>(j2), h1, h2, cost});
  }
  std::stable_sort(choices.begin(), choices.end(),
                   [](const SeamChoice& p, const SeamChoice& q) { return p.cost < q.cost; });
  return choices;
}

}  // namespace cooperage::cooper::detail
