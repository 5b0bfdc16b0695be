// The working triangulation of cdt_2d.cpp: triangles with neighbours and
// loop-edge flags, point location by visibility walk, Bowyer-Watson
// insertion with a cavity that never crosses loop edges, edge flips, and
// Sloan's loop-edge recovery. Internal to the pave scheme (cdt_2d.h is the
// interface).
#pragma once

#include "framework/mesh2d/predicates.h"

#include <Eigen/Core>

#include <algorithm>

#include <array>
#include <cstdint>
#include <deque>
#include <stdexcept>
#include <unordered_set>
#include <utility>
#include <vector>

namespace cooperage::pave::detail::cdt {

using V2 = Eigen::Vector2d;

// The predicates are framework/mesh2d's (exact signs, Shewchuk's adaptive
// arithmetic): pave's own plain-double versions gave wrong signs on nearly
// collinear fronts (issue 16 item 2, "one robust 2D layer").
inline double orient(const V2& a, const V2& b, const V2& c) { return mesh2d::orient2d(a, b, c); }

/// > 0 when d lies inside the circumcircle of the counter-clockwise a, b, c.
inline double incircle(const V2& a, const V2& b, const V2& c, const V2& d) {
  return mesh2d::incircle(a, b, c, d);
}

/// Offset from a to the circumcentre of the counter-clockwise a, b, c; false
/// for a degenerate or clockwise triangle.
inline bool circumcentre_offset(const V2& a, const V2& b, const V2& c, V2& offset) {
  const V2 ab = b - a, ac = c - a;
  const double d = 2.0 * (ab.x() * ac.y() - ab.y() * ac.x());
  if (!(d > 0)) return false;
  offset = V2(ac.y() * ab.squaredNorm() - ab.y() * ac.squaredNorm(),
              ab.x() * ac.squaredNorm() - ac.x() * ab.squaredNorm()) /
           d;
  return true;
}

inline std::uint64_t edge_key(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) |
         static_cast<std::uint32_t>(b);
}

struct Tri {
  std::array<int, 3> v{};                      // counter-clockwise
  std::array<int, 3> n{-1, -1, -1};            // neighbour across the edge opposite v[i]
  std::array<bool, 3> c{false, false, false};  // that edge is a loop edge
  bool alive = true;
  bool inside = true;
};

struct BoundaryEdge {
  int a, b, nb;
  bool constrained;
};

class Cdt {
 public:
  std::vector<V2> p;
  std::vector<double> size;
  std::vector<Tri> t;
  std::vector<int> vt;  // a triangle of each vertex
  std::vector<int> free_slots;
  std::vector<int> mark;
  int stamp = 0;
  std::vector<int> created;  // triangles made by the last insert()

  int new_tri(int a, int b, int c) {
    int id;
    if (!free_slots.empty()) {
      id = free_slots.back();
      free_slots.pop_back();
      t[static_cast<size_t>(id)] = Tri{};
    } else {
      id = static_cast<int>(t.size());
      t.emplace_back();
      mark.push_back(0);
    }
    Tri& T = tri(id);
    T.v = {a, b, c};
    vt[static_cast<size_t>(a)] = vt[static_cast<size_t>(b)] = vt[static_cast<size_t>(c)] = id;
    return id;
  }
  Tri& tri(int i) { return t[static_cast<size_t>(i)]; }
  /// Mean target size at the corners of T.
  double mean_size(const Tri& T) const {
    return (size[static_cast<size_t>(T.v[0])] + size[static_cast<size_t>(T.v[1])] +
            size[static_cast<size_t>(T.v[2])]) /
           3.0;
  }
  const V2& pt(int i) const { return p[static_cast<size_t>(i)]; }

  /// Sets the neighbour of triangle nb across its edge {a, b} to neu.
  void relink(int nb, int a, int b, int neu) {
    if (nb < 0) return;
    Tri& N = tri(nb);
    for (int k = 0; k < 3; ++k) {
      const int x = N.v[static_cast<size_t>((k + 1) % 3)],
                y = N.v[static_cast<size_t>((k + 2) % 3)];
      if ((x == a && y == b) || (x == b && y == a)) {
        N.n[static_cast<size_t>(k)] = neu;
        return;
      }
    }
  }

