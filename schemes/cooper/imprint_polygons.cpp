#include "schemes/cooper/imprint_polygons.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <unordered_map>
#include <utility>

namespace cooperage::cooper {

double signed_area(const std::vector<int>& loop, const std::map<int, Vec2>& xy) {
  if (loop.empty()) return 0;
  // From the first node: the rounding then follows the loop's size, not
  // its distance from the chart's origin (which a moved part changes).
  const Vec2& o = xy.at(loop.front());
  double a = 0;
  for (size_t i = 0; i < loop.size(); ++i) {
    const Vec2 p = xy.at(loop[i]) - o;
    const Vec2 q = xy.at(loop[(i + 1) % loop.size()]) - o;
    a += p.x() * q.y() - p.y() * q.x();
  }
  return 0.5 * a;
}

bool flat_loop(const std::vector<int>& loop, const std::map<int, Vec2>& xy) {
  double perimeter = 0;
  for (size_t i = 0; i < loop.size(); ++i)
    perimeter += (xy.at(loop[(i + 1) % loop.size()]) - xy.at(loop[i])).norm();
  return std::abs(signed_area(loop, xy)) <= 1e-12 * perimeter * perimeter;
}

std::vector<std::vector<int>> oriented_loops(std::vector<std::vector<int>> loops,
                                             const std::map<int, Vec2>& xy) {
  size_t outer = 0;
  double best = -1;
  for (size_t l = 0; l < loops.size(); ++l) {
    const double a = std::abs(signed_area(loops[l], xy));
    if (a > best) {
      best = a;
      outer = l;
    }
  }
  if (!loops.empty()) std::swap(loops[0], loops[outer]);
  for (size_t l = 0; l < loops.size(); ++l) {
    if ((l == 0) != (signed_area(loops[l], xy) > 0)) std::reverse(loops[l].begin(), loops[l].end());
  }
  return loops;
}

std::vector<std::vector<std::vector<int>>> separate_regions(
    const std::vector<std::vector<int>>& loops, const std::map<int, Vec2>& xy) {
  const size_t n = loops.size();
  // inside[i][j]: loop i lies inside loop j (tested at a node of i not on j).
  std::vector<std::vector<char>> inside(n, std::vector<char>(n, 0));
  std::vector<size_t> depth(n, 0);
  for (size_t i = 0; i < n; ++i) {
    for (size_t j = 0; j < n; ++j) {
      if (i == j) continue;
      for (int v : loops[i]) {
        if (detail::index_in(loops[j], v) >= 0) continue;
        inside[i][j] = detail::point_in_loop(xy.at(v), loops[j], xy) ? 1 : 0;
        break;
      }
      depth[i] += static_cast<size_t>(inside[i][j]);
    }
  }
  std::vector<std::vector<std::vector<int>>> regions;
  std::vector<long> region_of(n, -1);
  for (size_t i = 0; i < n; ++i) {
    if (depth[i] % 2) continue;
    region_of[i] = static_cast<long>(regions.size());
    regions.push_back({loops[i]});
  }
  for (size_t i = 0; i < n; ++i) {
    if (depth[i] % 2 == 0) continue;
    // The loops holding a hole are nested: the deepest of them is outer.
    size_t best = i;
    for (size_t j = 0; j < n; ++j) {
      if (inside[i][j] && (best == i || depth[j] > depth[best])) best = j;
    }
    regions[static_cast<size_t>(region_of[best])].push_back(loops[i]);
  }
  return regions;
}

namespace detail {

double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

// Intersection parameter t on segment p0-p1 with q0-q1 (touching included).
Vec2 closest_on_segment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 d = b - a;
  const double len2 = d.squaredNorm();
  const double t = len2 > 0.0 ? std::clamp((p - a).dot(d) / len2, 0.0, 1.0) : 0.0;
  return a + t * d;
}

std::optional<Vec2> foot_inside_segment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 d = b - a;
  const double len2 = d.squaredNorm();
  if (!(len2 > 0.0)) return std::nullopt;
  const double t = (p - a).dot(d) / len2;
  if (!(t > 1e-9 && t < 1.0 - 1e-9)) return std::nullopt;
  return Vec2(a + t * d);
}

