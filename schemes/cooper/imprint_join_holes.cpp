// Subtraction between holes (Blacker 1996, sec. 5.2): a subcap a whose loop
// runs along loops A, B, ... of one opposing subcap t, with a gap from A to
// B, another from B to the next, and the last back to A. Each gap alone
// joins two loops and splits nothing, so all are projected together: t
// loses the piece between them (a's image) and the loops become one. Two
// holes: the top of a plate under a block, with nuts straddling the block's
// edge below (the block's footprint reaches the plate's underside only as
// paths between the nuts' outlines). Three: a blind hole's floor under two
// bosses and beside a through hole, its rim running from one to the next
// (campaign seed 19 case 9). One of the loops may be t's outer loop, which
// then runs round the joined holes: a foot's rim from the block's side to
// a boss's footprint, on to another's and back to the side (seed 37 case 26).
#include "schemes/cooper/imprinter.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace cooperage::cooper::detail {
namespace {

// The nodes of `hole` strictly between positions i and j: forward (i + 1 ...
// j - 1) or backward (i - 1 ... j + 1).
Loop arc(const Loop& hole, size_t i, size_t j, bool forward) {
  Loop out;
  const size_t n = hole.size();
  for (size_t k = forward ? (i + 1) % n : (i + n - 1) % n; k != j;
       k = forward ? (k + 1) % n : (k + n - 1) % n)
    out.push_back(hole[k]);
  return out;
}

}  // namespace

