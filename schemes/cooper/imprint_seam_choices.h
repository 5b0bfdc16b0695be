// Where a gap's image crosses a hole twice (Blacker 1996, sec. 5.3 with
// 5.4): the crossings of the chain x -> image -> y with the hole's loop,
// and the ways of seaming each crossing onto a gap node at one end of the
// crossed chain segment and a hole node at one end of the crossed hole
// segment, closest first. Shared by a gap through another hole of the
// subcap it splits (imprint_gap_through_hole.cpp) and a gap leaving through
// the hole it starts and ends on (imprint_gap_through_own_hole.cpp).
#pragma once

#include "schemes/cooper/imprint_polygons.h"

#include <functional>
#include <map>
#include <vector>

namespace cooperage::cooper::detail {

struct ChainCrossing {
  size_t s = 0;  ///< chain segment chain[s] - chain[s + 1]
  size_t k = 0;  ///< loop segment loop[k] - loop[k + 1]
  double t = 0;  ///< where along the chain segment
};

/// Crossings of the open chain with the closed loop, skipping segment pairs
/// that share a node; in the order of chain segments, then loop segments.
std::vector<ChainCrossing> chain_crossings(const Loop& chain, const Loop& loop,
                                           const std::map<int, Vec2>& xy);

/// Sorts crossings along the chain (segment, then position on it).
void sort_along_chain(std::vector<ChainCrossing>& crossings);

/// Gap node j1 seamed onto hole node h1 at the first crossing, j2 onto h2
/// at the second.
struct SeamChoice {
  size_t j1 = 0, j2 = 0;
  int h1 = 0, h2 = 0;
  double cost = 0;  ///< the two seams' lengths
};

/// For two crossings (sorted along the chain x, image of gap..., y) of the
/// loop `hole`: the chain's node s + 1 is gap node s, so a gap node at
/// either end of each crossed chain segment, and a `free` node of the hole
/// at either end of each crossed hole segment; those with j2 - j1 at least
/// `apart` and distinct hole nodes, the closest first (ties in mask order).
std::vector<SeamChoice> seam_choices(const ChainCrossing& first, const ChainCrossing& second,
                                     const Loop& hole, const Loop& gap, size_t apart,
                                     const std::function<bool(int)>& free,
                                     const std::map<int, Vec2>& xy);

}  // namespace cooperage::cooper::detail
