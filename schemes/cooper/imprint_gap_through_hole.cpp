// A gap whose image crosses a hole of the subcap it splits (Blacker 1996,
// sec. 5.2 with 5.3): a blind hole's floor from below reaching past a
// boss's footprint above, the footprint a hole of the top's remainder and
// a subcap of its own. Split as if the hole were not there, the hole went
// whole to one piece although the path runs through it. Here the path's
// two crossings of the hole are combined onto nodes of both loops (sec.
// 5.4, as for free loops in imprint_intersect.cpp), the subcap is split
// along path - hole arc - path, one arc of the hole to each piece, and the
// part of the gap inside the hole stays a gap: the subcap filling the hole
// is split by it in a later step.
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
  if (index_in(b.loops.front(), x) < 0 || index_in(b.loops.front(), y) < 0) return false;
  Loop chain{x};
  chain.insert(chain.end(), path.begin(), path.end());
  chain.push_back(y);
  // The crossings of the chain with b's holes: exactly two, on one hole.
  struct Crossing {
    size_t s;  // chain segment chain[s] - chain[s + 1]
    size_t k;  // hole segment hole[k] - hole[k + 1]
    double t;
  };
  std::vector<Crossing> found;
  size_t hole = 0;
  for (size_t h = 1; h < b.loops.size(); ++h) {
    const Loop& l = b.loops[h];
    for (size_t s = 0; s + 1 < chain.size(); ++s) {
      for (size_t k = 0; k < l.size(); ++k) {
        const int q0 = l[k], q1 = l[(k + 1) % l.size()];
        if (chain[s] == q0 || chain[s] == q1 || chain[s + 1] == q0 || chain[s + 1] == q1) continue;
        const auto t =
            segment_hit(xy().at(chain[s]), xy().at(chain[s + 1]), xy().at(q0), xy().at(q1));
        if (!t) continue;
        if (hole != 0 && hole != h) return false;
        hole = h;
        found.push_back({s, k, *t});
      }
    }
  }
  if (found.size() != 2) return false;
  std::sort(found.begin(), found.end(), [](const Crossing& p, const Crossing& q) {
    return p.s != q.s ? p.s < q.s : p.t < q.t;
  });
  const Loop H = b.loops[hole];
  const Loop& outer = b.loops.front();
  const double whole = signed_area(outer, xy()) + signed_area(H, xy());  // H runs clockwise
  const auto free_b = [&](int v) { return !partner(1 - e, v) && !exterior_.count(v); };
  // Candidates: a gap node at either end of each crossed chain segment (the
  // chain's node s + 1 is gap node s), a free hole node at either end of
  // each crossed hole segment; the closest pairs whose pieces are all even.
  struct Choice {
    size_t j1, j2;
    int h1, h2;
    double cost;
  };
  std::vector<Choice> choices;
  for (int mask = 0; mask < 16; ++mask) {
    const long j1 = static_cast<long>(found[0].s) - 1 + (mask & 1);
    const long j2 = static_cast<long>(found[1].s) - 1 + ((mask >> 1) & 1);
    const int h1 = H[(found[0].k + ((mask >> 2) & 1)) % H.size()];
    const int h2 = H[(found[1].k + ((mask >> 3) & 1)) % H.size()];
    if (j1 < 0 || j2 >= static_cast<long>(m) || j1 >= j2 || h1 == h2) continue;
    if (!free_b(h1) || !free_b(h2)) continue;
    const double cost = (xy().at(gap[static_cast<size_t>(j1)]) - xy().at(h1)).norm() +
                        (xy().at(gap[static_cast<size_t>(j2)]) - xy().at(h2)).norm();
    choices.push_back({static_cast<size_t>(j1), static_cast<size_t>(j2), h1, h2, cost});
  }
  std::stable_sort(choices.begin(), choices.end(),
                   [](const Choice& p, const Choice& q) { return p.cost < q.cost; });
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
      if (al > 0 && ar > 0 && std::abs(al + ar - whole) <= tol) return {left, right};
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
    const bool even = left.size() % 2 == 0 && right.size() % 2 == 0 &&
                      (arc + static_cast<long>(c.j2 - c.j1)) % 2 == 0;
    if (options_.even_parity && !even) continue;
    chosen = &c;
    break;
  }
  if (!chosen) return false;
  // Project again: the ends to the chosen hole nodes, the middle left as a gap.
  const Choice c = *chosen;
  roll_back(e, fresh, undo);
  Loop p(m, -1);
  auto seam = [&](int v, int h) {
    link(e, v, h);
    r_.seams.push_back({v, h});
    r_.steps.push_back(ImprintStep::Seam);
    return h;
  };
  for (size_t j = 0; j < m; ++j) {
    if (j == c.j1) {
      p[j] = seam(gap[j], c.h1);
    } else if (j == c.j2) {
      p[j] = seam(gap[j], c.h2);
    } else if (j < c.j1 || j > c.j2) {
      p[j] = project(e, gap[j], around, seamed);
    }
  }
  const auto [left, right] = pieces(c, p);
  if (left.empty()) {
    // Seamed otherwise this time: the path as it was, and no step.
    roll_back(e, fresh, undo);
    for (int v : gap) project(e, v, around, seamed);
    return false;
  }
  caps(1 - e)[bi].loops.erase(caps(1 - e)[bi].loops.begin() + static_cast<long>(hole));
  replace(1 - e, bi, {left, right});
  r_.steps.push_back(ImprintStep::Intersect);
  r_.steps.push_back(ImprintStep::Subtract);
  return true;
}

}  // namespace cooperage::cooper::detail
