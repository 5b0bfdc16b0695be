// Shared helpers of the pave tests: generated 2D faces and mesh checks.
#pragma once

#include "schemes/pave/pave_2d.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace cooperage::pave::testing {

using V2 = Eigen::Vector2d;
using Loops = std::vector<std::vector<V2>>;

/// n points on a circle, counter-clockwise (or clockwise with cw).
inline std::vector<V2> circle(const V2& c, double r, int n, bool cw = false) {
  std::vector<V2> p;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * M_PI * i / n * (cw ? -1 : 1);
    p.emplace_back(c.x() + r * std::cos(a), c.y() + r * std::sin(a));
  }
  return p;
}

/// Polygon corners subdivided: counts[k] intervals on edge k.
inline std::vector<V2> polygon(const std::vector<V2>& corners, const std::vector<int>& counts) {
  std::vector<V2> p;
  for (size_t k = 0; k < corners.size(); ++k) {
    const V2 a = corners[k], b = corners[(k + 1) % corners.size()];
    const int n = counts[k];
    for (int i = 0; i < n; ++i) p.push_back(a + (b - a) * (double(i) / n));
  }
  return p;
}

inline std::vector<V2> reversed(std::vector<V2> p) {
  std::reverse(p.begin() + 1, p.end());
  return p;
}

struct Stats {
  double min_sj = 2, median_sj = 0;
  int quads = 0, irregular = 0;
};

inline double sj(const std::vector<V2>& P, const std::array<int, 4>& q) {
  double m = 1;
  for (int k = 0; k < 4; ++k) {
    const V2 a = P[q[k]], b = P[q[(k + 1) % 4]], d = P[q[(k + 3) % 4]];
    const V2 e0 = b - a, e1 = d - a;
    m = std::min(m, (e0.x() * e1.y() - e0.y() * e1.x()) / (e0.norm() * e1.norm()));
  }
  return m;
}

/// Scaled Jacobians and irregular interior nodes (valence != 4).
inline Stats stats(const QuadMesh2D& m) {
  Stats s;
  std::vector<double> v;
  for (const auto& q : m.quads) v.push_back(sj(m.points, q));
  std::sort(v.begin(), v.end());
  s.quads = static_cast<int>(v.size());
  if (!v.empty()) {
    s.min_sj = v.front();
    s.median_sj = v[v.size() / 2];
  }
  std::vector<int> val(m.points.size(), 0);
  for (const auto& q : m.quads) {
    for (int x : q) ++val[static_cast<size_t>(x)];
  }
  for (size_t i = static_cast<size_t>(m.boundary_count); i < val.size(); ++i)
    s.irregular += val[i] != 4;
  return s;
}

struct NamedFace {
  const char* name;
  Loops loops;
  bool simple;  // quality bars asserted (median > 0.8, min > 0.3)
};

/// pave's named 2D test faces (pave_2d_test, bench/pave_cleanup_table.cpp).
inline std::vector<NamedFace> benchmark_faces() {
  std::vector<NamedFace> f;
  f.push_back({"square", {polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {10, 10, 10, 10})}, true});
  f.push_back(
      {"square, odd sides", {polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {7, 7, 7, 7})}, true});
  f.push_back({"disk", {circle({0, 0}, 1, 40)}, true});
  f.push_back({"annulus", {circle({0, 0}, 2, 48), circle({0, 0}, 1, 24, true)}, true});
  f.push_back(
      {"plate with three holes",
       {polygon({{0, 0}, {4, 0}, {4, 2}, {0, 2}}, {24, 12, 24, 12}), circle({1, 1}, 0.4, 16, true),
        circle({2.2, 1}, 0.3, 12, true), circle({3.2, 0.8}, 0.25, 4, true)},
       true});
  f.push_back({"L-shape",
               {polygon({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}, {12, 6, 6, 6, 6, 12})},
               true});
  f.push_back({"narrow neck",
               {polygon({{0, 0},
                         {1, 0},
                         {1, 0.45},
                         {2, 0.45},
                         {2, 0},
                         {3, 0},
                         {3, 1},
                         {2, 1},
                         {2, 0.55},
                         {1, 0.55},
                         {1, 1},
                         {0, 1}},
                        {10, 5, 10, 5, 10, 10, 10, 5, 10, 5, 10, 10})},
               false});
  f.push_back(
      {"spacing 1:8",
       {polygon({{-4, -4}, {4, -4}, {4, 4}, {-4, 4}}, {8, 8, 8, 8}), circle({0, 0}, 1, 50, true)},
       false});
  return f;
}