bool Imprinter::join_holes(int e, const Subcap& a, int r0, const Loop& path1, int r1, size_t bi) {
  const int o = 1 - e;
  const Loop& la = a.loops.front();
  const size_t n = la.size();
  const int x1 = *partner(e, r0), y1 = *partner(e, r1);
  // The loop of t through v: a hole, else the outer loop (0), else none.
  constexpr size_t kNone = static_cast<size_t>(-1);
  auto loop_through = [&](int v) {
    const auto& loops = caps(o)[bi].loops;
    for (size_t h = 1; h < loops.size(); ++h) {
      if (index_in(loops[h], v) >= 0) return h;
    }
    return index_in(loops.front(), v) >= 0 ? size_t{0} : kNone;
  };
  const size_t ha = loop_through(x1), hb = loop_through(y1);
  if (ha == kNone || hb == kNone || ha == hb) return false;
  auto on = [&](int v, size_t h) {
    const auto p = partner(e, v);
    return p && index_in(caps(o)[bi].loops[h], *p) >= 0;
  };
  // a's loop after r1, round to r0: a run of nodes ribbed onto one loop, a
  // gap (perhaps empty: the partners of its ends are not adjacent), a run on
  // the next loop, ... and last a run on A up to r0. Each loop once; every
  // run at least two nodes (a run of one touches its loop at a node).
  std::vector<size_t> holes{hb};
  std::vector<int> into{y1}, out_of;  // per hole: where the piece's loop arrives and leaves
  std::vector<Loop> gaps;
  const size_t k0 = static_cast<size_t>(index_in(la, r0));
  size_t k = (static_cast<size_t>(index_in(la, r1)) + 1) % n;
  int entry = r1;
  for (;;) {
    const size_t h = holes.back();
    while (k != k0 && on(la[k], h)) k = (k + 1) % n;
    const int exit = la[(k + n - 1) % n];
    if (exit == entry) return false;
    out_of.push_back(*partner(e, exit));
    Loop gap;
    while (k != k0 && !partner(e, la[k])) {
      gap.push_back(la[k]);
      k = (k + 1) % n;
    }
    gaps.push_back(std::move(gap));
    entry = la[k];
    const size_t next = loop_through(*partner(e, entry));
    if (next == ha) break;
    if (next == kNone || k == k0 || std::count(holes.begin(), holes.end(), next) > 0) return false;
    holes.push_back(next);
    into.push_back(*partner(e, entry));
  }
  // The last run, on A, up to r0.
  if (entry == r0) return false;
  for (size_t m = k; m != k0; m = (m + 1) % n) {
    if (!on(la[m], ha)) return false;  // a reaches a hole twice or another cap
  }
  holes.push_back(ha);
  into.push_back(*partner(e, entry));
  out_of.push_back(x1);
  const size_t count = holes.size();
  if (count > 8) return false;  // 2^count arc choices below
  Subcap& t = caps(o)[bi];
  const bool through_outer = std::count(holes.begin(), holes.end(), size_t{0}) > 0;
  // Per loop j: its two arcs between where the piece arrives and leaves.
  std::vector<std::array<Loop, 2>> arcs(count);
  for (size_t j = 0; j < count; ++j) {
    const Loop& hole = t.loops[holes[j]];
    const size_t i_in = static_cast<size_t>(index_in(hole, into[j]));
    const size_t i_out = static_cast<size_t>(index_in(hole, out_of[j]));
    if (i_in == i_out) return false;
    arcs[j] = {arc(hole, i_in, i_out, true), arc(hole, i_in, i_out, false)};
  }
  // The gaps after the first, projected (path1 is).
  const int first_new = next_node_;
  std::vector<Loop> paths{path1};
  for (size_t j = 0; j + 1 < count; ++j) {
    Loop path;
    for (int v : gaps[j]) path.push_back(project(e, v, la));
    paths.push_back(std::move(path));
  }
  // x1 -> path1 -> (B: arrive, arc, leave) -> path2 -> ... -> (A: arrive, arc) -> x1.
  auto loop_of = [&](unsigned choice, bool flip) {
    Loop out{x1};
    out.insert(out.end(), paths[0].begin(), paths[0].end());
    for (size_t j = 0; j < count; ++j) {
      const bool which = ((choice >> j) & 1u) != 0;
      const Loop& arc_j = arcs[j][(which != flip) ? 1 : 0];
      out.push_back(into[j]);
      out.insert(out.end(), arc_j.begin(), arc_j.end());
      if (j + 1 < count) {
        out.push_back(out_of[j]);
        out.insert(out.end(), paths[j + 1].begin(), paths[j + 1].end());
      }
    }
    return out;
  };
  auto encloses = [&](const Loop& c, const Loop& other) {
    return !other.empty() && point_in_loop(xy().at(other[other.size() / 2]), c, xy());
  };
  // Through the outer loop the two loops split t's area less the joined
  // holes' (the joined loop is t's new outer loop); a choice whose loops
  // cross themselves or each other does not add up.
  auto splits_t = [&](const Loop& piece, const Loop& joined) {
    double holes_area = 0;
    for (size_t h : holes) holes_area += h == 0 ? 0.0 : std::abs(signed_area(t.loops[h], xy()));
    const double whole = std::abs(signed_area(t.loops.front(), xy()));
    const double parts = std::abs(signed_area(piece, xy())) + std::abs(signed_area(joined, xy()));
    return std::abs(parts - (whole - holes_area)) <= 1e-9 * whole;
  };
  // The piece takes the arc of each loop facing the others: it encloses
  // none of the arcs it leaves to the joined loop.
  for (unsigned choice = 0; choice < (1u << count); ++choice) {
    Loop piece = loop_of(choice, false);
    bool clear = true;
    for (size_t j = 0; j < count && clear; ++j) {
      const bool which = ((choice >> j) & 1u) != 0;
      clear = !encloses(piece, arcs[j][which ? 0 : 1]);
    }
    if (!clear) continue;
    Loop joined = loop_of(choice, true);
    if (through_outer && !splits_t(piece, joined)) continue;
    if (signed_area(piece, xy()) < 0) std::reverse(piece.begin(), piece.end());
    // The joined loop is a hole of t, or its outer loop when the outer took part.
    if ((signed_area(joined, xy()) > 0) == !through_outer)
      std::reverse(joined.begin(), joined.end());
    // t's other holes inside the piece (a nut wholly under the block) go with it.
    std::vector<Loop> kept{through_outer ? joined : t.loops.front()}, inner{piece};
    if (!through_outer) kept.push_back(joined);
    for (size_t h = 1; h < t.loops.size(); ++h) {
      if (std::count(holes.begin(), holes.end(), h) > 0) continue;
      const Loop& hole = t.loops[h];
      bool in = true;
      for (int v : hole)
        in = in && (index_in(piece, v) >= 0 || point_in_loop(xy().at(v), piece, xy()));
      (in ? inner : kept).push_back(hole);
    }
    t.loops = std::move(kept);
    new_cap(o, std::move(inner), t.id);
    r_.steps.push_back(ImprintStep::Subtract);
    return true;
  }
  // No piece: the later gaps' ribs go (path1's are the caller's to undo).
  for (size_t j = 0; j + 1 < count; ++j) {
    for (int v : gaps[j]) {
      const auto p = partner(e, v);
      if (!p) continue;
      partner_[e].erase(v);
      partner_[o].erase(*p);
      if (*p >= first_new) r_.ends.xy.erase(*p);
    }
  }
  return false;
}

}  // namespace cooperage::cooper::detail
