// A path from a subcap's outer loop to one of its holes splits nothing,
// unless the hole touches the outer loop at a node (a tip of an imprinted
// footprint combined onto the outer boundary, sec. 5.3-5.4): outer loop and
// hole are then one boundary pinched at that node, and the path cuts it in
// two (sec. 5.2). The pieces are handed to replace(), which splits a piece
// still touching itself at the pinch (sec. 5.5).
#include "schemes/cooper/imprinter.h"

namespace cooperage::cooper::detail {

bool Imprinter::split_pinched(int e, size_t bi, int x, const Loop& path, int y) {
  Subcap& b = caps(e)[bi];
  const Loop& outer = b.loops.front();
  const bool x_out = index_in(outer, x) >= 0, y_out = index_in(outer, y) >= 0;
  if (x_out == y_out) return false;
  const int on_hole = x_out ? y : x;
  for (size_t h = 1; h < b.loops.size(); ++h) {
    const Loop& hole = b.loops[h];
    const int j = index_in(hole, on_hole);
    if (j < 0) continue;
    // The pinch: a node of the hole on the outer loop.
    int jt = -1, it = -1;
    for (size_t k = 0; k < hole.size() && jt < 0; ++k) {
      const int i = index_in(outer, hole[k]);
      if (i >= 0) {
        jt = static_cast<int>(k);
        it = i;
      }
    }
    if (jt < 0) return false;
    // outer up to the pinch, around the hole back to the pinch, outer on.
    Loop merged(outer.begin(), outer.begin() + it + 1);
    const size_t m = hole.size();
    for (size_t k = 1; k <= m; ++k) merged.push_back(hole[(static_cast<size_t>(jt) + k) % m]);
    merged.insert(merged.end(), outer.begin() + it + 1, outer.end());
    auto [left, right] = split_loop(merged, x, path, y);
    b.loops.erase(b.loops.begin() + static_cast<long>(h));
    replace(e, bi, {left, right});
    r_.steps.push_back(ImprintStep::Subtract);
    return true;
  }
  return false;
}

}  // namespace cooperage::cooper::detail