std::optional<double> segment_hit(const Vec2& p0, const Vec2& p1, const Vec2& q0, const Vec2& q1) {
  const Vec2 r = p1 - p0, s = q1 - q0;
  const double d = cross(r, s);
  const double scale = r.norm() * s.norm();
  if (std::abs(d) <= 1e-12 * scale) return std::nullopt;  // parallel
  const double t = cross(q0 - p0, s) / d;
  const double u = cross(q0 - p0, r) / d;
  const double eps = 1e-9;
  if (t < -eps || t > 1 + eps || u < -eps || u > 1 + eps) return std::nullopt;
  return std::clamp(t, 0.0, 1.0);
}

bool point_in_loop(const Vec2& p, const Loop& loop, const std::map<int, Vec2>& xy) {
  bool in = false;
  for (size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++) {
    const Vec2& a = xy.at(loop[i]);
    const Vec2& b = xy.at(loop[j]);
    if ((a.y() > p.y()) != (b.y() > p.y()) &&
        p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x()) {
      in = !in;
    }
  }
  return in;
}

bool point_in_subcap(const Vec2& p, const Subcap& s, const std::map<int, Vec2>& xy) {
  if (!point_in_loop(p, s.loops.front(), xy)) return false;
  for (size_t h = 1; h < s.loops.size(); ++h) {
    if (point_in_loop(p, s.loops[h], xy)) return false;
  }
  return true;
}

int index_in(const Loop& loop, int node) {
  const auto it = std::find(loop.begin(), loop.end(), node);
  return it == loop.end() ? -1 : static_cast<int>(it - loop.begin());
}

bool adjacent(const Loop& loop, int a, int b) {
  const int i = index_in(loop, a);
  if (i < 0) return false;
  const size_t n = loop.size();
  return loop[(static_cast<size_t>(i) + 1) % n] == b ||
         loop[(static_cast<size_t>(i) + n - 1) % n] == b;
}

bool flat_quad(const Loop& loop, const std::map<int, Vec2>& xy) {
  if (loop.size() != 4) return false;
  for (size_t k = 0; k < 4; ++k) {
    const Vec2 a = xy.at(loop[(k + 3) % 4]) - xy.at(loop[k]);
    const Vec2 b = xy.at(loop[(k + 1) % 4]) - xy.at(loop[k]);
    const double len = a.norm() * b.norm();
    if (len <= 0.0 || std::abs(cross(b, a)) / len < 0.2) return true;
  }
  return false;
}

bool absorb_touching_hole(Loop& outer, const Loop& hole) {
  const size_t n = outer.size(), h = hole.size();
  for (size_t i = 0; i < n; ++i) {
    const int u = outer[i], v = outer[(i + 1) % n];
    const int j = index_in(hole, v);
    if (j < 0 || hole[(static_cast<size_t>(j) + 1) % h] != u) continue;
    // outer ... u, [hole after u up to before v], v ...
    Loop merged(outer.begin(), outer.begin() + static_cast<long>(i) + 1);
    for (size_t k = (static_cast<size_t>(j) + 2) % h; k != static_cast<size_t>(j); k = (k + 1) % h)
      merged.push_back(hole[k]);
    merged.insert(merged.end(), outer.begin() + static_cast<long>(i) + 1, outer.end());
    // Edges the two loops shared beyond the first come back as spikes p, q, p.
    remove_spikes(merged);
    outer = std::move(merged);
    return true;
  }
  return false;
}

bool merge_touching_holes(std::vector<Loop>& loops) {
  bool merged = false;
  for (size_t i = 0; i < loops.size(); ++i) {
    for (size_t j = i + 1; j < loops.size();) {
      if (absorb_touching_hole(loops[i], loops[j])) {
        loops.erase(loops.begin() + static_cast<long>(j));
        merged = true;
        j = i + 1;
      } else {
        ++j;
      }
    }
  }
  return merged;
}

bool remove_spikes(Loop& loop) {
  bool removed = false;
  for (bool again = true; again && loop.size() > 2;) {
    again = false;
    const size_t m = loop.size();
    for (size_t k = 0; k < m; ++k) {
      if (loop[k] != loop[(k + 2) % m]) continue;
      const size_t a = (k + 1) % m, b = (k + 2) % m;
      loop.erase(loop.begin() + static_cast<long>(std::max(a, b)));
      loop.erase(loop.begin() + static_cast<long>(std::min(a, b)));
      again = removed = true;
      break;
    }
  }
  return removed;
}