/// Empty when the mesh is a valid all-quad mesh of the loops: boundary nodes
/// first and unchanged, every quad counter-clockwise (positive scaled
/// Jacobian), every boundary edge used once in its loop direction, every
/// interior edge used twice in opposite directions, total area matches.
inline std::string check_mesh(const Loops& loops, const QuadMesh2D& m) {
  std::ostringstream err;
  size_t i = 0;
  for (const auto& l : loops) {
    for (const auto& p : l) {
      if (i >= m.points.size() || m.points[i] != p) {
        err << "boundary node " << i << " moved; ";
        return err.str();
      }
      ++i;
    }
  }
  if (m.boundary_count != static_cast<int>(i)) err << "boundary_count " << m.boundary_count << "; ";
  std::map<std::pair<int, int>, int> dir;
  double area = 0;
  for (size_t k = 0; k < m.quads.size(); ++k) {
    const auto& q = m.quads[k];
    for (int x : q) {
      if (x < 0 || x >= static_cast<int>(m.points.size())) return "bad node index";
    }
    if (sj(m.points, q) <= 0) err << "quad " << k << " inverted (sj " << sj(m.points, q) << "); ";
    for (int c = 0; c < 4; ++c) ++dir[{q[c], q[(c + 1) % 4]}];
    const V2 d1 = m.points[q[2]] - m.points[q[0]], d2 = m.points[q[3]] - m.points[q[1]];
    area += 0.5 * (d1.x() * d2.y() - d1.y() * d2.x());
  }
  std::set<std::pair<int, int>> boundary;
  double loop_area = 0;
  int base = 0;
  for (const auto& l : loops) {
    const int n = static_cast<int>(l.size());
    for (int k = 0; k < n; ++k) {
      boundary.insert({base + k, base + (k + 1) % n});
      const V2 a = l[k], b = l[(k + 1) % n];
      loop_area += 0.5 * (a.x() * b.y() - a.y() * b.x());
    }
    base += n;
  }
  for (const auto& [e, count] : dir) {
    if (count != 1) {
      err << "edge used " << count << " times; ";
      break;
    }
    const bool is_b = boundary.count(e) > 0;
    const bool twin = dir.count({e.second, e.first}) > 0;
    if (is_b == twin) {
      err << "edge " << e.first << "-" << e.second
          << (is_b ? " on boundary has a twin" : " is a free edge") << "; ";
      break;
    }
  }
  for (const auto& e : boundary) {
    if (!dir.count(e)) {
      err << "boundary edge " << e.first << "-" << e.second << " not used; ";
      break;
    }
  }
  if (std::abs(area - loop_area) > 1e-8 * std::max(1.0, std::abs(loop_area))) {
    err << "area " << area << " != " << loop_area << "; ";
  }
  return err.str();
}

/// Distance from q to the closed polygon p.
inline double distance_to_polygon(const V2& q, const std::vector<V2>& p) {
  double d = 1e300;
  for (size_t k = 0; k < p.size(); ++k) {
    const V2 a = p[k], b = p[(k + 1) % p.size()];
    const double t =
        std::clamp((q - a).dot(b - a) / std::max((b - a).squaredNorm(), 1e-300), 0.0, 1.0);
    d = std::min(d, (q - (a + t * (b - a))).norm());
  }
  return d;
}

/// True when q lies inside the closed polygon p (crossing number).
inline bool inside_polygon(const V2& q, const std::vector<V2>& p) {
  bool in = false;
  for (size_t k = 0, j = p.size() - 1; k < p.size(); j = k++) {
    if ((p[k].y() > q.y()) != (p[j].y() > q.y()) &&
        q.x() < (p[j].x() - p[k].x()) * (q.y() - p[k].y()) / (p[j].y() - p[k].y()) + p[k].x()) {
      in = !in;
    }
  }
  return in;
}