  /// Visibility walk from `start` to the triangle containing q; -1 when the
  /// walk leaves the triangulation or (stop_at_loop) crosses a loop edge.
  int locate(const V2& q, int start, bool stop_at_loop) {
    int cur = start;
    unsigned rot = 0;
    const int limit = 4 * static_cast<int>(t.size()) + 100;
    for (int step = 0; step < limit; ++step) {
      const Tri& T = tri(cur);
      int moved = -1;
      for (unsigned k = 0; k < 3; ++k) {
        const size_t i = (k + rot) % 3;
        if (orient(pt(T.v[(i + 1) % 3]), pt(T.v[(i + 2) % 3]), q) < 0) {
          moved = static_cast<int>(i);
          break;
        }
      }
      ++rot;
      if (moved < 0) return cur;
      if (stop_at_loop && T.c[static_cast<size_t>(moved)]) return -1;
      cur = T.n[static_cast<size_t>(moved)];
      if (cur < 0) return -1;
    }
    return -1;
  }

  /// Bowyer-Watson insertion of point pi, which lies in triangle t0; the
  /// cavity never crosses loop edges. With `guard_loops`, a point inside the
  /// diametral circle of a loop edge on the cavity boundary is refused.
  bool insert(int pi, int t0, bool guard_loops, double min_distance = 0.0) {
    const V2 q = pt(pi);
    ++stamp;
    std::vector<int> cavity{t0};
    mark[static_cast<size_t>(t0)] = stamp;
    for (size_t k = 0; k < cavity.size(); ++k) {
      const Tri& T = tri(cavity[k]);
      for (size_t i = 0; i < 3; ++i) {
        const int nb = T.n[i];
        if (nb < 0 || T.c[i] || mark[static_cast<size_t>(nb)] == stamp) continue;
        const Tri& N = tri(nb);
        if (N.inside != T.inside) continue;
        if (incircle(pt(N.v[0]), pt(N.v[1]), pt(N.v[2]), q) > 0) {
          mark[static_cast<size_t>(nb)] = stamp;
          cavity.push_back(nb);
        }
      }
    }
    // Shrink the cavity until it is star-shaped from q (rounding can break it).
    std::vector<BoundaryEdge> boundary;
    for (int round = 0;; ++round) {
      boundary.clear();
      int bad = -1;
      for (int c : cavity) {
        if (mark[static_cast<size_t>(c)] != stamp) continue;
        const Tri& T = tri(c);
        for (size_t i = 0; i < 3; ++i) {
          const int nb = T.n[i];
          if (nb >= 0 && mark[static_cast<size_t>(nb)] == stamp) continue;
          const int a = T.v[(i + 1) % 3], b = T.v[(i + 2) % 3];
          if (orient(pt(a), pt(b), q) <= 0 && bad < 0) bad = c;
          if (guard_loops && T.c[i] && (pt(a) - q).dot(pt(b) - q) <= 0) return false;
          if ((pt(a) - q).squaredNorm() < min_distance * min_distance) return false;
          boundary.push_back({a, b, nb, T.c[i]});
        }
      }
      if (bad < 0) break;
      if (bad == t0 || round > 50) {
        for (int c : cavity) mark[static_cast<size_t>(c)] = 0;
        return false;
      }
      mark[static_cast<size_t>(bad)] = 0;
    }
    const bool inside = tri(t0).inside;
    for (int c : cavity) {
      if (mark[static_cast<size_t>(c)] != stamp) continue;
      tri(c).alive = false;
      free_slots.push_back(c);
    }
    created.clear();
    for (const BoundaryEdge& e : boundary) {
      const int id = new_tri(pi, e.a, e.b);
      Tri& T = tri(id);
      T.n[0] = e.nb;
      T.c[0] = e.constrained;
      T.inside = inside;
      relink(e.nb, e.a, e.b, id);
      created.push_back(id);
    }
    // Link the fan: edge (b_k, q) of triangle k meets edge (q, a_j) with a_j == b_k.
    for (size_t k = 0; k < created.size(); ++k) {
      for (size_t j = 0; j < created.size(); ++j) {
        if (boundary[j].a == boundary[k].b) {
          tri(created[k]).n[1] = created[j];
          tri(created[j]).n[2] = created[k];
        }
      }
    }
    // The cavity triangles are recycled: clear their marks for later stamps.
    for (int c : cavity) mark[static_cast<size_t>(c)] = 0;
    return true;
  }

