// A gap whose image leaves the opposing subcap it starts and ends in and
// comes back (Blacker 1996, sec. 5.3): a boss's rim, projected onto a
// bottom from the hole floor's rim it starts on, bulges across a foot's
// rim and back (campaign seed 11 case 93). Subtracted from the bottom
// alone, the boss's piece took in the lens over the foot, its loop crossed
// the foot's rim, and meshing the bottom's piece failed at every size. The
// two crossings are combined onto nodes of both loops, as for a free loop
// crossing an opposing boundary (free_crossing): the gap becomes three, each
// inside one opposing subcap, and the lens is cut out of the foot's subcap.
#include "schemes/cooper/imprinter.h"

#include <limits>

namespace cooperage::cooper::detail {

bool Imprinter::gap_crossing(int e, const Subcap& a, int x, const Loop& gap, int y, size_t bi) {
  const int o = 1 - e;
  const Subcap& b = caps(o)[bi];
  Loop chain{x};
  chain.insert(chain.end(), gap.begin(), gap.end());
  chain.push_back(y);
  struct Crossing {
    size_t i;  // chain segment chain[i] - chain[i + 1]
    size_t l;  // b's loop
    size_t k;  // its edge lb[k] - lb[k + 1]
  };
  std::vector<Crossing> found;
  for (size_t i = 0; i + 1 < chain.size(); ++i) {
    for (size_t l = 0; l < b.loops.size(); ++l) {
      const Loop& lb = b.loops[l];
      for (size_t k = 0; k < lb.size(); ++k) {
        const int q0 = lb[k], q1 = lb[(k + 1) % lb.size()];
        // Segments sharing a node meet there, they do not cross.
        if (q0 == chain[i] || q0 == chain[i + 1] || q1 == chain[i] || q1 == chain[i + 1]) continue;
        if (segment_hit(xy().at(chain[i]), xy().at(chain[i + 1]), xy().at(q0), xy().at(q1)))
          found.push_back({i, l, k});
      }
    }
  }
  // From a hole of b out across b's outer loop and back (other shapes are
  // the other steps').
  if (found.size() != 2 || found[0].l != 0 || found[1].l != 0) return false;
  bool on_a_hole = false;
  for (size_t h = 1; h < b.loops.size(); ++h)
    on_a_hole = on_a_hole || (index_in(b.loops[h], x) >= 0 && index_in(b.loops[h], y) >= 0);
  if (!on_a_hole) return false;
  const Loop& lb = b.loops[found[0].l];
  const Loop* la = nullptr;
  for (const Loop& l : a.loops) {
    if (index_in(l, gap.front()) >= 0) la = &l;
  }
  if (!la) return false;
  auto edges = [](const Loop& l, int from, int to) {
    const long n = static_cast<long>(l.size());
    return ((index_in(l, to) - index_in(l, from)) % n + n) % n;
  };
  // The gap's nodes beside each crossing (x and y have their ribs), b's
  // free nodes beside it; of the 16 choices, those keeping the lens even
  // (the arcs between the two links, one on each loop, sum to an even
  // count: free_crossing), the shortest links.
  auto a_side = [&](const Crossing& c, int m) {
    const size_t j = c.i + static_cast<size_t>(m);
    return j >= 1 && j <= gap.size() ? chain[j] : -1;
  };
  const auto free_b = [&](int v) { return !partner(o, v).has_value() && !exterior_.count(v); };
  // Every arc between two links even on both loops (then every piece is,
  // free_crossing) where the gap's own arc allows it; else the lens alone.
  const size_t na = la->size();
  const int r0 = (*la)[(static_cast<size_t>(index_in(*la, gap.front())) + na - 1) % na];
  const int r1 = (*la)[(static_cast<size_t>(index_in(*la, gap.back())) + 1) % na];
  auto arcs_even_on_b = [&](int v0, int v1) {
    std::vector<long> at;  // positions of b's linked nodes, the new two among them
    for (size_t k = 0; k < lb.size(); ++k) {
      if (partner(o, lb[k]) || lb[k] == v0 || lb[k] == v1) at.push_back(static_cast<long>(k));
    }
    for (size_t k = 0; k < at.size(); ++k) {
      const long from = at[k], to = at[(k + 1) % at.size()];
      const int p = lb[static_cast<size_t>(from)], q = lb[static_cast<size_t>(to)];
      if (p != v0 && p != v1 && q != v0 && q != v1) continue;  // an arc this leaves alone
      if (edges(lb, p, q) % 2 != 0) return false;
    }
    return true;
  };
  int a0 = -1, a1 = -1, b0 = -1, b1 = -1;
  double best = std::numeric_limits<double>::infinity();
  bool best_strong = false;
  for (int m = 0; m < 16; ++m) {
    const int u0 = a_side(found[0], m & 1), u1 = a_side(found[1], (m >> 1) & 1);
    const int v0 = lb[(found[0].k + ((m >> 2) & 1)) % lb.size()];
    const int v1 = lb[(found[1].k + ((m >> 3) & 1)) % lb.size()];
    if (u0 < 0 || u1 < 0 || u0 == u1 || v0 == v1 || !free_b(v0) || !free_b(v1)) continue;
    if (options_.even_parity && (edges(*la, u0, u1) + edges(lb, v1, v0)) % 2 != 0) continue;
    const bool strong = options_.even_parity && edges(*la, r0, u0) % 2 == 0 &&
                        edges(*la, u1, r1) % 2 == 0 && arcs_even_on_b(v0, v1);
    const double cost = (xy().at(u0) - xy().at(v0)).norm() + (xy().at(u1) - xy().at(v1)).norm();
    if (best_strong && !strong) continue;
    if (!(cost < best) && strong == best_strong) continue;
    best_strong = strong;
    best = cost;
    a0 = u0;
    a1 = u1;
    b0 = v0;
    b1 = v1;
  }
  if (a0 < 0) return false;
  for (const auto& [u, v] : {std::make_pair(a0, b0), std::make_pair(a1, b1)}) {
    link(e, u, v);
    r_.seams.push_back({u, v});
    r_.steps.push_back(ImprintStep::Seam);
  }
  r_.steps.push_back(ImprintStep::Intersect);
  return true;
}

}  // namespace cooperage::cooper::detail
