#include "schemes/submap/facing_edges.h"

#include "schemes/submap/directions.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <string>

namespace cooperage::submap {
namespace {

using geom::Vec3;
using Expr = std::map<int, int>;  // curve id -> coefficient

struct Edge {
  int curve = 0;
  int axis = 0;            // 0: runs along i, 1: along j
  double a0 = 0, a1 = 0;   // extent along its axis (geometric, a0 < a1)
  double b = 0;            // geometric coordinate across its axis
  std::array<Expr, 2> at;  // lattice (i, j) of its start, in curve counts
};

// Even-odd point in the polygon of the loop's vertices (in axis coordinates).
bool inside(const std::vector<std::array<double, 2>>& poly, double x, double y) {
  bool in = false;
  for (size_t k = 0, m = poly.size() - 1; k < poly.size(); m = k++) {
    const auto& p = poly[k];
    const auto& q = poly[m];
    if ((p[1] > y) != (q[1] > y) && x < (q[0] - p[0]) * (y - p[1]) / (q[1] - p[1]) + p[0]) in = !in;
  }
  return in;
}

}  // namespace

// cite: Whiteley et al. 1996 (submapping): the interval counts must give a
// valid region; here the part of that the loop balance leaves open.
void add_facing_edge_constraints(const geom::Model& model, int surface_id, const LoopPlan& loop,
                                 intervals::IntervalProblem& problem) {
  const size_t n = loop.uses.size();
  if (n < 4 || n > 64 || loop.directions.size() != n) return;
  std::vector<Vec3> start(n), end(n);
  double scale = 0;
  for (size_t k = 0; k < n; ++k) {
    const geom::Curve& c = model.curve(loop.uses[k].curve);
    const bool forward = loop.uses[k].sense == geom::Sense::Forward;
    start[k] = model.vertex(forward ? c.start_vertex : c.end_vertex).point;
    end[k] = model.vertex(forward ? c.end_vertex : c.start_vertex).point;
    const double chord = (end[k] - start[k]).norm();
    if (c.start_vertex == c.end_vertex || std::abs(c.length - chord) > 1e-6 * c.length + 1e-12)
      return;
    scale = std::max(scale, chord);
  }
  const double aligned = std::cos(20.0 * 3.14159265358979323846 / 180.0);
  // The axes: the chords of the + curves minus those of the - curves.
  std::array<Vec3, 2> axis = {Vec3::Zero(), Vec3::Zero()};
  for (size_t k = 0; k < n; ++k) {
    const int d = loop.directions[k];
    axis[static_cast<size_t>(d % 2)] += (d < 2 ? 1.0 : -1.0) * (end[k] - start[k]);
  }
  if (axis[0].norm() <= 1e-9 * scale || axis[1].norm() <= 1e-9 * scale) return;
  for (auto& a : axis) a.normalize();
  const Vec3 normal = axis[0].cross(axis[1]);
  if (normal.norm() < 0.1) return;  // axes nearly parallel: no reliable picture
  const double tol = 1e-6 * scale;
  for (size_t k = 0; k < n; ++k) {
    if (std::abs((start[k] - start[0]).dot(normal.normalized())) > 1e3 * tol) return;  // not planar
  }
  // Every curve within 20 degrees of its axis: the picture is a plain
  // rectilinear polygon, whose facing curves the lattice must keep apart.
  for (size_t k = 0; k < n; ++k) {
    const Vec3 chord = end[k] - start[k];
    if (std::abs(chord.dot(axis[static_cast<size_t>(loop.directions[k] % 2)])) <
        aligned * chord.norm())
      return;
  }
  std::vector<std::array<double, 2>> poly(n);
  for (size_t k = 0; k < n; ++k) poly[k] = {start[k].dot(axis[0]), start[k].dot(axis[1])};
  // Lattice position of every use's start: the counts walked before it.
  std::vector<Edge> edges;
  std::array<Expr, 2> at;
  for (size_t k = 0; k < n; ++k) {
    const int d = loop.directions[k];
    const int along = d % 2;
    Edge e;
    e.curve = loop.uses[k].curve;
    e.axis = along;
    const double s = start[k].dot(axis[static_cast<size_t>(along)]);
    const double t = end[k].dot(axis[static_cast<size_t>(along)]);
    e.a0 = std::min(s, t);
    e.a1 = std::max(s, t);
    e.b = 0.5 * (start[k] + end[k]).dot(axis[static_cast<size_t>(1 - along)]);
    e.at = at;
    edges.push_back(e);
    at[static_cast<size_t>(along)][e.curve] += d < 2 ? 1 : -1;
  }
  for (size_t p = 0; p < edges.size(); ++p) {
    for (size_t q = p + 1; q < edges.size(); ++q) {
      const Edge& ep = edges[p];
      const Edge& eq = edges[q];
      if (ep.axis != eq.axis || std::abs(ep.b - eq.b) <= tol) continue;
      const double lo = std::max(ep.a0, eq.a0), hi = std::min(ep.a1, eq.a1);
      if (hi - lo <= tol) continue;
      const double m = 0.5 * (lo + hi);
      const Edge& near = ep.b < eq.b ? ep : eq;
      const Edge& far = ep.b < eq.b ? eq : ep;
      // They face each other: the segment between them at m is inside the
      // face and no curve along the same axis lies between them there.
      const double mid_b = 0.5 * (near.b + far.b);
      const double x = ep.axis == 0 ? m : mid_b, y = ep.axis == 0 ? mid_b : m;
      if (!inside(poly, x, y)) continue;
      bool blocked = false;
      for (const Edge& r : edges) {
        if (&r == &ep || &r == &eq || r.axis != ep.axis) continue;
        if (r.b > near.b + tol && r.b < far.b - tol && r.a0 < m && r.a1 > m) blocked = true;
      }
      if (blocked) continue;
      // far - near >= 1 across the axis.
      const size_t across = static_cast<size_t>(1 - ep.axis);
      Expr diff = far.at[across];
      for (const auto& [curve, k] : near.at[across]) diff[curve] -= k;
      std::vector<intervals::LinearTerm> terms;
      for (const auto& [curve, k] : diff) {
        if (k != 0) terms.push_back({curve, k});
      }
      if (terms.empty()) continue;
      problem.add_linear(std::move(terms), intervals::Sense::GreaterEqual, 1,
                         "surface " + std::to_string(surface_id) + " (submap) curves " +
                             std::to_string(near.curve) + " and " + std::to_string(far.curve) +
                             " keep a row of cells between them");
    }
  }
}

}  // namespace cooperage::submap
