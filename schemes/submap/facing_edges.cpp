#include "schemes/submap/facing_edges.h"

#include "schemes/submap/directions.h"
#include "schemes/submap/uv_chart.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <string>

namespace cooperage::submap {
namespace {

using geom::Vec3;
using Expr = std::map<int, int>;  // curve id -> coefficient

struct Edge {
  int curve = 0;
  int axis = 0;            // 0: runs along i, 1: along j
  double a0 = 0, a1 = 0;   // extent along its axis (geometric, a0 < a1)
  double b = 0;            // geometric coordinate across its axis (its chord's middle)
  bool aligned = true;     // its chord within 20 degrees of its axis
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

// The loop drawn in lattice-aligned coordinates: per use, its start and
// end (x along lattice axis i, y along j, each growing with its axis).
struct Picture {
  std::vector<std::array<double, 2>> start, end;
  double scale = 0;  ///< the largest extent: tolerances are relative to it
  /// Per use: its chord runs within 20 degrees of its axis. A planar face
  /// with slanted curves (a lug's conical underside cut by a wall: lines at
  /// 36 degrees) is drawn all the same, but only its aligned curves are
  /// paired, and as preferences.
  std::vector<char> aligned;
  bool all_aligned() const {
    return std::all_of(aligned.begin(), aligned.end(), [](char a) { return a != 0; });
  }
};

// A planar face of straight curves: the chords along the lattice's axes.
std::optional<Picture> planar_picture(const geom::Model& model, const LoopPlan& loop) {
  const size_t n = loop.uses.size();
  std::vector<Vec3> start(n), end(n);
  double scale = 0;
  for (size_t k = 0; k < n; ++k) {
    const geom::Curve& c = model.curve(loop.uses[k].curve);
    const bool forward = loop.uses[k].sense == geom::Sense::Forward;
    start[k] = model.vertex(forward ? c.start_vertex : c.end_vertex).point;
    end[k] = model.vertex(forward ? c.end_vertex : c.start_vertex).point;
    const double chord = (end[k] - start[k]).norm();
    if (c.start_vertex == c.end_vertex || std::abs(c.length - chord) > 1e-6 * c.length + 1e-12)
      return std::nullopt;
    scale = std::max(scale, chord);
  }
  const double aligned = std::cos(20.0 * 3.14159265358979323846 / 180.0);
  // The axes: the chords of the + curves minus those of the - curves.
  std::array<Vec3, 2> axis = {Vec3::Zero(), Vec3::Zero()};
  for (size_t k = 0; k < n; ++k) {
    const int d = loop.directions[k];
    axis[static_cast<size_t>(d % 2)] += (d < 2 ? 1.0 : -1.0) * (end[k] - start[k]);
  }
  if (axis[0].norm() <= 1e-9 * scale || axis[1].norm() <= 1e-9 * scale) return std::nullopt;
  for (auto& a : axis) a.normalize();
  const Vec3 normal = axis[0].cross(axis[1]);
  if (normal.norm() < 0.1) return std::nullopt;  // axes nearly parallel: no reliable picture
  const double tol = 1e-6 * scale;
  for (size_t k = 0; k < n; ++k) {
    if (std::abs((start[k] - start[0]).dot(normal.normalized())) > 1e3 * tol)
      return std::nullopt;  // not planar
  }
  // Every curve within 20 degrees of its axis: the picture is a plain
  // rectilinear polygon, whose facing curves the lattice must keep apart.
  Picture out;
  for (size_t k = 0; k < n; ++k) {
    const Vec3 chord = end[k] - start[k];
    out.aligned.push_back(std::abs(chord.dot(axis[static_cast<size_t>(loop.directions[k] % 2)])) >=
                          aligned * chord.norm());
  }
  out.scale = scale;
  for (size_t k = 0; k < n; ++k) {
    out.start.push_back({start[k].dot(axis[0]), start[k].dot(axis[1])});
    out.end.push_back({end[k].dot(axis[0]), end[k].dot(axis[1])});
  }
  return out;
}

// A face whose every curve is a line of constant u or constant v of its
// parameters (a cylinder's circles about its axis and lines along it; a
// cone's): its parameters, unwrapped along the loop, are an exact picture.
std::optional<Picture> parametric_picture(const geom::Model& model, int surface_id,
                                          const LoopPlan& loop) {
  const geom::Surface& surface = model.surface(surface_id);
  if (!surface.geometry) return std::nullopt;
  const UvChart chart(*surface.geometry);
  constexpr int kSamples = 8;  // per curve: arcs below a period unwrap step by step
  const size_t n = loop.uses.size();
  std::vector<std::vector<Vec2>> samples(n);
  Vec2 previous = Vec2::Zero();
  bool first = true;
  for (size_t k = 0; k < n; ++k) {
    const geom::Curve& c = model.curve(loop.uses[k].curve);
    if (!c.geometry || c.start_vertex == c.end_vertex) return std::nullopt;
    const auto [t0, t1] = c.geometry->range();
    const bool forward = loop.uses[k].sense == geom::Sense::Forward;
    for (int j = 0; j <= kSamples; ++j) {
      const double f = static_cast<double>(forward ? j : kSamples - j) / kSamples;
      const Vec2 uv = chart.uv(c.geometry->point(t0 + f * (t1 - t0)));
      previous = first ? uv : chart.shift_near(uv, previous);
      first = false;
      samples[k].push_back(previous);
    }
  }
  Vec2 lo = samples[0][0], hi = lo;
  for (const auto& use : samples)
    for (const Vec2& uv : use) {
      lo = lo.cwiseMin(uv);
      hi = hi.cwiseMax(uv);
    }
  const Vec2 tol = 1e-6 * (hi - lo) + Vec2::Constant(1e-12);
  // Closed in the unwrapped picture (a band around a cylinder is not).
  const Vec2 gap = samples.back().back() - samples.front().front();
  if (std::abs(gap.x()) > 1e3 * tol.x() || std::abs(gap.y()) > 1e3 * tol.y()) return std::nullopt;
  // Each lattice axis is one parameter, growing with it or against it.
  std::array<int, 2> component = {-1, -1};
  std::array<double, 2> sign = {0, 0};
  for (size_t k = 0; k < n; ++k) {
    const Vec2 d = samples[k].back() - samples[k].front();
    const int c =
        std::abs(d.x()) / (hi.x() - lo.x() + 1e-300) >= std::abs(d.y()) / (hi.y() - lo.y() + 1e-300)
            ? 0
            : 1;
    const size_t a = static_cast<size_t>(loop.directions[k] % 2);
    if (component[a] < 0) component[a] = c;
    if (component[a] != c) return std::nullopt;
    // Its samples keep the other parameter: an iso-parametric line.
    const int other = 1 - c;
    for (const Vec2& uv : samples[k]) {
      if (std::abs(uv[other] - samples[k].front()[other]) > 1e3 * tol[other]) return std::nullopt;
    }
    sign[a] += (loop.directions[k] < 2 ? 1.0 : -1.0) * d[c];
  }
  if (component[0] < 0 || component[1] < 0 || component[0] == component[1]) return std::nullopt;
  if (sign[0] == 0 || sign[1] == 0) return std::nullopt;
  Picture out;
  out.scale = std::max(hi.x() - lo.x(), hi.y() - lo.y());
  const auto draw = [&](const Vec2& uv) {
    return std::array<double, 2>{std::copysign(1.0, sign[0]) * uv[component[0]],
                                 std::copysign(1.0, sign[1]) * uv[component[1]]};
  };
  for (size_t k = 0; k < n; ++k) {
    out.start.push_back(draw(samples[k].front()));
    out.end.push_back(draw(samples[k].back()));
  }
  out.aligned.assign(n, 1);
  return out;
}

}  // namespace

// cite: Whiteley et al. 1996 (submapping): the interval counts must give a
// valid region; here the part of that the loop balance leaves open.
void add_facing_edge_constraints(const geom::Model& model, int surface_id, const LoopPlan& loop,
                                 intervals::IntervalProblem& problem) {
  const size_t n = loop.uses.size();
  if (n < 4 || n > 64 || loop.directions.size() != n) return;
  std::optional<Picture> picture = planar_picture(model, loop);
  const bool planar = picture.has_value();
  if (!picture) picture = parametric_picture(model, surface_id, loop);
  if (!picture) return;
  const double tol = 1e-6 * picture->scale;
  const std::vector<std::array<double, 2>>& poly = picture->start;
  // Lattice position of every use's start: the counts walked before it.
  std::vector<Edge> edges;
  std::array<Expr, 2> at;
  for (size_t k = 0; k < n; ++k) {
    const int d = loop.directions[k];
    const int along = d % 2;
    Edge e;
    e.curve = loop.uses[k].curve;
    e.axis = along;
    e.aligned = picture->aligned[k] != 0;
    const double s = picture->start[k][static_cast<size_t>(along)];
    const double t = picture->end[k][static_cast<size_t>(along)];
    e.a0 = std::min(s, t);
    e.a1 = std::max(s, t);
    e.b = 0.5 * (picture->start[k][static_cast<size_t>(1 - along)] +
                 picture->end[k][static_cast<size_t>(1 - along)]);
    e.at = at;
    edges.push_back(e);
    at[static_cast<size_t>(along)][e.curve] += d < 2 ? 1 : -1;
  }
  const auto point_inside = [&](int axis, double along, double across) {
    return axis == 0 ? inside(poly, along, across) : inside(poly, across, along);
  };
  for (size_t p = 0; p < edges.size(); ++p) {
    for (size_t q = p + 1; q < edges.size(); ++q) {
      const Edge& ep = edges[p];
      const Edge& eq = edges[q];
      if (ep.axis != eq.axis || std::abs(ep.b - eq.b) <= tol) continue;
      // A slanted curve's place across its axis is not one number.
      if (!ep.aligned || !eq.aligned) continue;
      const double lo = std::max(ep.a0, eq.a0), hi = std::min(ep.a1, eq.a1);
      const Edge& near = ep.b < eq.b ? ep : eq;
      const Edge& far = ep.b < eq.b ? eq : ep;
      const double mid_b = 0.5 * (near.b + far.b);
      double m = 0.5 * (lo + hi);
      if (hi - lo > tol) {
        // They face each other: the segment between them at m is inside
        // the face and no curve along the same axis lies between them there.
        if (!point_inside(ep.axis, m, mid_b)) continue;
      } else if (hi - lo > -tol) {
        // They meet at one level, one on each side of it (a wall's edge
        // going up from where another comes down, a hole's wall cut open
        // under a boss that continues it): the face runs on both sides of
        // the segment between their ends, so the ends must not share a
        // lattice point either.
        const double step = 1e-3 * picture->scale;
        if (!point_inside(ep.axis, m - step, mid_b) || !point_inside(ep.axis, m + step, mid_b))
          continue;
      } else {
        continue;
      }
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
      // A row asking one count to be at least 1 asks nothing every count
      // does not give; left out, it cannot move the solver's answer.
      if (terms.empty() || (terms.size() == 1 && terms.front().coeff == 1)) continue;
      const std::string label = "surface " + std::to_string(surface_id) + " (submap) curves " +
                                std::to_string(near.curve) + " and " + std::to_string(far.curve) +
                                " keep a row of cells between them";
      // The rows of a rectilinear planar face are needs (session 33). The
      // others (off a plane, or beside slanted curves) are preferences:
      // answers that keep them stay as they are (a row CBC does not need can
      // move its answer within its gap: 7/46 at size 3.0 lost a step of its
      // imprinting), and where no answer keeps them the face fails at mesh
      // time as it did without them.
      if (planar) {
        problem.add_linear(std::move(terms), intervals::Sense::GreaterEqual, 1, label);
      } else {
        problem.add_preference(std::move(terms), intervals::Sense::GreaterEqual, 1, label);
      }
    }
  }
}

}  // namespace cooperage::submap
