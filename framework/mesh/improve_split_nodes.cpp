#include "framework/mesh/improve_split_nodes.h"

#include "framework/mesh/split_poor_quads.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace cooperage::mesh {
namespace {

// An element around a node: its corners, their count and its normal at the
// start (the reference an inverted element would be measured against).
struct Element {
  std::array<int, 4> corners;
  int count;
  Vec3 normal;
};

double quality(const std::vector<Vec3>& points, const Element& e) {
  const double s = min_corner_sine(points, e.corners.data(), e.count, e.normal);
  return e.count == 3 ? s * 2.0 / std::sqrt(3.0) : s;
}

double worst(const std::vector<Vec3>& points, const std::vector<Element>& elements,
             const std::vector<int>& around) {
  double w = 2.0;
  for (int e : around) w = std::min(w, quality(points, elements[static_cast<size_t>(e)]));
  return w;
}

// The smallest margin of the quads around a node over their floors: negative
// when a move took a quad below its floor.
double quad_margin(const std::vector<Vec3>& points, const std::vector<Element>& elements,
                   const std::vector<int>& around, const std::vector<double>& floors) {
  double m = 1.0;
  for (size_t k = 0; k < around.size(); ++k) {
    const Element& e = elements[static_cast<size_t>(around[k])];
    if (e.count == 4) m = std::min(m, quality(points, e) - floors[k]);
  }
  return m;
}

}  // namespace

void improve_split_nodes(std::vector<Vec3>& points, const std::vector<Quad>& quads,
                         const std::vector<Tri>& tris, const std::vector<bool>& movable,
                         const std::function<Vec3(const Vec3&)>& project, double quad_floor,
                         int passes) {
  if (tris.empty()) return;
  std::set<int> target_set;
  for (const Tri& t : tris)
    for (int v : t)
      if (movable[static_cast<size_t>(v)]) target_set.insert(v);
  raise_worst_elements(points, quads, tris, std::vector<int>(target_set.begin(), target_set.end()),
                       project, quad_floor, passes);
}

void raise_worst_elements(std::vector<Vec3>& points, const std::vector<Quad>& quads,
                          const std::vector<Tri>& tris, const std::vector<int>& targets,
                          const std::function<Vec3(const Vec3&)>& project, double quad_floor,
                          int passes) {
  if (targets.empty()) return;
  std::vector<Element> elements;
  elements.reserve(quads.size() + tris.size());
  for (const Quad& q : quads) {
    const Vec3 n =
        (points[static_cast<size_t>(q[2])] - points[static_cast<size_t>(q[0])])
            .cross(points[static_cast<size_t>(q[3])] - points[static_cast<size_t>(q[1])]);
    elements.push_back({q, 4, n});
  }
  for (const Tri& t : tris) {
    const Vec3 n =
        (points[static_cast<size_t>(t[1])] - points[static_cast<size_t>(t[0])])
            .cross(points[static_cast<size_t>(t[2])] - points[static_cast<size_t>(t[0])]);
    elements.push_back({{t[0], t[1], t[2], -1}, 3, n});
  }
  // Elements and neighbours of the target nodes only (a few near each
  // split quad), indexed by their position in `targets`.
  std::map<int, size_t> slot;
  for (size_t k = 0; k < targets.size(); ++k) slot[targets[k]] = k;
  std::vector<std::vector<int>> around(targets.size());
  std::vector<std::set<int>> neighbours(targets.size());
  for (size_t e = 0; e < elements.size(); ++e) {
    const Element& el = elements[e];
    for (int k = 0; k < el.count; ++k) {
      const auto it = slot.find(el.corners[static_cast<size_t>(k)]);
      if (it == slot.end()) continue;
      around[it->second].push_back(static_cast<int>(e));
      neighbours[it->second].insert(el.corners[static_cast<size_t>((k + 1) % el.count)]);
      neighbours[it->second].insert(el.corners[static_cast<size_t>((k + el.count - 1) % el.count)]);
    }
  }
  for (int pass = 0; pass < passes; ++pass) {
    for (size_t t = 0; t < targets.size(); ++t) {
      Vec3& x = points[static_cast<size_t>(targets[t])];
      const std::vector<int>& mine = around[t];
      std::vector<Vec3> directions;
      double mean_length = 0;
      for (int u : neighbours[t]) {
        const Vec3 d = points[static_cast<size_t>(u)] - x;
        mean_length += d.norm();
        if (d.norm() > 0) {
          directions.push_back(d.normalized());
          directions.push_back(-d.normalized());
        }
      }
      if (directions.empty()) continue;
      mean_length /= static_cast<double>(neighbours[t].size());
      double best = worst(points, elements, mine);
      // Quads keep quad_floor, or their quality now when already below it.
      std::vector<double> floors;
      for (int e : mine) {
        floors.push_back(std::min(quad_floor, quality(points, elements[static_cast<size_t>(e)])) -
                         1e-12);
      }
      // Trials move in the tangent plane (the elements' mean normal), and
      // only the best of a round is passed through `project` (onto a
      // curved surface a projection costs far more than the trial).
      Vec3 tangent_normal = Vec3::Zero();
      for (int e : mine) tangent_normal += elements[static_cast<size_t>(e)].normal.normalized();
      if (tangent_normal.norm() > 0) tangent_normal.normalize();
      for (Vec3& d : directions) {
        d -= d.dot(tangent_normal) * tangent_normal;
        if (d.norm() > 0) d.normalize();
      }
      // Step from a fifth of the mean edge down to a thousandth of it; at
      // most 100 trial rounds, so a long run of tiny gains ends too.
      int rounds = 0;
      for (double step = 0.2 * mean_length; step > 1e-3 * mean_length && rounds < 100; ++rounds) {
        const Vec3 start = x;
        const double before = best;
        Vec3 best_x = start;
        for (const Vec3& d : directions) {
          if (!(d.norm() > 0)) continue;
          x = start + step * d;
          const double q = worst(points, elements, mine);
          if (q > best + 1e-12 && quad_margin(points, elements, mine, floors) >= 0) {
            best = q;
            best_x = x;
          }
        }
        if (best_x == start) {
          x = start;
          step *= 0.5;
          continue;
        }
        x = project(best_x);
        const double q = worst(points, elements, mine);
        if (q > before + 1e-12 && quad_margin(points, elements, mine, floors) >= 0) {
          best = q;
        } else {  // the surface took the gain back
          x = start;
          best = before;
          step *= 0.5;
        }
      }
    }
  }
}

QuadDominant make_quad_dominant(std::vector<Vec3>& points, const std::vector<Quad>& quads,
                                const std::vector<bool>& movable,
                                const std::function<Vec3(const Vec3&)>& project,
                                double min_quality) {
  QuadDominant out = split_poor_quads(points, quads, min_quality);
  improve_split_nodes(points, out.quads, out.tris, movable, project, min_quality);
  return out;
}

}  // namespace cooperage::mesh