Vec2 hole_owner_probe(const Loop& hole, const std::map<int, Vec2>& xy,
                      const std::vector<Loop>& outers) {
  auto on_an_outer = [&](int a, int b) {
    for (const Loop& o : outers) {
      if (adjacent(o, a, b)) return true;
    }
    return false;
  };
  const size_t h = hole.size();
  for (size_t k = 0; k < h; ++k) {
    const int a = hole[k], b = hole[(k + 1) % h];
    if (on_an_outer(a, b)) continue;
    const Vec2 p = xy.at(a), q = xy.at(b);
    const Vec2 d = q - p;
    // A clockwise hole has the subcap's material on its left.
    return 0.5 * (p + q) + 1e-3 * Vec2(-d.y(), d.x());
  }
  return xy.at(hole.front());
}

// Splits a counter-clockwise loop by a path x -> interior -> y (x, y on the
// loop): left = path + loop from y forward to x; right = reversed path +
// loop from x forward to y (sec. 5.2: b^ and b').
std::pair<Loop, Loop> split_loop(const Loop& loop, int x, const Loop& interior, int y) {
  const size_t n = loop.size();
  // A node not on the loop: the walks below would never meet it.
  if (index_in(loop, x) < 0 || index_in(loop, y) < 0) return {};
  const size_t ix = static_cast<size_t>(index_in(loop, x));
  const size_t iy = static_cast<size_t>(index_in(loop, y));
  Loop left{x};
  left.insert(left.end(), interior.begin(), interior.end());
  for (size_t k = iy;; k = (k + 1) % n) {
    if (loop[k] == x) break;
    left.push_back(loop[k]);
  }
  Loop right{y};
  right.insert(right.end(), interior.rbegin(), interior.rend());
  for (size_t k = ix;; k = (k + 1) % n) {
    if (loop[k] == y) break;
    right.push_back(loop[k]);
  }
  return {left, right};
}

// Splits a loop at its first repeated node (the smallest i whose node comes
// again, at the smallest such j); returns false when none. Linear: long
// subcap loops (a boss 7,500 elements long) made the pairwise scan stall.
bool split_at_repeat(const Loop& loop, Loop& a, Loop& b) {
  std::unordered_map<int, size_t> first;
  first.reserve(loop.size());
  size_t best_i = loop.size(), best_j = loop.size();
  for (size_t j = 0; j < loop.size(); ++j) {
    const auto [it, added] = first.emplace(loop[j], j);
    if (!added && it->second < best_i) {
      best_i = it->second;
      best_j = j;
    }
  }
  if (best_i == loop.size()) return false;
  a.assign(loop.begin() + static_cast<long>(best_i), loop.begin() + static_cast<long>(best_j));
  b.assign(loop.begin() + static_cast<long>(best_j), loop.end());
  b.insert(b.end(), loop.begin(), loop.begin() + static_cast<long>(best_i));
  return true;
}

