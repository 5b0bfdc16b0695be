// A gap whose image leaves the subcap it splits through the very hole it
// starts and ends on (Blacker 1996, sec. 5.2 with 5.3): blind holes from
// both ends a little off one axis, both cut by a through hole (campaign
// seed 27 case 81). The top floor's rim, projected, runs from the through
// hole's rim into the part's remainder, across the bottom floor's rim (the
// remainder's hole is the through hole and the bottom floor together) and
// out again back to the through hole. Split along the whole path, the
// piece overlapped the bottom floor. Here the two crossings are seamed
// onto nodes of that hole, the parts of the path outside it cut pieces off
// the remainder that join the hole, and the part inside stays a gap: the
// subcap filling the hole there (the bottom floor) is split by it in a
// later step.
#include "schemes/cooper/imprinter.h"

#include <algorithm>

namespace cooperage::cooper::detail {
namespace {

// The nodes of `loop` strictly between positions i and j, walking in
// direction `dir` (+1 or -1).
Loop walk(const Loop& loop, size_t i, size_t j, int dir) {
  Loop out;
  const size_t n = loop.size();
  for (size_t k = (i + n + static_cast<size_t>(dir)) % n; k != j;
       k = (k + n + static_cast<size_t>(dir)) % n)
    out.push_back(loop[k]);
  return out;
}

// Steps from i to j walking in direction dir.
size_t steps(size_t n, size_t i, size_t j, int dir) {
  return dir > 0 ? (j + n - i) % n : (i + n - j) % n;
}

}  // namespace

bool Imprinter::gap_through_own_hole(int e, const Loop& around, const Loop& gap, const Loop& path,
                                     bool seamed, int x, int y, size_t bi, const Loop& fresh,
                                     const Undo& undo) {
  const Subcap b = caps(1 - e)[bi];
  const size_t m = gap.size();
  if (m < 3 || path.size() != m || x == y) return false;
  size_t hole = 0;
  for (size_t l = 1; l < b.loops.size() && hole == 0; ++l) {
    if (index_in(b.loops[l], x) >= 0 && index_in(b.loops[l], y) >= 0) hole = l;
  }
  if (hole == 0) return false;
  const Loop H = b.loops[hole];
  const size_t n = H.size();
  Loop chain{x};
  chain.insert(chain.end(), path.begin(), path.end());
  chain.push_back(y);
  // The chain's crossings of H away from its nodes: exactly two, on two
  // segments of the chain; the closest seams first.
  std::vector<ChainCrossing> found = chain_crossings(chain, H, xy());
  if (found.size() != 2) return false;
  sort_along_chain(found);
  if (found[0].s == found[1].s) return false;
  const auto free_b = [&](int v) { return !partner(1 - e, v) && !exterior_.count(v); };
  using Choice = SeamChoice;
  const std::vector<Choice> choices = seam_choices(found[0], found[1], H, gap, 2, free_b, xy());
  const size_t ix = static_cast<size_t>(index_in(H, x));
  const size_t iy = static_cast<size_t>(index_in(H, y));
  // For a choice and the path's nodes p: the piece cut off before the hole
  // (x, p, h1 and H back to x), the one after it (h2, p, y and H back to
  // h2), each empty when it has no area, and the grown hole; H must meet x,
  // h1, h2, y in that order.
  struct Split {
    Loop first, second, grown;
    size_t arc = 0;  // steps along H from h1 to h2
  };
  auto split = [&](const Choice& c, const Loop& p) -> std::optional<Split> {
    const size_t i1 = static_cast<size_t>(index_in(H, c.h1));
    const size_t i2 = static_cast<size_t>(index_in(H, c.h2));
    for (int dir : {1, -1}) {
      const size_t a = steps(n, ix, i1, dir), b2 = steps(n, ix, i2, dir),
                   b3 = steps(n, ix, iy, dir);
      if (!(a > 0 && a < b2 && b2 < b3)) continue;
      Split out;
      out.arc = b2 - a;
      Loop before(p.begin(), p.begin() + static_cast<long>(c.j1));
      Loop after(p.begin() + static_cast<long>(c.j2) + 1, p.end());
      // The piece before: x, p[0, j1), h1, then H back from h1 to x.
      out.first = {x};
      out.first.insert(out.first.end(), before.begin(), before.end());
      out.first.push_back(c.h1);
      const Loop back1 = walk(H, i1, ix, -dir);
      out.first.insert(out.first.end(), back1.begin(), back1.end());
      // The piece after: h2, p(j2, m), y, then H back from y to h2.
      out.second = {c.h2};
      out.second.insert(out.second.end(), after.begin(), after.end());
      out.second.push_back(y);
      const Loop back2 = walk(H, iy, i2, -dir);
      out.second.insert(out.second.end(), back2.begin(), back2.end());
      // The grown hole: x, p before, h1, H on to h2, h2, p after, y, H on to x.
      out.grown = {x};
      out.grown.insert(out.grown.end(), before.begin(), before.end());
      out.grown.push_back(c.h1);
      const Loop mid = walk(H, i1, i2, dir);
      out.grown.insert(out.grown.end(), mid.begin(), mid.end());
      out.grown.push_back(c.h2);
      out.grown.insert(out.grown.end(), after.begin(), after.end());
      out.grown.push_back(y);
      const Loop rest = walk(H, iy, ix, dir);
      out.grown.insert(out.grown.end(), rest.begin(), rest.end());
      // Pieces without area (the path along an edge of H) are no pieces.
      for (Loop* piece : {&out.first, &out.second}) {
        if (piece->size() < 3) piece->clear();
        if (!piece->empty() && signed_area(*piece, xy()) < 0)
          std::reverse(piece->begin(), piece->end());
      }
      if (signed_area(out.grown, xy()) > 0) std::reverse(out.grown.begin(), out.grown.end());
      // The hole grows by the pieces: |grown| = |H| + |first| + |second|.
      const double ah = std::abs(signed_area(H, xy()));
      double pieces = 0;
      for (const Loop* piece : {&out.first, &out.second})
        if (!piece->empty()) pieces += signed_area(*piece, xy());
      const double ag = std::abs(signed_area(out.grown, xy()));
      if (std::abs(ag - ah - pieces) > 1e-9 * std::max(1.0, ag)) return std::nullopt;
      return out;
    }
    return std::nullopt;
  };
  const Choice* chosen = nullptr;
  for (const Choice& c : choices) {
    const auto s = split(c, path);
    if (!s) continue;
    // Even pieces here, and in the subcap filling the hole once the gap's
    // middle splits it along an arc of H.
    const bool even =
        s->first.size() % 2 == 0 && s->second.size() % 2 == 0 && (s->arc + (c.j2 - c.j1)) % 2 == 0;
    if (options_.even_parity && !even) continue;
    chosen = &c;
    break;
  }
  if (!chosen) return false;
  // Project again: the ends to the chosen hole nodes, the middle left as a gap.
  const Choice c = *chosen;
  roll_back(e, fresh, undo);
  const Loop p = project_with_seams(e, gap, around, seamed, c);
  const auto s = split(c, p);
  if (!s) {
    // Seamed otherwise this time: the path as it was, and no step.
    roll_back(e, fresh, undo);
    for (int v : gap) project(e, v, around, seamed);
    return false;
  }
  // b keeps its outer loop and its other holes but those inside a piece,
  // which go with it; H grows by the pieces.
  Subcap& t = caps(1 - e)[bi];
  std::vector<Loop> kept{t.loops.front()};
  std::vector<std::vector<Loop>> pieces;
  for (const Loop* piece : {&s->first, &s->second})
    if (!piece->empty()) pieces.push_back({*piece});
  for (size_t l = 1; l < t.loops.size(); ++l) {
    if (l == hole) {
      kept.push_back(s->grown);
      continue;
    }
    const Loop& other = t.loops[l];
    bool taken = false;
    for (auto& piece : pieces) {
      if (!taken && point_in_loop(xy().at(other.front()), piece.front(), xy())) {
        piece.push_back(other);
        taken = true;
      }
    }
    if (!taken) kept.push_back(other);
  }
  t.loops = std::move(kept);
  const int parent = t.id;
  for (auto& piece : pieces) new_cap(1 - e, std::move(piece), parent);
  r_.steps.push_back(ImprintStep::Intersect);
  r_.steps.push_back(ImprintStep::Subtract);
  return true;
}

}  // namespace cooperage::cooper::detail
