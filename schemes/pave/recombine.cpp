#include "schemes/pave/recombine.h"

#include "schemes/pave/quad_quality_2d.h"

#include <algorithm>
#include <cstdint>

namespace cooperage::pave::detail {
namespace {
/// Smallest scaled Jacobian of the quad a boundary triangle may move into.
constexpr double kMigrateQuality = 0.5;
}  // namespace

std::vector<Cell> recombine(const Triangulation2D& tri, double min_quality,
                            const std::vector<int>& min_cells) {
  const auto& P = tri.points;
  const auto& T = tri.tris;
  // Directed edge (a -> b) -> triangle and the index of a, as rows by a
  // (compressed; a hash map here thrashes the cache on large meshes). Within
  // a row the half-edges keep the triangle order, so a lookup finds the
  // first one, as an emplace-only map would.
  struct Half {
    int b, t, i;
  };
  std::vector<int> half_start(P.size() + 1, 0);
  for (const auto& v : T) {
    for (int x : v) ++half_start[static_cast<size_t>(x) + 1];
  }
  for (size_t x = 0; x < P.size(); ++x) half_start[x + 1] += half_start[x];
  std::vector<Half> half(static_cast<size_t>(half_start[P.size()]));
  {
    std::vector<int> fill(half_start.begin(), half_start.end() - 1);
    for (int t = 0; t < static_cast<int>(T.size()); ++t) {
      const auto& v = T[static_cast<size_t>(t)];
      for (int i = 0; i < 3; ++i) {
        half[static_cast<size_t>(fill[static_cast<size_t>(v[static_cast<size_t>(i)])]++)] =
            Half{v[static_cast<size_t>((i + 1) % 3)], t, i};
      }
    }
  }
  auto find_half = [&](int a, int b) -> const Half* {
    for (int k = half_start[static_cast<size_t>(a)]; k < half_start[static_cast<size_t>(a) + 1];
         ++k) {
      if (half[static_cast<size_t>(k)].b == b) return &half[static_cast<size_t>(k)];
    }
    return nullptr;
  };
  struct Candidate {
    double score;
    int t, s;
    Cell quad;
  };
  std::vector<Candidate> cands;
  for (int t = 0; t < static_cast<int>(T.size()); ++t) {
    const auto& v = T[static_cast<size_t>(t)];
    for (size_t i = 0; i < 3; ++i) {
      const int a = v[i], b = v[(i + 1) % 3], c = v[(i + 2) % 3];
      const Half* it = find_half(b, a);
      if (it == nullptr || it->t < t) continue;  // boundary, or seen
      const int s = it->t;
      const auto& w = T[static_cast<size_t>(s)];
      const int d = w[static_cast<size_t>((it->i + 2) % 3)];
      // Triangles (a, b, c) and (b, a, d) form the quad (a, d, b, c).
      const Cell q{a, d, b, c};
      const double sj = scaled_jacobian_2d(P, q);
      if (sj < min_quality) continue;
      cands.push_back({sj, t, s, q});
    }
  }
  std::stable_sort(cands.begin(), cands.end(),
                   [](const Candidate& x, const Candidate& y) { return x.score > y.score; });
  std::vector<int> cells_at(P.size(), 0);
  for (const auto& v : T) {
    for (int x : v) ++cells_at[static_cast<size_t>(x)];
  }
  auto floor_of = [&](int x) {
    return static_cast<size_t>(x) < min_cells.size() ? min_cells[static_cast<size_t>(x)] : 0;
  };
  // match[t]: the candidate pairing triangle t, or -1.
  std::vector<int> match(T.size(), -1);
  auto can_merge = [&](const Candidate& c) {
    const int x = c.quad[0], y = c.quad[2];  // the shared edge: both lose a cell
    return cells_at[static_cast<size_t>(x)] - 1 >= floor_of(x) &&
           cells_at[static_cast<size_t>(y)] - 1 >= floor_of(y);
  };
  auto merge = [&](int k, int sign) {
    const Candidate& c = cands[static_cast<size_t>(k)];
    cells_at[static_cast<size_t>(c.quad[0])] -= sign;
    cells_at[static_cast<size_t>(c.quad[2])] -= sign;
    match[static_cast<size_t>(c.t)] = match[static_cast<size_t>(c.s)] = sign > 0 ? k : -1;
  };
  for (int k = 0; k < static_cast<int>(cands.size()); ++k) {
    const Candidate& c = cands[static_cast<size_t>(k)];
    if (match[static_cast<size_t>(c.t)] >= 0 || match[static_cast<size_t>(c.s)] >= 0 ||
        !can_merge(c))
      continue;
    merge(k, +1);
  }
  // Augmenting paths of length 3: a free triangle t next to s, whose partner
  // s' has a free neighbour u, becomes (t, s) + (s', u): one more quad.
  // of(t): the candidates holding triangle t, in candidate order (compressed rows).
  std::vector<int> of_start(T.size() + 1, 0);
  for (const Candidate& c : cands) {
    ++of_start[static_cast<size_t>(c.t) + 1];
    ++of_start[static_cast<size_t>(c.s) + 1];
  }
  for (size_t t = 0; t < T.size(); ++t) of_start[t + 1] += of_start[t];
  std::vector<int> of_items(static_cast<size_t>(of_start[T.size()]));
  {
    std::vector<int> fill(of_start.begin(), of_start.end() - 1);
    for (int k = 0; k < static_cast<int>(cands.size()); ++k) {
      of_items[static_cast<size_t>(fill[static_cast<size_t>(cands[static_cast<size_t>(k)].t)]++)] =
          k;
      of_items[static_cast<size_t>(fill[static_cast<size_t>(cands[static_cast<size_t>(k)].s)]++)] =
          k;
    }
  }
  struct Row {
    const int* b;
    const int* e;
    const int* begin() const { return b; }
    const int* end() const { return e; }
  };
  auto of = [&](int t) {
    return Row{of_items.data() + of_start[static_cast<size_t>(t)],
               of_items.data() + of_start[static_cast<size_t>(t) + 1]};
  };
  auto other = [&](int k, int t) {
    const Candidate& c = cands[static_cast<size_t>(k)];
    return c.t == t ? c.s : c.t;
  };
  auto augment = [&]() {
    for (int pass = 0; pass < 6; ++pass) {
      bool changed = false;
      for (int t = 0; t < static_cast<int>(T.size()); ++t) {
        if (match[static_cast<size_t>(t)] >= 0) continue;
        bool done = false;
        for (int kts : of(t)) {
          const int s2 = other(kts, t);
          const int kss = match[static_cast<size_t>(s2)];
          if (kss < 0) continue;  // s2 free too: cannot happen after greedy unless blocked
          const int sp = other(kss, s2);
          for (int ku : of(sp)) {
            const int u = other(ku, sp);
            if (u == t || u == s2 || match[static_cast<size_t>(u)] >= 0) continue;
            merge(kss, -1);
            if (can_merge(cands[static_cast<size_t>(kts)])) {
              merge(kts, +1);
              if (can_merge(cands[static_cast<size_t>(ku)])) {
                merge(ku, +1);
                done = true;
                break;
              }
              merge(kts, -1);
            }
            merge(kss, +1);
          }
          if (done) break;
        }
        changed = changed || done;
      }
      if (!changed) break;
    }
  };
  augment();
  // A triangle left on the boundary spoils the boundary row (its split puts
  // a valence-3 node next to the loop): it trades places with the partner
  // of a neighbour that lies off the boundary, when the new quad is fair.
  // Points with a min_cells entry are the loop points.
  const int loop_points = static_cast<int>(min_cells.size());
  auto on_boundary = [&](int t) {
    for (int x : T[static_cast<size_t>(t)]) {
      if (x < loop_points) return true;
    }
    return false;
  };
  bool moved = false;
  for (int t = 0; t < static_cast<int>(T.size()); ++t) {
    if (match[static_cast<size_t>(t)] >= 0 || !on_boundary(t)) continue;
    int best_kts = -1, best_kss = -1;
    for (int kts : of(t)) {
      const Candidate& c = cands[static_cast<size_t>(kts)];
      if (c.score < kMigrateQuality) continue;
      const int s2 = other(kts, t);
      const int kss = match[static_cast<size_t>(s2)];
      if (kss < 0 || on_boundary(other(kss, s2))) continue;
      if (best_kts < 0 || c.score > cands[static_cast<size_t>(best_kts)].score) {
        best_kts = kts;
        best_kss = kss;
      }
    }
    if (best_kts < 0) continue;
    merge(best_kss, -1);
    if (can_merge(cands[static_cast<size_t>(best_kts)])) {
      merge(best_kts, +1);
      moved = true;
    } else {
      merge(best_kss, +1);
    }
  }
  if (moved) augment();
  std::vector<Cell> cells;
  cells.reserve(T.size());
  for (int t = 0; t < static_cast<int>(T.size()); ++t) {
    const int k = match[static_cast<size_t>(t)];
    if (k < 0) {
      cells.push_back({T[static_cast<size_t>(t)][0], T[static_cast<size_t>(t)][1],
                       T[static_cast<size_t>(t)][2], -1});
    } else if (cands[static_cast<size_t>(k)].t == t) {
      cells.push_back(cands[static_cast<size_t>(k)].quad);
    }
  }
  return cells;
}

}  // namespace cooperage::pave::detail
