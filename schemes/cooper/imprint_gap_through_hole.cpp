// A gap whose image crosses a hole of the subcap it splits (Blacker 1996,
// sec. 5.2 with 5.3): a blind hole's floor from below reaching past a
// boss's footprint above, the footprint a hole of the top's remainder and
// a subcap of its own. Split as if the hole were not there, the hole went
// whole to one piece although the path runs through it. Here the path's
// two crossings of the hole are combined onto nodes of both loops (sec.
// 5.4, as for free loops in imprint_intersect.cpp), the subcap is split
// along path - hole arc - path, one arc of the hole to each piece, and the
// part of the gap inside the hole stays a gap: the subcap filling the hole
// is split by it in a later step. The chain may also start and end on
// another hole of the subcap (a footprint reaching a through hole's rim):
// then the piece leaves the subcap and that hole grows by it and by the
// crossed hole's disk.
#include "schemes/cooper/imprinter.h"

#include <algorithm>
#include <cmath>

namespace cooperage::cooper::detail {
namespace {

// The nodes of `loop` strictly between positions i and j, walking forward.
Loop between(const Loop& loop, size_t i, size_t j) {
  Loop out;
  for (size_t k = (i + 1) % loop.size(); k != j; k = (k + 1) % loop.size()) out.push_back(loop[k]);
  return out;
}

}  // namespace

bool Imprinter::gap_through_hole(int e, const Loop& around, const Loop& gap, const Loop& path,
                                 bool seamed, int x, int y, size_t bi, const Loop& fresh,
                                 const Undo& undo) {
  const Subcap b = caps(1 - e)[bi];
  const size_t m = gap.size();
  if (m < 2 || path.size() != m || x == y) return false;
  // The loop of b the chain starts and ends on: its outer loop, or a hole
  // (a boss's footprint reaching a through hole's rim from inside the top).
  size_t ends = b.loops.size();
  for (size_t l = 0; l < b.loops.size() && ends == b.loops.size(); ++l) {
    if (index_in(b.loops[l], x) >= 0 && index_in(b.loops[l], y) >= 0) ends = l;
  }
  if (ends == b.loops.size()) return false;
  Loop chain{x};
  chain.insert(chain.end(), path.begin(), path.end());
  chain.push_back(y);
  // The crossings of the chain with b's holes: exactly two, on one hole.
  std::vector<ChainCrossing> found;
  size_t hole = 0;
  for (size_t h = 1; h < b.loops.size(); ++h) {
    if (h == ends) continue;
    const std::vector<ChainCrossing> c = chain_crossings(chain, b.loops[h], xy());
    if (c.empty()) continue;
    if (hole != 0) return false;
    hole = h;
    found = c;
  }
  if (found.size() != 2) return false;
  sort_along_chain(found);
  const Loop H = b.loops[hole];
  const Loop& outer = b.loops[ends];
  // Outer ends: the two pieces' areas add up to b's (H runs clockwise).
  // Hole ends: the hole grows by the piece and H's disk, |new hole| =
  // |hole| + |H| + |piece|.
  const double whole = ends == 0
                           ? signed_area(outer, xy()) + signed_area(H, xy())
                           : std::abs(signed_area(outer, xy())) + std::abs(signed_area(H, xy()));
  const auto free_b = [&](int v) { return !partner(1 - e, v) && !exterior_.count(v); };
  // A hole of b inside `piece` (judged by a node of it not on the piece).
  const auto inside = [&](const Loop& other, const Loop& piece) {
    const auto free_node =
        std::find_if(other.begin(), other.end(), [&](int v) { return index_in(piece, v) < 0; });
    return free_node != other.end() && point_in_loop(xy().at(*free_node), piece, xy());
  };
  // The closest seams first; of those, the first whose pieces are all even.
  using Choice = SeamChoice;
  const std::vector<Choice> choices = seam_choices(found[0], found[1], H, gap, 1, free_b, xy());
  // The two pieces of b for a choice, with the path's nodes `p` (gap node
  // j's image at p[j]): path to h1, one arc of H, h2, path on; the pair whose
  // areas add up to b's. Empty when none does.
  auto pieces = [&](const Choice& c, const Loop& p) -> std::pair<Loop, Loop> {
    const size_t i1 = static_cast<size_t>(index_in(H, c.h1));
    const size_t i2 = static_cast<size_t>(index_in(H, c.h2));
    std::pair<Loop, Loop> split[2];
    for (int d = 0; d < 2; ++d) {
      Loop interior(p.begin(), p.begin() + static_cast<long>(c.j1));
      interior.push_back(c.h1);
      Loop arc = d == 0 ? between(H, i1, i2) : between(H, i2, i1);
      if (d == 1) std::reverse(arc.begin(), arc.end());
      interior.insert(interior.end(), arc.begin(), arc.end());
      interior.push_back(c.h2);
      interior.insert(interior.end(), p.begin() + static_cast<long>(c.j2) + 1, p.end());
      split[d] = split_loop(outer, x, interior, y);
    }
    const double tol = 1e-9 * std::max(1.0, std::abs(whole));
    for (int d = 0; d < 2; ++d) {
      const Loop& left = d == 0 ? split[0].first : split[1].first;
      const Loop& right = d == 0 ? split[1].second : split[0].second;
      const double al = signed_area(left, xy()), ar = signed_area(right, xy());
      if (ends == 0) {
        if (al > 0 && ar > 0 && std::abs(al + ar - whole) <= tol) return {left, right};
        continue;
      }
      // {piece, grown hole}, either way round; the piece counter-clockwise,
      // the hole clockwise.
      for (int swap = 0; swap < 2; ++swap) {
        Loop piece = swap ? right : left, grown = swap ? left : right;
        const double ap = std::abs(swap ? ar : al), ag = std::abs(swap ? al : ar);
        if (!(ap > tol) || std::abs(ag - ap - whole) > tol) continue;
        if (signed_area(piece, xy()) < 0) std::reverse(piece.begin(), piece.end());
        if (signed_area(grown, xy()) > 0) std::reverse(grown.begin(), grown.end());
        return {piece, grown};
      }
    }
    return {};
  };
  // A kept image seamed onto the hole makes the pieces touch themselves
  // there, and their parts' parity is not chosen here.
  const auto on_hole = [&](const Choice& c) {
    for (size_t j = 0; j < m; ++j) {
      if ((j < c.j1 || j > c.j2) && index_in(H, path[j]) >= 0) return true;
    }
    return false;
  };
  const Choice* chosen = nullptr;
  for (const Choice& c : choices) {
    if (on_hole(c)) continue;
    const auto [left, right] = pieces(c, path);
    if (left.empty()) continue;
    // Even pieces here, and in the subcap filling the hole once the gap's
    // middle splits it along an arc of H (both arcs alike: H is even).
    const long arc = (index_in(H, c.h2) - index_in(H, c.h1) + static_cast<long>(H.size())) %
                     static_cast<long>(H.size());
    // With hole ends b keeps its outer loop and the holes the piece does
    // not take: both counts are of all their loops.
    size_t piece_count = left.size(), rest = right.size();
    for (size_t l = 0; ends != 0 && l < b.loops.size(); ++l) {
      if (l == ends || l == hole) continue;
      (l != 0 && inside(b.loops[l], left) ? piece_count : rest) += b.loops[l].size();
    }
    const bool even =
        piece_count % 2 == 0 && rest % 2 == 0 && (arc + static_cast<long>(c.j2 - c.j1)) % 2 == 0;
    if (options_.even_parity && !even) continue;
    chosen = &c;
    break;
  }
  if (!chosen) return false;
  // Project again: the ends to the chosen hole nodes, the middle left as a gap.
  const Choice c = *chosen;
  roll_back(e, fresh, undo);
  const Loop p = project_with_seams(e, gap, around, seamed, c);
  const auto [left, right] = pieces(c, p);
  if (left.empty()) {
    // Seamed otherwise this time: the path as it was, and no step.
    roll_back(e, fresh, undo);
    for (int v : gap) project(e, v, around, seamed);
    return false;
  }
  if (ends == 0) {
    caps(1 - e)[bi].loops.erase(caps(1 - e)[bi].loops.begin() + static_cast<long>(hole));
    replace(1 - e, bi, {left, right});
  } else {
    // b keeps its outer loop and its other holes, the piece's inside it go
    // with the piece (as in split_hole).
    Subcap& t = caps(1 - e)[bi];
    std::vector<Loop> kept{t.loops.front()}, piece_loops{left};
    for (size_t l = 1; l < t.loops.size(); ++l) {
      if (l == hole) continue;
      if (l == ends) {
        kept.push_back(right);
        continue;
      }
      (inside(t.loops[l], left) ? piece_loops : kept).push_back(t.loops[l]);
    }
    t.loops = std::move(kept);
    new_cap(1 - e, std::move(piece_loops), t.id);
  }
  r_.steps.push_back(ImprintStep::Intersect);
  r_.steps.push_back(ImprintStep::Subtract);
  return true;
}

Loop Imprinter::project_with_seams(int e, const Loop& gap, const Loop& around, bool seamed,
                                   const SeamChoice& c) {
  Loop p(gap.size(), -1);
  for (size_t j = 0; j < gap.size(); ++j) {
    if (j == c.j1 || j == c.j2) {
      const int h = j == c.j1 ? c.h1 : c.h2;
      link(e, gap[j], h);
      r_.seams.push_back({gap[j], h});
      r_.steps.push_back(ImprintStep::Seam);
      p[j] = h;
    } else if (j < c.j1 || j > c.j2) {
      p[j] = project(e, gap[j], around, seamed);
    }
  }
  return p;
}

}  // namespace cooperage::cooper::detail
