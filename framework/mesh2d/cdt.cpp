#include "framework/mesh2d/cdt.h"

#include <algorithm>
#include <deque>
#include <string>

#include "framework/core/error.h"

namespace cooperage::mesh2d::detail {
namespace {

[[noreturn]] void bad_input(const std::string& message) {
  throw MeshingError(ErrorCode::InvalidInput, "triangulate: " + message);
}

}  // namespace

int Cdt::init(const Point2& s0, const Point2& s1, const Point2& s2) {
  const int a = add_point(s0, 0.0);
  const int b = add_point(s1, 0.0);
  const int c = add_point(s2, 0.0);
  tris.emplace_back();
  set(0, {a, b, c}, {-1, -1, -1}, {false, false, false});
  return 0;
}

int Cdt::add_point(const Point2& p, double h) {
  pts.push_back(p);
  size.push_back(h);
  vtri.push_back(-1);
  return static_cast<int>(pts.size()) - 1;
}

void Cdt::set(int t, const std::array<int, 3>& v, const std::array<int, 3>& n,
              const std::array<bool, 3>& c) {
  Tri& T = tris[static_cast<size_t>(t)];
  T.v = v;
  T.n = n;
  T.c = c;
  ++T.stamp;
  for (int k : v) vtri[static_cast<size_t>(k)] = t;
  touched.push_back(t);
}

void Cdt::relink(int nb, int from, int to) {
  if (nb < 0) return;
  Tri& T = tris[static_cast<size_t>(nb)];
  for (int& k : T.n) {
    if (k == from) {
      k = to;
      return;
    }
  }
}

int Cdt::back_index(int u, int t) const {
  const Tri& U = tris[static_cast<size_t>(u)];
  for (int k = 0; k < 3; ++k) {
    if (U.n[static_cast<size_t>(k)] == t) return k;
  }
  throw MeshingError(ErrorCode::Internal, "triangulate: broken neighbour link");
}

Cdt::Location Cdt::locate(const Point2& p, int start, bool stop_at_constraints) const {
  int t = start;
  int prev = -1;
  const size_t cap = 4 * tris.size() + 100;
  for (size_t step = 0;; ++step) {
    if (step > cap) throw MeshingError(ErrorCode::Internal, "triangulate: point location cycles");
    const Tri& T = tris[static_cast<size_t>(t)];
    bool moved = false;
    const int k0 = static_cast<int>(step % 3);
    for (int e = 0; e < 3 && !moved; ++e) {
      const int i = (k0 + e) % 3;
      const int nb = T.n[static_cast<size_t>(i)];
      if (nb >= 0 && nb == prev) continue;
      const Point2& a = pts[static_cast<size_t>(T.v[static_cast<size_t>(nxt(i))])];
      const Point2& b = pts[static_cast<size_t>(T.v[static_cast<size_t>(prv(i))])];
      if (orient2d(a, b, p) < 0.0) {
        if (stop_at_constraints && T.c[static_cast<size_t>(i)]) return {Where::Blocked, t, i};
        if (nb < 0) return {Where::Outside, t, i};
        prev = t;
        t = nb;
        moved = true;
      }
    }
    if (!moved) break;
  }
  // p is in the closed triangle t: on an edge (within tolerance), a vertex, or inside.
  const Tri& T = tris[static_cast<size_t>(t)];
  int on = 0;
  int edge = -1;
  for (int i = 0; i < 3; ++i) {
    const Point2& a = pts[static_cast<size_t>(T.v[static_cast<size_t>(nxt(i))])];
    const Point2& b = pts[static_cast<size_t>(T.v[static_cast<size_t>(prv(i))])];
    const double d = orient2d(a, b, p);
    if (d <= kOnEdgeTol * (b - a).squaredNorm()) {
      ++on;
      edge = i;
    }
  }
  if (on == 0) return {Where::Inside, t, -1};
  if (on == 1) {
    // Either triangle of the edge may be reached; report a canonical one
    // (inside before outside, then the lower index) so ties resolve alike.
    const int u = T.n[static_cast<size_t>(edge)];
    if (u >= 0) {
      const Tri& U = tris[static_cast<size_t>(u)];
      if ((U.inside && !T.inside) || (U.inside == T.inside && u < t)) {
        return {Where::OnEdge, u, back_index(u, t)};
      }
    }
    return {Where::OnEdge, t, edge};
  }
  int vertex = 0;
  double best = (pts[static_cast<size_t>(T.v[0])] - p).squaredNorm();
  for (int k = 1; k < 3; ++k) {
    const double d = (pts[static_cast<size_t>(T.v[static_cast<size_t>(k)])] - p).squaredNorm();
    if (d < best) {
      best = d;
      vertex = k;
    }
  }
  return {Where::OnVertex, t, vertex};
}

bool Cdt::insert(int p, const Location& loc) {
  std::vector<std::pair<int, int>> stack;
  const Point2& P = pts[static_cast<size_t>(p)];
  if (loc.where == Where::OnEdge) {
    const int t = loc.tri;
    const int i = loc.edge;
    const Tri T = tris[static_cast<size_t>(t)];
    const int u = T.n[static_cast<size_t>(i)];
    if (u >= 0 && !T.c[static_cast<size_t>(i)]) {
      const int j = back_index(u, t);
      const Tri U = tris[static_cast<size_t>(u)];
      const int vi = T.v[static_cast<size_t>(i)];
      const int a = T.v[static_cast<size_t>(nxt(i))];
      const int b = T.v[static_cast<size_t>(prv(i))];
      const int s = U.v[static_cast<size_t>(j)];
      const auto& X = pts;
      if (orient2d(X[static_cast<size_t>(vi)], X[static_cast<size_t>(a)], P) > 0.0 &&
          orient2d(X[static_cast<size_t>(vi)], P, X[static_cast<size_t>(b)]) > 0.0 &&
          orient2d(X[static_cast<size_t>(s)], X[static_cast<size_t>(b)], P) > 0.0 &&
          orient2d(X[static_cast<size_t>(s)], P, X[static_cast<size_t>(a)]) > 0.0) {
        const int t2 = static_cast<int>(tris.size());
        const int t4 = t2 + 1;
        tris.emplace_back();
        tris.emplace_back();
        tris[static_cast<size_t>(t2)].inside = T.inside;
        tris[static_cast<size_t>(t4)].inside = U.inside;
        const int tb = T.n[static_cast<size_t>(nxt(i))];  // across (b, vi)
        const int ta = T.n[static_cast<size_t>(prv(i))];  // across (vi, a)
        const int ub = U.n[static_cast<size_t>(nxt(j))];  // across (a, s)
        const int ua = U.n[static_cast<size_t>(prv(j))];  // across (s, b)
        set(t, {vi, a, p}, {t4, t2, ta}, {false, false, T.c[static_cast<size_t>(prv(i))]});
        set(t2, {vi, p, b}, {u, tb, t}, {false, T.c[static_cast<size_t>(nxt(i))], false});
        set(u, {s, b, p}, {t2, t4, ua}, {false, false, U.c[static_cast<size_t>(prv(j))]});
        set(t4, {s, p, a}, {t, ub, u}, {false, U.c[static_cast<size_t>(nxt(j))], false});
        relink(tb, t, t2);
        relink(ub, u, t4);
        stack = {{t, 2}, {t2, 1}, {u, 2}, {t4, 1}};
        legalize(stack);
        return true;
      }
    }
    // Not a clean edge split: fall through when p is strictly inside t.
    const Tri& T2 = tris[static_cast<size_t>(t)];
    for (int k = 0; k < 3; ++k) {
      if (orient2d(pts[static_cast<size_t>(T2.v[static_cast<size_t>(nxt(k))])],
                   pts[static_cast<size_t>(T2.v[static_cast<size_t>(prv(k))])], P) <= 0.0) {
        return false;
      }
    }
  } else if (loc.where != Where::Inside) {
    return false;
  }
  const int t0 = loc.tri;
  const Tri T = tris[static_cast<size_t>(t0)];
  const int t1 = static_cast<int>(tris.size());
  const int t2 = t1 + 1;
  tris.emplace_back();
  tris.emplace_back();
  tris[static_cast<size_t>(t1)].inside = T.inside;
  tris[static_cast<size_t>(t2)].inside = T.inside;
  const auto& v = T.v;
  set(t0, {p, v[1], v[2]}, {T.n[0], t1, t2}, {T.c[0], false, false});
  set(t1, {p, v[2], v[0]}, {T.n[1], t2, t0}, {T.c[1], false, false});
  set(t2, {p, v[0], v[1]}, {T.n[2], t0, t1}, {T.c[2], false, false});
  relink(T.n[1], t0, t1);
  relink(T.n[2], t0, t2);
  stack = {{t0, 0}, {t1, 0}, {t2, 0}};
  legalize(stack);
  return true;
}

bool Cdt::flip_wanted(int t, int i) const {
  const Tri& T = tris[static_cast<size_t>(t)];
  const int u = T.n[static_cast<size_t>(i)];
  if (u < 0 || T.c[static_cast<size_t>(i)]) return false;
  const int j = back_index(u, t);
  const int s = tris[static_cast<size_t>(u)].v[static_cast<size_t>(j)];
  double permanent = 0.0;
  const double det =
      incircle_fast(pts[static_cast<size_t>(T.v[0])], pts[static_cast<size_t>(T.v[1])],
                    pts[static_cast<size_t>(T.v[2])], pts[static_cast<size_t>(s)], permanent);
  return det > kDelaunayTieTol * permanent;
}

int Cdt::flip(int t, int i) {
  const Tri T = tris[static_cast<size_t>(t)];
  const int u = T.n[static_cast<size_t>(i)];
  const int j = back_index(u, t);
  const Tri U = tris[static_cast<size_t>(u)];
  const int p = T.v[static_cast<size_t>(i)];
  const int q = T.v[static_cast<size_t>(nxt(i))];
  const int r = T.v[static_cast<size_t>(prv(i))];
  const int s = U.v[static_cast<size_t>(j)];
  const int A = T.n[static_cast<size_t>(nxt(i))];  // across (r, p)
  const int B = T.n[static_cast<size_t>(prv(i))];  // across (p, q)
  const int C = U.n[static_cast<size_t>(nxt(j))];  // across (q, s)
  const int D = U.n[static_cast<size_t>(prv(j))];  // across (s, r)
  const bool cA = T.c[static_cast<size_t>(nxt(i))];
  const bool cB = T.c[static_cast<size_t>(prv(i))];
  const bool cC = U.c[static_cast<size_t>(nxt(j))];
  const bool cD = U.c[static_cast<size_t>(prv(j))];
  set(t, {p, q, s}, {C, u, B}, {cC, false, cB});
  set(u, {p, s, r}, {D, A, t}, {cD, cA, false});
  relink(C, u, t);
  relink(A, t, u);
  return u;
}

void Cdt::legalize(std::vector<std::pair<int, int>>& stack) {
  while (!stack.empty()) {
    const auto [t, i] = stack.back();
    stack.pop_back();
    if (!flip_wanted(t, i)) continue;
    // Rotate so that the new point is v[0] of both results.
    const int u = flip(t, i);
    stack.emplace_back(t, 0);
    stack.emplace_back(u, 0);
  }
}

std::vector<std::pair<int, int>> Cdt::star(int a) const {
  std::vector<std::pair<int, int>> out;
  const int t0 = vtri[static_cast<size_t>(a)];
  auto index_of = [&](int t) {
    const Tri& T = tris[static_cast<size_t>(t)];
    for (int k = 0; k < 3; ++k) {
      if (T.v[static_cast<size_t>(k)] == a) return k;
    }
    throw MeshingError(ErrorCode::Internal, "triangulate: broken vertex link");
  };
  int t = t0;
  do {
    const int k = index_of(t);
    out.emplace_back(t, k);
    t = tris[static_cast<size_t>(t)].n[static_cast<size_t>(nxt(k))];
  } while (t >= 0 && t != t0);
  if (t < 0) {  // open star (hull vertex): walk the other way as well
    t = tris[static_cast<size_t>(t0)].n[static_cast<size_t>(prv(index_of(t0)))];
    while (t >= 0) {
      const int k = index_of(t);
      out.emplace_back(t, k);
      t = tris[static_cast<size_t>(t)].n[static_cast<size_t>(prv(k))];
    }
  }
  return out;
}

std::pair<int, int> Cdt::find_edge(int a, int b) const {
  for (const auto& [t, k] : star(a)) {
    const Tri& T = tris[static_cast<size_t>(t)];
    if (T.v[static_cast<size_t>(nxt(k))] == b) return {t, prv(k)};
    if (T.v[static_cast<size_t>(prv(k))] == b) return {t, nxt(k)};
  }
  return {-1, -1};
}

void Cdt::insert_segment(int a, int b) {
  const Point2& A = pts[static_cast<size_t>(a)];
  const Point2& B = pts[static_cast<size_t>(b)];
  auto on_segment = [&](int q) {
    const Point2& Q = pts[static_cast<size_t>(q)];
    return orient2d(A, B, Q) == 0.0 && (Q - A).dot(B - A) > 0.0 && (Q - B).dot(A - B) > 0.0;
  };
  auto mark = [&]() {
    const auto [t, i] = find_edge(a, b);
    if (t < 0) return false;
    Tri& T = tris[static_cast<size_t>(t)];
    T.c[static_cast<size_t>(i)] = true;
    const int u = T.n[static_cast<size_t>(i)];
    if (u >= 0) tris[static_cast<size_t>(u)].c[static_cast<size_t>(back_index(u, t))] = true;
    return true;
  };
  if (mark()) return;
  // The triangle at a whose opposite edge (q, r) the segment crosses.
  int t = -1;
  int R = -1;  // right of a->b
  int L = -1;  // left of a->b
  for (const auto& [tt, k] : star(a)) {
    const Tri& T = tris[static_cast<size_t>(tt)];
    const int q = T.v[static_cast<size_t>(nxt(k))];
    const int r = T.v[static_cast<size_t>(prv(k))];
    if (on_segment(q) || on_segment(r)) bad_input("a boundary point lies on a boundary segment");
    if (orient2d(A, pts[static_cast<size_t>(q)], B) > 0.0 &&
        orient2d(A, pts[static_cast<size_t>(r)], B) < 0.0) {
      t = tt;
      R = q;
      L = r;
      break;
    }
  }
  if (t < 0) throw MeshingError(ErrorCode::Internal, "triangulate: segment start not found");
  std::deque<std::pair<int, int>> crossing;
  for (;;) {
    crossing.emplace_back(R, L);
    const auto [tt, i] = find_edge(R, L);
    const Tri& T = tris[static_cast<size_t>(tt)];
    // The triangle across (R, L) away from the current one.
    int u = T.n[static_cast<size_t>(i)];
    if (u == t) u = tt;
    if (u < 0) bad_input("a boundary segment leaves the domain");
    const Tri& U = tris[static_cast<size_t>(u)];
    int s = -1;
    for (int k : U.v) {
      if (k != R && k != L) s = k;
    }
    if (s == b) break;
    const double o = orient2d(A, B, pts[static_cast<size_t>(s)]);
    if (o == 0.0) bad_input("a boundary point lies on a boundary segment");
    if (o > 0.0)
      L = s;
    else
      R = s;
    t = u;
  }
  // Sloan: flip crossing edges whose quadrilateral is strictly convex.
  size_t guard = 0;
  const size_t cap = 64 * crossing.size() * crossing.size() + 1000;
  while (!crossing.empty()) {
    if (++guard > cap) bad_input("boundary segments cross");
    const auto [x, y] = crossing.front();
    crossing.pop_front();
    const auto [tt, i] = find_edge(x, y);
    if (tt < 0) continue;
    const Tri& T = tris[static_cast<size_t>(tt)];
    const int u = T.n[static_cast<size_t>(i)];
    if (T.c[static_cast<size_t>(i)]) bad_input("boundary segments cross");
    const int p = T.v[static_cast<size_t>(i)];
    const int q = T.v[static_cast<size_t>(nxt(i))];
    const int r = T.v[static_cast<size_t>(prv(i))];
    const int s = tris[static_cast<size_t>(u)].v[static_cast<size_t>(back_index(u, tt))];
    const auto& X = pts;
    const bool convex = orient2d(X[static_cast<size_t>(p)], X[static_cast<size_t>(q)],
                                 X[static_cast<size_t>(s)]) > 0.0 &&
                        orient2d(X[static_cast<size_t>(p)], X[static_cast<size_t>(s)],
                                 X[static_cast<size_t>(r)]) > 0.0;
    if (!convex) {
      crossing.emplace_back(x, y);
      continue;
    }
    flip(tt, i);
    if (p != a && p != b && s != a && s != b) {
      const double op = orient2d(A, B, X[static_cast<size_t>(p)]);
      const double os = orient2d(A, B, X[static_cast<size_t>(s)]);
      if ((op > 0.0 && os < 0.0) || (op < 0.0 && os > 0.0)) crossing.emplace_back(p, s);
    }
  }
  if (!mark()) throw MeshingError(ErrorCode::Internal, "triangulate: segment not recovered");
}

void Cdt::mark_inside() {
  std::vector<int> depth(tris.size(), -1);
  std::deque<int> queue;
  for (size_t t = 0; t < tris.size(); ++t) {
    for (int k : tris[t].v) {
      if (k < 3) {  // a super-triangle vertex
        if (depth[t] < 0) {
          depth[t] = 0;
          queue.push_back(static_cast<int>(t));
        }
      }
    }
  }
  // 0-1 breadth-first search: crossing a constraint costs one.
  std::vector<bool> done(tris.size(), false);
  while (!queue.empty()) {
    const int t = queue.front();
    queue.pop_front();
    if (done[static_cast<size_t>(t)]) continue;
    done[static_cast<size_t>(t)] = true;
    const Tri& T = tris[static_cast<size_t>(t)];
    for (int i = 0; i < 3; ++i) {
      const int u = T.n[static_cast<size_t>(i)];
      if (u < 0) continue;
      const int d = depth[static_cast<size_t>(t)] + (T.c[static_cast<size_t>(i)] ? 1 : 0);
      if (depth[static_cast<size_t>(u)] < 0 || d < depth[static_cast<size_t>(u)]) {
        depth[static_cast<size_t>(u)] = d;
        if (T.c[static_cast<size_t>(i)])
          queue.push_back(u);
        else
          queue.push_front(u);
      }
    }
  }
  for (size_t t = 0; t < tris.size(); ++t) tris[t].inside = depth[t] % 2 == 1;
}

void Cdt::make_delaunay() {
  std::vector<std::pair<int, int>> stack;
  for (size_t t = 0; t < tris.size(); ++t) {
    if (!tris[t].inside) continue;
    for (int i = 0; i < 3; ++i) stack.emplace_back(static_cast<int>(t), i);
  }
  std::reverse(stack.begin(), stack.end());
  while (!stack.empty()) {
    const auto [t, i] = stack.back();
    stack.pop_back();
    if (!tris[static_cast<size_t>(t)].inside || !flip_wanted(t, i)) continue;
    const int u = flip(t, i);
    stack.emplace_back(u, 1);
    stack.emplace_back(u, 0);
    stack.emplace_back(t, 2);
    stack.emplace_back(t, 0);
  }
}

void Cdt::canonicalize() {
  for (Tri& T : tris) {
    int k = 0;
    if (T.v[1] < T.v[k]) k = 1;
    if (T.v[2] < T.v[static_cast<size_t>(k)]) k = 2;
    std::rotate(T.v.begin(), T.v.begin() + k, T.v.end());
    std::rotate(T.n.begin(), T.n.begin() + k, T.n.end());
    std::rotate(T.c.begin(), T.c.begin() + k, T.c.end());
  }
  std::vector<int> order(tris.size());
  for (size_t t = 0; t < tris.size(); ++t) order[t] = static_cast<int>(t);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    return tris[static_cast<size_t>(a)].v < tris[static_cast<size_t>(b)].v;
  });
  std::vector<int> index(tris.size());
  for (size_t k = 0; k < order.size(); ++k)
    index[static_cast<size_t>(order[k])] = static_cast<int>(k);
  std::vector<Tri> sorted;
  sorted.reserve(tris.size());
  for (int t : order) {
    Tri T = tris[static_cast<size_t>(t)];
    for (int& u : T.n) {
      if (u >= 0) u = index[static_cast<size_t>(u)];
    }
    sorted.push_back(T);
  }
  tris = std::move(sorted);
  for (size_t t = 0; t < tris.size(); ++t) {
    for (int v : tris[t].v) vtri[static_cast<size_t>(v)] = static_cast<int>(t);
  }
}

}  // namespace cooperage::mesh2d::detail