  /// Flips the edge opposite v[i] of triangle ti when the result is valid.
  bool flip(int ti, int i) {
    Tri T = tri(ti);
    const size_t ui = static_cast<size_t>(i);
    const int x = T.v[ui], u = T.v[(ui + 1) % 3], w = T.v[(ui + 2) % 3];
    const int si = T.n[ui];
    if (si < 0 || T.c[ui]) return false;
    Tri S = tri(si);
    size_t j = 0;
    while (j < 3 && (S.v[j] == u || S.v[j] == w)) ++j;
    if (j == 3) return false;
    const int y = S.v[j];
    if (S.v[(j + 1) % 3] != w) return false;  // inconsistent orientation
    if (orient(pt(x), pt(u), pt(y)) <= 0 || orient(pt(y), pt(w), pt(x)) <= 0) return false;
    const int n_wx = T.n[(ui + 1) % 3], n_xu = T.n[(ui + 2) % 3];
    const bool c_wx = T.c[(ui + 1) % 3], c_xu = T.c[(ui + 2) % 3];
    const int n_uy = S.n[(j + 1) % 3], n_yw = S.n[(j + 2) % 3];
    const bool c_uy = S.c[(j + 1) % 3], c_yw = S.c[(j + 2) % 3];
    Tri& A = tri(ti);
    A.v = {x, u, y};
    A.n = {n_uy, si, n_xu};
    A.c = {c_uy, false, c_xu};
    Tri& B = tri(si);
    B.v = {y, w, x};
    B.n = {n_wx, ti, n_yw};
    B.c = {c_wx, false, c_yw};
    B.inside = A.inside;
    relink(n_uy, u, y, ti);
    relink(n_wx, w, x, si);
    vt[static_cast<size_t>(x)] = vt[static_cast<size_t>(u)] = vt[static_cast<size_t>(y)] = ti;
    vt[static_cast<size_t>(w)] = si;
    return true;
  }

  /// Triangle holding the directed edge u -> v (index of u in `at`), or -1.
  int find_edge(int u, int v, int& at) {
    const int start = vt[static_cast<size_t>(u)];
    for (int dir = 0; dir < 2; ++dir) {
      int cur = start;
      for (int guard = 0; cur >= 0 && guard < 10000; ++guard) {
        const Tri& T = tri(cur);
        size_t i = 0;
        while (i < 3 && T.v[i] != u) ++i;
        if (i == 3) return -1;
        if (T.v[(i + 1) % 3] == v) {
          at = static_cast<int>(i);
          return cur;
        }
        cur = dir == 0 ? T.n[(i + 1) % 3] : T.n[(i + 2) % 3];
        if (cur == start) break;
      }
    }
    return -1;
  }

  /// The inside triangles having vertex v (a full turn around v).
  std::vector<int> inside_triangles_at(int v) {
    std::vector<int> out;
    const int start = vt[static_cast<size_t>(v)];
    int cur = start;
    for (int guard = 0; cur >= 0 && guard < 10000; ++guard) {
      const Tri& T = tri(cur);
      size_t i = 0;
      while (i < 3 && T.v[i] != v) ++i;
      if (i == 3) break;
      if (T.inside) out.push_back(cur);
      cur = T.n[(i + 1) % 3];
      if (cur == start) break;
    }
    return out;
  }

  static bool crosses(const V2& a, const V2& b, const V2& c, const V2& d) {
    return orient(a, b, c) * orient(a, b, d) < 0 && orient(c, d, a) * orient(c, d, b) < 0;
  }

