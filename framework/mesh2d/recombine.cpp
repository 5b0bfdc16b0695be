#include "framework/mesh2d/recombine.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace cooperage::mesh2d {
namespace {

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// A possible merge: triangles s < u sharing an edge, and the quad they make.
struct Merge {
  long long key = 0;  // quality rounded to 1e-9 (ties compare equal after a rigid motion)
  int s = -1, u = -1;
  std::array<int, 4> quad{};
};

struct Graph {
  std::vector<std::vector<int>> merges_of;  // per triangle: indices into merges, by edge
  std::vector<Merge> merges;
  int other(int m, int tri) const {
    return merges[static_cast<size_t>(m)].s == tri ? merges[static_cast<size_t>(m)].u
                                                   : merges[static_cast<size_t>(m)].s;
  }
};

Graph acceptable_merges(const Triangulation2D& t, double min_quality) {
  Graph g;
  g.merges_of.resize(t.triangles.size());
  std::unordered_map<std::uint64_t, std::pair<int, int>> open;  // edge -> (triangle, corner)
  open.reserve(3 * t.triangles.size());
  for (int s = 0; s < static_cast<int>(t.triangles.size()); ++s) {
    const auto& T = t.triangles[static_cast<size_t>(s)];
    for (int k = 0; k < 3; ++k) {
      const int a = T[static_cast<size_t>((k + 1) % 3)], b = T[static_cast<size_t>((k + 2) % 3)];
      const std::uint64_t key = (static_cast<std::uint64_t>(std::min(a, b)) << 32) |
                                static_cast<std::uint32_t>(std::max(a, b));
      auto [it, fresh] = open.emplace(key, std::make_pair(s, k));
      if (fresh) continue;
      // The earlier triangle r = (c, a', b') owns the edge a' -> b'; s runs it backwards.
      const auto [r, kr] = it->second;
      const auto& R = t.triangles[static_cast<size_t>(r)];
      const int c = R[static_cast<size_t>(kr)];
      const int ra = R[static_cast<size_t>((kr + 1) % 3)], rb = R[static_cast<size_t>((kr + 2) % 3)];
      const int d = T[static_cast<size_t>(k)];
      const std::array<int, 4> q{c, ra, d, rb};
      const auto& P = t.points;
      const double quality = quad_quality(P[static_cast<size_t>(q[0])], P[static_cast<size_t>(q[1])],
                                          P[static_cast<size_t>(q[2])], P[static_cast<size_t>(q[3])]);
      open.erase(it);
      if (!(quality >= min_quality)) continue;
      g.merges.push_back({std::llround(quality * 1e9), r, s, q});
      const int m = static_cast<int>(g.merges.size()) - 1;
      g.merges_of[static_cast<size_t>(r)].push_back(m);
      g.merges_of[static_cast<size_t>(s)].push_back(m);
    }
  }
  return g;
}

// Breadth-first search for an augmenting path from the unpaired triangle
// `start`: start - y1 = w1 - y2 = w2 ... - f with y_i = w_i paired and f
// unpaired. Re-pairs the path (one more quad) and returns whether it found one.
bool augment(const Graph& g, int start, int max_quads, std::vector<int>& mate,
             std::vector<int>& via, std::vector<std::uint32_t>& seen, std::uint32_t stamp) {
  std::vector<std::pair<int, int>> queue{{start, 0}};  // (even triangle, quads re-paired so far)
  seen[static_cast<size_t>(start)] = stamp;
  for (size_t head = 0; head < queue.size(); ++head) {
    const auto [x, depth] = queue[head];
    for (int m : g.merges_of[static_cast<size_t>(x)]) {
      const int y = g.other(m, x);
      if (seen[static_cast<size_t>(y)] == stamp) continue;
      seen[static_cast<size_t>(y)] = stamp;
      via[static_cast<size_t>(y)] = m;
      if (mate[static_cast<size_t>(y)] < 0) {
        // Walk back: y pairs with x, x's old mate pairs with what reached x, ...
        int odd = y;
        while (true) {
          const int even = g.other(via[static_cast<size_t>(odd)], odd);
          const int old = mate[static_cast<size_t>(even)];
          mate[static_cast<size_t>(even)] = odd;
          mate[static_cast<size_t>(odd)] = even;
          if (even == start) return true;
          odd = old;
        }
      }
      const int w = mate[static_cast<size_t>(y)];
      if (depth >= max_quads || seen[static_cast<size_t>(w)] == stamp) continue;
      seen[static_cast<size_t>(w)] = stamp;
      queue.emplace_back(w, depth + 1);
    }
  }
  return false;
}

}  // namespace

double quad_quality(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                    const Eigen::Vector2d& d) {
  const Eigen::Vector2d e[4] = {b - a, c - b, d - c, a - d};
  double l[4];
  for (int k = 0; k < 4; ++k) {
    l[k] = e[k].norm();
    if (!(l[k] > 0.0)) return -1.0;
  }
  double m = 1.0;
  for (int k = 0; k < 4; ++k) {
    const int j = (k + 3) % 4;  // corner k lies between e[j] (in) and e[k] (out)
    m = std::min(m, cross(e[j], e[k]) / (l[j] * l[k]));
  }
  return m;
}

MixedMesh2D recombine(const Triangulation2D& t, const RecombineOptions& options) {
  const Graph g = acceptable_merges(t, options.min_quad_quality);
  // Greedy: best quad first; ties by the triangles' indices.
  std::vector<int> order(g.merges.size());
  for (size_t m = 0; m < order.size(); ++m) order[m] = static_cast<int>(m);
  std::sort(order.begin(), order.end(), [&](int i, int j) {
    const Merge& a = g.merges[static_cast<size_t>(i)];
    const Merge& b = g.merges[static_cast<size_t>(j)];
    if (a.key != b.key) return a.key > b.key;
    return std::make_pair(a.s, a.u) < std::make_pair(b.s, b.u);
  });
  const size_t n = t.triangles.size();
  std::vector<int> mate(n, -1);
  for (int m : order) {
    const Merge& x = g.merges[static_cast<size_t>(m)];
    if (mate[static_cast<size_t>(x.s)] < 0 && mate[static_cast<size_t>(x.u)] < 0) {
      mate[static_cast<size_t>(x.s)] = x.u;
      mate[static_cast<size_t>(x.u)] = x.s;
    }
  }
  if (options.max_path_quads > 0) {
    std::vector<int> via(n, -1);
    std::vector<std::uint32_t> seen(n, 0);
    std::uint32_t stamp = 0;
    for (size_t s = 0; s < n; ++s) {
      if (mate[s] >= 0 || g.merges_of[s].empty()) continue;
      augment(g, static_cast<int>(s), options.max_path_quads, mate, via, seen, ++stamp);
    }
  }

  MixedMesh2D out;
  out.points = t.points;
  out.boundary_count = t.boundary_count;
  for (size_t s = 0; s < n; ++s) {
    const int u = mate[s];
    if (u < 0) {
      out.triangles.push_back(t.triangles[s]);
    } else if (static_cast<size_t>(u) > s) {
      for (int m : g.merges_of[s]) {
        if (g.other(m, static_cast<int>(s)) == u) out.quads.push_back(g.merges[static_cast<size_t>(m)].quad);
      }
    }
  }
  return out;
}

}  // namespace cooperage::mesh2d
