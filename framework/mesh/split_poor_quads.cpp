#include "framework/mesh/split_poor_quads.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>
#include <utility>

#include <Eigen/Geometry>

namespace cooperage::mesh {
namespace {

const Vec3& at(const std::vector<Vec3>& points, int n) { return points[static_cast<size_t>(n)]; }

// Verdict's quad centre normal (e0 - e2) x (e1 - e3), i.e. (c - a) x (d - b).
Vec3 quad_normal(const std::vector<Vec3>& points, const Quad& q) {
  return (at(points, q[2]) - at(points, q[0])).cross(at(points, q[3]) - at(points, q[1]));
}

}  // namespace

std::array<Tri, 2> split_quad(const std::vector<Vec3>& points, const Quad& q) {
  const Vec3 normal = quad_normal(points, q);
  const std::array<Tri, 2> ac{Tri{q[0], q[1], q[2]}, Tri{q[0], q[2], q[3]}};
  const std::array<Tri, 2> bd{Tri{q[1], q[2], q[3]}, Tri{q[1], q[3], q[0]}};
  auto worse = [&](const std::array<Tri, 2>& t) {
    return std::min(min_corner_sine(points, t[0].data(), 3, normal),
                    min_corner_sine(points, t[1].data(), 3, normal));
  };
  return worse(bd) > worse(ac) + 1e-9 ? bd : ac;
}

namespace {

// Two neighbouring triangles of different split quads may make a good quad
// (one half of each of two poor quads): merged, best quad first, so no two
// triangles left would make a quad of min_quality. Ties (qualities within
// 1e-9) go by triangle indices, so a moved mesh pairs the same way.
void merge_good_pairs(const std::vector<Vec3>& points, double min_quality, QuadDominant& m) {
  std::map<std::pair<int, int>, size_t> by_edge;  // directed edge -> triangle
  for (size_t t = 0; t < m.tris.size(); ++t) {
    for (int k = 0; k < 3; ++k) by_edge[{m.tris[t][k], m.tris[t][(k + 1) % 3]}] = t;
  }
  struct Candidate {
    double quality;
    size_t a, b;
    Quad quad;
  };
  std::vector<Candidate> candidates;
  for (size_t t = 0; t < m.tris.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const Tri& tri = m.tris[t];
      const int from = tri[k], to = tri[(k + 1) % 3], apex = tri[(k + 2) % 3];
      const auto twin = by_edge.find({to, from});
      if (twin == by_edge.end() || twin->second <= t) continue;  // each pair once
      const Tri& other = m.tris[twin->second];
      int far = other[0];
      for (int n : other) {
        if (n != from && n != to) far = n;
      }
      const Quad q{apex, from, far, to};
      const Vec3 normal = quad_normal(points, q);
      const Vec3 tri_normal =
          (at(points, from) - at(points, apex)).cross(at(points, to) - at(points, apex));
      if (!(normal.dot(tri_normal) > 0)) continue;
      const double quality = min_corner_sine(points, q.data(), 4, normal);
      if (quality >= min_quality)
        candidates.push_back({std::round(quality * 1e9), t, twin->second, q});
    }
  }
  std::sort(candidates.begin(), candidates.end(), [](const Candidate& x, const Candidate& y) {
    if (x.quality != y.quality) return x.quality > y.quality;
    return std::tie(x.a, x.b) < std::tie(y.a, y.b);
  });
  std::vector<char> used(m.tris.size(), 0);
  for (const Candidate& c : candidates) {
    if (used[c.a] || used[c.b]) continue;
    used[c.a] = used[c.b] = 1;
    m.quads.push_back(c.quad);
  }
  std::vector<Tri> left;
  for (size_t t = 0; t < m.tris.size(); ++t) {
    if (!used[t]) left.push_back(m.tris[t]);
  }
  m.tris = std::move(left);
}

}  // namespace

QuadDominant split_poor_quads(const std::vector<Vec3>& points, const std::vector<Quad>& quads,
                              double min_quality) {
  QuadDominant out;
  for (const Quad& q : quads) {
    if (min_corner_sine(points, q.data(), 4, quad_normal(points, q)) >= min_quality) {
      out.quads.push_back(q);
      continue;
    }
    for (const Tri& t : split_quad(points, q)) out.tris.push_back(t);
  }
  merge_good_pairs(points, min_quality, out);
  return out;
}

}  // namespace cooperage::mesh