  void recover(int a, int b) {
    int at = 0;
    if (find_edge(a, b, at) >= 0 || find_edge(b, a, at) >= 0) {
      mark_constrained(a, b);
      return;
    }
    // Triangle around a whose opposite edge crosses a->b.
    std::deque<std::pair<int, int>> queue;
    int cur = vt[static_cast<size_t>(a)];
    int x = -1, y = -1, guard = 0;
    for (;; ++guard) {
      if (cur < 0 || guard > 10000) throw std::runtime_error("loop edge recovery failed");
      const Tri& T = tri(cur);
      size_t i = 0;
      while (T.v[i] != a) ++i;
      const int r = T.v[(i + 1) % 3], l = T.v[(i + 2) % 3];
      if (orient(pt(a), pt(r), pt(b)) > 0 && orient(pt(a), pt(l), pt(b)) < 0) {
        x = r;
        y = l;
        cur = T.n[i];
        break;
      }
      cur = T.n[(i + 1) % 3];
    }
    queue.emplace_back(x, y);
    for (guard = 0;; ++guard) {
      if (cur < 0 || guard > 100000) throw std::runtime_error("loop edge recovery failed");
      const Tri& T = tri(cur);
      int w = -1;
      for (int k : T.v) {
        if (k != x && k != y) w = k;
      }
      if (w == b) break;
      const double s = orient(pt(a), pt(b), pt(w));
      if (s == 0) throw std::runtime_error("a loop point lies on another loop edge");
      int at2 = 0;
      if (s > 0) {
        y = w;
      } else {
        x = w;
      }
      queue.emplace_back(x, y);
      // Continue across the new crossing edge, away from the current triangle.
      const int next = find_edge(y, x, at2);
      if (next < 0 || next == cur) throw std::runtime_error("loop edge recovery failed");
      cur = next;
    }
    const size_t limit = 50 * queue.size() * queue.size() + 1000;
    for (size_t guard2 = 0; !queue.empty(); ++guard2) {
      if (guard2 > limit) throw std::runtime_error("loop edges intersect");
      auto [u, v] = queue.front();
      queue.pop_front();
      int i = 0;
      int ti = find_edge(u, v, i);
      if (ti < 0) throw std::runtime_error("loop edge recovery lost an edge");
      // The edge (u, v) is opposite v[i + 2] of ti.
      const int opp = (i + 2) % 3;
      const int xo = tri(ti).v[static_cast<size_t>(opp)];
      if (!flip(ti, opp)) {
        queue.emplace_back(u, v);
        continue;
      }
      // The new diagonal joins xo and the far vertex.
      int yo = -1;
      for (int k : tri(ti).v) {
        if (k != xo && k != u && k != v) yo = k;
      }
      if (crosses(pt(a), pt(b), pt(xo), pt(yo))) queue.emplace_back(xo, yo);
    }
    mark_constrained(a, b);
  }

  /// Marks the existing edge {a, b} as a loop edge on both sides (flips then
  /// leave it alone); throws when it is missing.
  void mark_constrained(int a, int b) {
    int at = 0;
    bool found = false;
    for (const auto& [u, v] : {std::make_pair(a, b), std::make_pair(b, a)}) {
      const int ti = find_edge(u, v, at);
      if (ti < 0) continue;
      tri(ti).c[static_cast<size_t>((at + 2) % 3)] = true;
      found = true;
    }
    if (!found) throw std::runtime_error("loop edge recovery failed");
  }

  void mark_loop_edges(const std::unordered_set<std::uint64_t>& keys) {
    for (Tri& T : t) {
      if (!T.alive) continue;
      for (size_t i = 0; i < 3; ++i) {
        T.c[i] = keys.count(edge_key(T.v[(i + 1) % 3], T.v[(i + 2) % 3])) > 0;
      }
    }
  }

  void legalize_all() {
    std::vector<int> stack;
    for (int i = 0; i < static_cast<int>(t.size()); ++i) {
      if (tri(i).alive) stack.push_back(i);
    }
    size_t guard = 0;
    const size_t limit = 100 * t.size() + 1000;
    while (!stack.empty() && ++guard < limit) {
      const int ti = stack.back();
      stack.pop_back();
      if (!tri(ti).alive) continue;
      for (int i = 0; i < 3; ++i) {
        const Tri& T = tri(ti);
        const int si = T.n[static_cast<size_t>(i)];
        if (si < 0 || T.c[static_cast<size_t>(i)]) continue;
        const Tri& S = tri(si);
        int y = -1;
        for (int k : S.v) {
          if (k != T.v[static_cast<size_t>((i + 1) % 3)] &&
              k != T.v[static_cast<size_t>((i + 2) % 3)])
            y = k;
        }
        if (incircle(pt(T.v[0]), pt(T.v[1]), pt(T.v[2]), pt(y)) > 1e-14 && flip(ti, i)) {
          stack.push_back(ti);
          stack.push_back(si);
          break;
        }
      }
    }
  }
};

}  // namespace cooperage::pave::detail::cdt
