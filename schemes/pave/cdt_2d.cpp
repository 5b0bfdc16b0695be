#include "schemes/pave/cdt_2d.h"

#include "schemes/pave/cdt_kernel.h"
#include "schemes/pave/frontal_fill.h"
#include "schemes/pave/spatial_order.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <deque>
#include <random>
#include <stdexcept>
#include <unordered_set>
#include <utility>

namespace cooperage::pave::detail {

using cdt::Cdt;
using cdt::edge_key;
using cdt::Tri;
using V2 = Eigen::Vector2d;

Triangulation2D constrained_delaunay(const CdtInput& input) {
  const int n = static_cast<int>(input.points.size());
  if (n < 3) throw std::runtime_error("fewer than 3 loop points");
  Cdt cdt;
  cdt.p = input.points;
  cdt.size = input.sizes;
  Eigen::AlignedBox2d box;
  for (const auto& q : input.points) box.extend(q);
  const V2 c = box.center();
  const double r = std::max(box.sizes().maxCoeff(), 1e-300);
  cdt.p.push_back(c + V2(-20 * r, -20 * r));
  cdt.p.push_back(c + V2(20 * r, -20 * r));
  cdt.p.push_back(c + V2(0, 20 * r));
  cdt.size.resize(cdt.p.size(), r);
  cdt.vt.assign(cdt.p.size(), -1);
  const int super = cdt.new_tri(n, n + 1, n + 2);
  cdt.tri(super).inside = false;

  // Random (but fixed) insertion order avoids the quadratic cavities of
  // collinear runs; a location hint keeps the walks short.
  std::vector<int> order(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) order[static_cast<size_t>(i)] = i;
  std::mt19937 rng(12345u);
  for (size_t i = order.size(); i > 1; --i) {
    std::swap(order[i - 1], order[static_cast<size_t>(rng() % i)]);
  }
  int hint = super;
  for (int i : order) {
    int loc =
        cdt.locate(cdt.pt(i), cdt.tri(hint).alive ? hint : cdt.vt[static_cast<size_t>(n)], false);
    if (loc < 0) throw std::runtime_error("point location failed");
    cdt.tri(loc).inside = false;
    if (!cdt.insert(i, loc, false)) throw std::runtime_error("duplicate or degenerate loop points");
    hint = cdt.created.front();
  }

  std::unordered_set<std::uint64_t> keys;
  for (const auto& loop : input.loops) {
    for (size_t k = 0; k < loop.size(); ++k) {
      keys.insert(edge_key(loop[k], loop[(k + 1) % loop.size()]));
    }
  }
  for (const auto& loop : input.loops) {
    for (size_t k = 0; k < loop.size(); ++k) cdt.recover(loop[k], loop[(k + 1) % loop.size()]);
  }
  cdt.mark_loop_edges(keys);
  for (const auto& loop : input.loops) {
    for (size_t k = 0; k < loop.size(); ++k)
      cdt.mark_constrained(loop[k], loop[(k + 1) % loop.size()]);
  }
  cdt.legalize_all();

  // Inside by parity: crossing a loop edge toggles.
  {
    std::vector<int> state(cdt.t.size(), -1);
    std::vector<int> stack{cdt.vt[static_cast<size_t>(n)]};
    state[static_cast<size_t>(stack.back())] = 0;
    while (!stack.empty()) {
      const int cur = stack.back();
      stack.pop_back();
      const Tri& T = cdt.tri(cur);
      for (size_t i = 0; i < 3; ++i) {
        const int nb = T.n[i];
        if (nb < 0 || state[static_cast<size_t>(nb)] >= 0) continue;
        state[static_cast<size_t>(nb)] = state[static_cast<size_t>(cur)] ^ (T.c[i] ? 1 : 0);
        stack.push_back(nb);
      }
    }
    for (size_t i = 0; i < cdt.t.size(); ++i) {
      Tri& T = cdt.t[i];
      if (!T.alive) continue;
      T.inside = state[i] == 1;
      for (int v : T.v) {
        if (v >= n) T.inside = false;
      }
    }
  }

  if (input.frontal && input.refine) frontal_fill(cdt, input.loops, input.accept_radius);
  for (size_t k = 0; !(input.frontal && input.refine) && k < input.seeds.size(); ++k) {
    const std::vector<int> ring = cdt.inside_triangles_at(input.seed_from[k]);
    if (ring.empty()) continue;
    const int loc = cdt.locate(input.seeds[k], ring.front(), true);
    if (loc < 0 || !cdt.tri(loc).inside) continue;
    const int pi = static_cast<int>(cdt.p.size());
    cdt.p.push_back(input.seeds[k]);
    cdt.size.push_back(input.seed_sizes[k]);
    cdt.vt.push_back(-1);
    if (!cdt.insert(pi, loc, true, 0.6 * input.seed_sizes[k])) {
      cdt.p.pop_back();
      cdt.size.pop_back();
      cdt.vt.pop_back();
    }
  }

  if (input.refine) {
    std::vector<int> queue;
    for (int i = 0; i < static_cast<int>(cdt.t.size()); ++i) {
      if (cdt.tri(i).alive && cdt.tri(i).inside) queue.push_back(i);
    }
    for (size_t head = 0; head < queue.size(); ++head) {
      const int ti = queue[head];
      const Tri& T = cdt.tri(ti);
      if (!T.alive || !T.inside) continue;
      const V2& a = cdt.pt(T.v[0]);
      const V2& b = cdt.pt(T.v[1]);
      const V2& cc = cdt.pt(T.v[2]);
      const V2 ab = b - a, ac = cc - a;
      V2 off;
      if (!cdt::circumcentre_offset(a, b, cc, off)) continue;
      const V2 center = a + off;
      const double R = off.norm();
      const double h = cdt.mean_size(T);
      const double lmin =
          std::sqrt(std::min({ab.squaredNorm(), ac.squaredNorm(), (cc - b).squaredNorm()}));
      // Too big, or fairly big with a short edge (input.max_radius).
      const bool bad =
          R > input.max_radius * h || (R > 0.7 * input.max_radius * h && R > 1.1 * lmin);
      if (!bad) continue;
      const int loc = cdt.locate(center, ti, true);
      if (loc < 0 || !cdt.tri(loc).inside) continue;
      const int pi = static_cast<int>(cdt.p.size());
      cdt.p.push_back(center);
      cdt.size.push_back(h);
      cdt.vt.push_back(-1);
      if (!cdt.insert(pi, loc, true)) {
        cdt.p.pop_back();
        cdt.size.pop_back();
        cdt.vt.pop_back();
        continue;
      }
      queue.insert(queue.end(), cdt.created.begin(), cdt.created.end());
    }
  }

  if (!input.min_triangles.empty()) {
    for (int v = 0; v < n; ++v) {
      for (int attempt = 0; attempt < 3; ++attempt) {
        const std::vector<int> ring = cdt.inside_triangles_at(v);
        if (static_cast<int>(ring.size()) >= input.min_triangles[static_cast<size_t>(v)]) break;
        // The inside triangle at v with the widest angle there.
        int best = -1;
        double widest = -1;
        for (int ti : ring) {
          const Tri& T = cdt.tri(ti);
          size_t i = 0;
          while (T.v[i] != v) ++i;
          const V2 e0 = cdt.pt(T.v[(i + 1) % 3]) - cdt.pt(v),
                   e1 = cdt.pt(T.v[(i + 2) % 3]) - cdt.pt(v);
          const double ang = std::atan2(e0.x() * e1.y() - e0.y() * e1.x(), e0.dot(e1));
          if (ang > widest) {
            widest = ang;
            best = ti;
          }
        }
        if (best < 0) break;
        const Tri T = cdt.tri(best);
        size_t i = 0;
        while (T.v[i] != v) ++i;
        const V2 a = cdt.pt(v), b = cdt.pt(T.v[(i + 1) % 3]), e = cdt.pt(T.v[(i + 2) % 3]);
        // The bisector from a meets be where it divides be in the ratio |ab| : |ae|.
        const double lb = (b - a).norm(), le = (e - a).norm();
        const V2 foot = b + (e - b) * (lb / (lb + le));
        const int pi = static_cast<int>(cdt.p.size());
        cdt.p.push_back(a + 0.5 * (foot - a));
        cdt.size.push_back(cdt.size[static_cast<size_t>(v)]);
        cdt.vt.push_back(-1);
        if (!cdt.insert(pi, best, false)) {
          cdt.p.pop_back();
          cdt.size.pop_back();
          cdt.vt.pop_back();
          break;
        }
      }
    }
  }

  // Output in Hilbert order: Steiner points sorted along the curve (input
  // points keep their indices), triangles by their lowest point (a counting
  // sort), so that the later steps, which walk these arrays by index, touch
  // memory locally.
  Eigen::AlignedBox2d domain;
  for (int i = 0; i < n; ++i) domain.extend(cdt.pt(i));
  const HilbertKeys key(domain);
  const int total = static_cast<int>(cdt.p.size());
  std::vector<std::pair<std::uint64_t, int>> steiner;
  steiner.reserve(static_cast<size_t>(total - n - 3));
  for (int i = n + 3; i < total; ++i) steiner.emplace_back(key(cdt.pt(i)), i);
  std::sort(steiner.begin(), steiner.end());
  std::vector<int> id(static_cast<size_t>(total), -1);
  Triangulation2D out;
  out.points.reserve(static_cast<size_t>(total - 3));
  for (int i = 0; i < n; ++i) {
    id[static_cast<size_t>(i)] = i;
    out.points.push_back(cdt.pt(i));
  }
  for (const auto& [k, i] : steiner) {
    id[static_cast<size_t>(i)] = static_cast<int>(out.points.size());
    out.points.push_back(cdt.pt(i));
  }
  std::vector<int> first(out.points.size() + 1, 0);
  for (const Tri& T : cdt.t) {
    if (!T.alive || !T.inside) continue;
    const int lo = std::min({id[static_cast<size_t>(T.v[0])], id[static_cast<size_t>(T.v[1])],
                             id[static_cast<size_t>(T.v[2])]});
    ++first[static_cast<size_t>(lo) + 1];
  }
  for (size_t i = 0; i + 1 < first.size(); ++i) first[i + 1] += first[i];
  out.tris.resize(static_cast<size_t>(first.back()));
  for (const Tri& T : cdt.t) {
    if (!T.alive || !T.inside) continue;
    std::array<int, 3> v;
    for (size_t k = 0; k < 3; ++k) v[k] = id[static_cast<size_t>(T.v[k])];
    out.tris[static_cast<size_t>(first[static_cast<size_t>(std::min({v[0], v[1], v[2]}))]++)] = v;
  }
  return out;
}

}  // namespace cooperage::pave::detail