/// Corners and interval counts of a star-shaped polygon about c: k corners
/// at sorted random angles, radii in [rmin, rmax], edges cut into intervals
/// of about h (varying from edge to edge).
struct Star {
  std::vector<V2> corners;
  std::vector<int> counts;
  int total() const {
    int t = 0;
    for (int c : counts) t += c;
    return t;
  }
  std::vector<V2> points(bool cw) const {
    std::vector<V2> p = polygon(corners, counts);
    return cw ? reversed(p) : p;
  }
};

inline Star random_star(std::mt19937& rng, const V2& c, int k, double rmin, double rmax, double h) {
  std::uniform_real_distribution<double> U(0.0, 1.0);
  Star s;
  for (int i = 0; i < k; ++i) {
    const double a = 2 * M_PI * (i + 0.15 + 0.7 * U(rng)) / k;
    const double r = rmin + (rmax - rmin) * U(rng);
    s.corners.emplace_back(c.x() + r * std::cos(a), c.y() + r * std::sin(a));
  }
  for (size_t i = 0; i < s.corners.size(); ++i) {
    const double len = (s.corners[(i + 1) % s.corners.size()] - s.corners[i]).norm();
    const double local = h * (0.75 + 0.5 * U(rng));
    s.counts.push_back(std::max(1, static_cast<int>(std::lround(len / local))));
  }
  while (s.total() < 5) ++s.counts.back();
  return s;
}

/// A random face: non-convex star outer loop, 0..3 holes (stars or circles,
/// some with only 4 or 5 nodes). Loops may have odd node counts; the total
/// is always even (the outer loop takes the parity).
inline Loops random_face(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  const double h = 0.05 + 0.07 * U(rng);
  const int k = 4 + static_cast<int>(rng() % 8);
  Star outer = random_star(rng, V2(0, 0), k, 0.6, 1.0, h);
  const std::vector<V2> outer_points = outer.points(false);
  Loops holes;
  int total = 0;
  const int wanted = static_cast<int>(rng() % 4);
  std::vector<std::pair<V2, double>> placed;
  for (int attempt = 0; attempt < 40 && static_cast<int>(placed.size()) < wanted; ++attempt) {
    const double r = 0.06 + 0.16 * U(rng);
    const V2 c(-0.5 + U(rng), -0.5 + U(rng));
    const double hh = h * (0.5 + U(rng));  // holes may be finer or coarser than the outer loop
    const double gap = 1.5 * std::max(h, hh);
    if (!inside_polygon(c, outer_points) || distance_to_polygon(c, outer_points) < r + gap)
      continue;
    bool clear = true;
    for (const auto& [c2, r2] : placed) clear = clear && (c - c2).norm() > r + r2 + gap;
    if (!clear) continue;
    placed.emplace_back(c, r);
    const int kind = static_cast<int>(rng() % 4);
    if (kind == 0) {
      holes.push_back(
          random_star(rng, c, 3 + static_cast<int>(rng() % 5), 0.6 * r, r, hh).points(true));
    } else if (kind == 1) {
      const int n = std::max(5, static_cast<int>(std::lround(2 * M_PI * r / hh)));
      holes.push_back(circle(c, r, n, true));
    } else if (kind == 2) {
      holes.push_back(circle(c, 0.5 * r, 4, true));  // a small hole with 4 nodes
    } else {
      holes.push_back(circle(c, 0.6 * r, 5, true));  // a small odd hole
    }
    total += static_cast<int>(holes.back().size());
  }
  if ((outer.total() + total) % 2 != 0) ++outer.counts.back();
  Loops loops{outer.points(false)};
  loops.insert(loops.end(), holes.begin(), holes.end());
  return loops;
}

/// The face as text, for failure messages.
inline std::string describe(const Loops& loops) {
  std::ostringstream s;
  s.precision(17);
  for (size_t l = 0; l < loops.size(); ++l) {
    s << "loop " << l << " (" << loops[l].size() << " nodes):";
    for (const auto& p : loops[l]) s << " (" << p.x() << ", " << p.y() << ")";
    s << "\n";
  }
  return s.str();
}

}  // namespace cooperage::pave::testing