// The first pair of crossing segments (i, k), i < k, in the order of a
// nested scan over i then k (segments sharing a node excluded), or none.
// Segments are binned in a uniform grid of about four cells per segment,
// so a loop of n segments costs O(n), not O(n^2).
std::optional<std::pair<size_t, size_t>> first_crossing(const Loop& loop,
                                                        const std::map<int, Vec2>& xy) {
  const size_t n = loop.size();
  if (n < 4) return std::nullopt;
  std::vector<Vec2> p(n);
  Vec2 lo = xy.at(loop[0]), hi = lo;
  for (size_t i = 0; i < n; ++i) {
    p[i] = xy.at(loop[i]);
    lo = lo.cwiseMin(p[i]);
    hi = hi.cwiseMax(p[i]);
  }
  const Vec2 extent = (hi - lo).cwiseMax(Vec2::Constant(1e-300));
  // Cells: about 4n in all, shaped like the loop's box.
  const double cells = 4.0 * static_cast<double>(n);
  const double aspect = extent.x() / extent.y();
  const int nx = static_cast<int>(std::clamp(std::sqrt(cells * aspect), 1.0, cells));
  const int ny = static_cast<int>(std::clamp(cells / nx, 1.0, cells));
  auto cell_x = [&](double x) {
    return std::clamp(static_cast<int>((x - lo.x()) / extent.x() * nx), 0, nx - 1);
  };
  auto cell_y = [&](double y) {
    return std::clamp(static_cast<int>((y - lo.y()) / extent.y() * ny), 0, ny - 1);
  };
  std::vector<std::vector<size_t>> grid(static_cast<size_t>(nx) * static_cast<size_t>(ny));
  auto for_cells = [&](size_t i, auto&& visit) {
    const Vec2& a = p[i];
    const Vec2& b = p[(i + 1) % n];
    for (int cx = cell_x(std::min(a.x(), b.x())); cx <= cell_x(std::max(a.x(), b.x())); ++cx) {
      for (int cy = cell_y(std::min(a.y(), b.y())); cy <= cell_y(std::max(a.y(), b.y())); ++cy) {
        visit(grid[static_cast<size_t>(cx) * static_cast<size_t>(ny) + static_cast<size_t>(cy)]);
      }
    }
  };
  for (size_t k = 0; k < n; ++k) for_cells(k, [&](std::vector<size_t>& c) { c.push_back(k); });
  for (size_t i = 0; i < n; ++i) {
    size_t best = n;
    for_cells(i, [&](const std::vector<size_t>& c) {
      for (size_t k : c) {
        if (k < i + 2 || k >= best || (k + 1) % n == i) continue;
        const int a0 = loop[i], a1 = loop[(i + 1) % n], b0 = loop[k], b1 = loop[(k + 1) % n];
        if (a0 == b0 || a0 == b1 || a1 == b0 || a1 == b1) continue;
        if (segment_hit(p[i], p[(i + 1) % n], p[k], p[(k + 1) % n])) best = k;
      }
    });
    if (best < n) return std::make_pair(i, best);
  }
  return std::nullopt;
}

}  // namespace detail

using detail::Loop;

// cite: Blacker 1996, sec. 5.5 (self-intersecting subcaps: n + 1 loops).
std::vector<Loop> split_self_intersections(const Loop& input, const std::map<int, Vec2>& xy,
                                           bool even_parity,
                                           std::vector<std::pair<int, int>>* combined,
                                           const std::function<bool(int, int)>& combinable) {
  Loop loop = input;
  // Combine proper crossings onto node pairs.
  for (int guard = 0; guard < 1000; ++guard) {
    const auto hit = detail::first_crossing(loop, xy);
    if (!hit) break;
    const size_t n = loop.size();
    const auto [i, k] = *hit;
    // Candidate pairs (one node of each segment), closest first, even loops preferred.
    struct Cand {
      size_t p, q;
      double d;
    };
    std::vector<Cand> cands;
    for (size_t p : {i, (i + 1) % n}) {
      for (size_t q : {k, (k + 1) % n})
        cands.push_back({p, q, (xy.at(loop[p]) - xy.at(loop[q])).norm()});
    }
    std::sort(cands.begin(), cands.end(), [](const Cand& x, const Cand& y) { return x.d < y.d; });
    // Two ribbed nodes made one would leave one of their ribs pointing at
    // a node that no loop holds any more; such pairs go last.
    if (combinable) {
      std::stable_partition(cands.begin(), cands.end(),
                            [&](const Cand& c) { return combinable(loop[c.p], loop[c.q]); });
    }
    const Cand* pick = &cands.front();
    if (even_parity) {
      for (const Cand& c : cands) {
        const size_t lo = std::min(c.p, c.q), hi = std::max(c.p, c.q);
        if ((hi - lo) % 2 == 0) {
          pick = &c;
          break;
        }
      }
    }
    const int keep = std::min(loop[pick->p], loop[pick->q]);
    const int drop = std::max(loop[pick->p], loop[pick->q]);
    if (combined) combined->push_back({drop, keep});
    for (int& v : loop) {
      if (v == drop) v = keep;
    }
  }
  // Split at repeated nodes (touching points), recursively.
  std::vector<Loop> out;
  std::vector<Loop> work{loop};
  while (!work.empty()) {
    Loop l = work.back();
    work.pop_back();
    Loop a, b;
    if (detail::split_at_repeat(l, a, b)) {
      if (a.size() >= 3) work.push_back(a);
      if (b.size() >= 3) work.push_back(b);
    } else if (l.size() >= 3) {
      out.push_back(l);
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace cooperage::cooper
