// Subtraction between two holes (Blacker 1996, sec. 5.2): a subcap a whose
// loop runs along two holes A and B of one opposing subcap t, with a gap
// from A to B and another back from B to A. Either gap alone joins two
// holes and splits nothing, so both are projected together: t loses the
// piece between them (a's image) and A and B become one hole. This is the
// top of a plate under a block, with nuts straddling the block's edge below:
// the block's footprint reaches the plate's underside only as paths between
// the nuts' outlines.
#include "schemes/cooper/imprinter.h"

#include <algorithm>

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

Loop chain(std::initializer_list<const Loop*> parts) {
  Loop out;
  for (const Loop* p : parts) out.insert(out.end(), p->begin(), p->end());
  return out;
}

}  // namespace

bool Imprinter::join_holes(int e, const Subcap& a, int r0, const Loop& path1, int r1, size_t bi) {
  const int o = 1 - e;
  const Loop& la = a.loops.front();
  const size_t n = la.size();
  const int x1 = *partner(e, r0), y1 = *partner(e, r1);
  auto hole_of = [&](int v) {
    const auto& loops = caps(o)[bi].loops;
    for (size_t h = 1; h < loops.size(); ++h) {
      if (index_in(loops[h], v) >= 0) return h;
    }
    return size_t{0};
  };
  const size_t ha = hole_of(x1), hb = hole_of(y1);
  if (ha == 0 || hb == 0 || ha == hb) return false;
  // a's loop after r1: nodes ribbed onto B, a gap, nodes ribbed onto A up to r0.
  auto on = [&](int v, size_t h) {
    const auto p = partner(e, v);
    return p && index_in(caps(o)[bi].loops[h], *p) >= 0;
  };
  size_t k = (static_cast<size_t>(index_in(la, r1)) + 1) % n;
  const size_t k0 = static_cast<size_t>(index_in(la, r0));
  while (k != k0 && on(la[k], hb)) k = (k + 1) % n;
  const int r2 = la[(k + n - 1) % n];
  Loop gap2;
  while (k != k0 && !partner(e, la[k])) {
    gap2.push_back(la[k]);
    k = (k + 1) % n;
  }
  const int r3 = la[k];
  for (size_t m = k; m != k0; m = (m + 1) % n) {
    if (!on(la[m], ha)) return false;  // a reaches a third hole or cap
  }
  if (r2 == r1 || r3 == r0 || !on(r3, ha)) return false;  // touching at one node
  Loop path2;
  for (int v : gap2) path2.push_back(project(e, v, la));
  const int x2 = *partner(e, r2), y2 = *partner(e, r3);
  Subcap& t = caps(o)[bi];
  const Loop A = t.loops[ha], B = t.loops[hb];
  const size_t ix1 = static_cast<size_t>(index_in(A, x1)),
               iy2 = static_cast<size_t>(index_in(A, y2));
  const size_t iy1 = static_cast<size_t>(index_in(B, y1)),
               ix2 = static_cast<size_t>(index_in(B, x2));
  if (ix1 == iy2 || iy1 == ix2) return false;
  // The piece takes the arc of each hole facing the other hole: it encloses
  // neither of the arcs it leaves to the joined hole.
  const Loop a_arcs[2] = {arc(A, iy2, ix1, true), arc(A, iy2, ix1, false)};
  const Loop b_arcs[2] = {arc(B, iy1, ix2, true), arc(B, iy1, ix2, false)};
  const Loop head{x1}, mid{y1}, tail{x2}, end{y2};
  auto loop_of = [&](int ia, int ib) {
    return chain({&head, &path1, &mid, &b_arcs[ib], &tail, &path2, &end, &a_arcs[ia]});
  };
  auto encloses = [&](const Loop& c, const Loop& other) {
    return !other.empty() && point_in_loop(xy().at(other[other.size() / 2]), c, xy());
  };
  for (int ia = 0; ia < 2; ++ia) {
    for (int ib = 0; ib < 2; ++ib) {
      Loop piece = loop_of(ia, ib);
      if (encloses(piece, a_arcs[1 - ia]) || encloses(piece, b_arcs[1 - ib])) continue;
      Loop joined = loop_of(1 - ia, 1 - ib);
      if (signed_area(piece, xy()) < 0) std::reverse(piece.begin(), piece.end());
      if (signed_area(joined, xy()) > 0) std::reverse(joined.begin(), joined.end());
      // t's other holes inside the piece (a nut wholly under the block) go with it.
      std::vector<Loop> kept{t.loops.front(), joined}, inner{piece};
      for (size_t h = 1; h < t.loops.size(); ++h) {
        if (h == ha || h == hb) continue;
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
  }
  return false;
}

}  // namespace cooperage::cooper::detail
