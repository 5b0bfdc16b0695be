#include "framework/intervals/curve_sizing.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <set>

namespace cooperage::intervals {
namespace {

using geom::Vec3;

/// A curve sampled at uniform parameters: points, tangents, arc-length
/// fractions (by chords) and the local sizes being built.
struct Sampled {
  std::vector<Vec3> p;
  std::vector<double> s;  ///< arc-length fraction of each sample
  double length = 0.0;
  double size = 1.0;      ///< the element size that applies
  std::vector<double> h;  ///< local size at each sample
  int min = 1;
  double turning = 0.0;
  geom::BoundingBox box;
};

double segment_distance(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double l2 = ab.squaredNorm();
  const double t = l2 > 0 ? std::clamp((p - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
  return (p - (a + t * ab)).norm();
}

double box_distance(const Vec3& p, const geom::BoundingBox& box) {
  const Vec3 d = (box.min - p).cwiseMax(p - box.max).cwiseMax(Vec3::Zero());
  return d.norm();
}

Sampled sample(const geom::Curve& curve, double size, const SizingOptions& options) {
  Sampled out;
  out.size = size;
  out.length = curve.length;
  const int n = std::max(2, options.samples);
  const auto [t0, t1] = curve.geometry->range();
  double turning = 0.0;
  Vec3 previous_tangent = Vec3::Zero();
  double arc = 0.0;
  for (int i = 0; i <= n; ++i) {
    const double t = t0 + (t1 - t0) * i / n;
    const Vec3 p = curve.geometry->point(t);
    if (i > 0) arc += (p - out.p.back()).norm();
    out.p.push_back(p);
    out.s.push_back(arc);
    out.box.add(p);
    const Vec3 tangent = curve.geometry->tangent(t);
    if (tangent.norm() > 0) {
      if (previous_tangent.norm() > 0) {
        turning +=
            std::atan2(previous_tangent.cross(tangent).norm(), previous_tangent.dot(tangent));
      }
      previous_tangent = tangent;
    }
  }
  for (double& s : out.s) s = arc > 0 ? s / arc : 0.0;
  out.s.back() = 1.0;
  const bool closed = curve.start_vertex == curve.end_vertex;
  const double per = options.turn_per_interval_deg * M_PI / 180.0;
  out.turning = turning;
  out.min = std::max(closed ? 2 : 1, static_cast<int>(std::ceil(turning / per - 1e-6)));
  out.h.assign(out.p.size(), size);
  return out;
}

/// Lowers c's sizes where curve d of a common face comes close: the
/// distance, unless d shares a vertex with c and the distance is only the
/// closeness near that vertex (a corner or a tangent contact, not a gap).
void apply_gap(Sampled& c, const geom::Curve& cc, const Sampled& d, const geom::Curve& dc,
               const geom::Model& model, const SizingOptions& options) {
  std::vector<Vec3> shared;
  for (int v : {cc.start_vertex, cc.end_vertex}) {
    if (v == dc.start_vertex || v == dc.end_vertex) shared.push_back(model.vertex(v).point);
  }
  for (size_t i = 0; i < c.p.size(); ++i) {
    const Vec3& p = c.p[i];
    if (box_distance(p, d.box) >= c.h[i] / options.gap_factor) continue;
    double dist = INFINITY;
    for (size_t k = 0; k + 1 < d.p.size(); ++k)
      dist = std::min(dist, segment_distance(p, d.p[k], d.p[k + 1]));
    if (!shared.empty()) {
      double r = INFINITY;
      for (const Vec3& v : shared) r = std::min(r, (p - v).norm());
      // Near the shared vertex the closeness is the corner's (refining a
      // tangent contact only makes its discrete angle sharper); farther
      // than twice the size, a narrow strip between the two curves.
      if (!(dist < 0.25 * r) || !(r > 2.0 * c.size)) continue;
    }
    c.h[i] = std::min(c.h[i], std::max(options.gap_factor * dist, options.min_fraction * c.size));
  }
}

}  // namespace

std::map<int, CurveSizing> curve_sizing(const geom::Model& model,
                                        const std::function<double(int)>& size_of,
                                        const SizingOptions& options) {
  std::vector<Sampled> sampled;
  sampled.reserve(model.curves().size());
  for (const geom::Curve& c : model.curves()) sampled.push_back(sample(c, size_of(c.id), options));
  auto of = [&](int id) -> Sampled& { return sampled[static_cast<size_t>(id - 1)]; };

  // Gaps between the curves of each face.
  for (const geom::Surface& s : model.surfaces()) {
    std::set<int> ids;
    for (const auto& loop : s.loops) {
      for (const auto& use : loop.uses) ids.insert(use.curve);
    }
    for (int a : ids) {
      for (int b : ids) {
        if (a != b) apply_gap(of(a), model.curve(a), of(b), model.curve(b), model, options);
      }
    }
  }
  // Sharp corners: the end's sample takes the bound; the grading below
  // spreads it along the curve and to the vertex's other curves.
  if (options.sharp_corners) {
    for (const EndSize& e : sharp_corner_sizes(model, size_of, options.corners)) {
      Sampled& sc = of(e.curve);
      double& h = e.at_start ? sc.h.front() : sc.h.back();
      h = std::min(h, e.size);
    }
  }
  // Small neighbours and grading: a vertex takes the smallest size of the
  // curve ends there (a short curve's whole length at most), and sizes grow
  // by at most `growth` per unit length; twice, so a vertex made smaller by
  // one curve's grading reaches the others.
  std::vector<double> vertex_size(model.vertices().size() + 1, INFINITY);
  for (int round = 0; round < 2; ++round) {
    for (const geom::Curve& c : model.curves()) {
      const Sampled& sc = of(c.id);
      double& a = vertex_size[static_cast<size_t>(c.start_vertex)];
      double& b = vertex_size[static_cast<size_t>(c.end_vertex)];
      a = std::min({a, sc.h.front(), c.length > 0 ? c.length : INFINITY});
      b = std::min({b, sc.h.back(), c.length > 0 ? c.length : INFINITY});
    }
    for (const geom::Curve& c : model.curves()) {
      Sampled& sc = of(c.id);
      const double ha = vertex_size[static_cast<size_t>(c.start_vertex)];
      const double hb = vertex_size[static_cast<size_t>(c.end_vertex)];
      const size_t n = sc.h.size();
      for (size_t i = 0; i < n; ++i) {
        const double s = sc.s[i] * sc.length;
        sc.h[i] =
            std::min({sc.h[i], ha + options.growth * s, hb + options.growth * (sc.length - s)});
      }
      for (size_t i = 1; i < n; ++i) {
        sc.h[i] =
            std::min(sc.h[i], sc.h[i - 1] + options.growth * (sc.s[i] - sc.s[i - 1]) * sc.length);
      }
      for (size_t i = n - 1; i-- > 0;) {
        sc.h[i] =
            std::min(sc.h[i], sc.h[i + 1] + options.growth * (sc.s[i + 1] - sc.s[i]) * sc.length);
      }
      for (double& h : sc.h) h = std::max(h, 1e-9 * sc.size);
    }
  }

  std::map<int, CurveSizing> out;
  for (const geom::Curve& c : model.curves()) {
    const Sampled& sc = of(c.id);
    CurveSizing z;
    z.min = sc.min;
    z.turning = sc.turning;
    z.sizes.at = sc.s;
    z.sizes.size = sc.h;
    z.goal = c.length > 0 ? z.sizes.intervals(c.length) : 1e-3;
    for (double h : sc.h) z.graded = z.graded || h < sc.size * (1.0 - 1e-9);
    out.emplace(c.id, std::move(z));
  }
  // Faceting: minima raised around round faces that would lose volume.
  std::map<int, TurningCurve> turning;
  for (const auto& [id, z] : out) {
    if (!(z.turning > 0)) continue;
    turning[id] = {z.turning, std::max(z.min, static_cast<int>(whole_goal(z.goal)))};
  }
  for (const auto& [id, n] : faceting_minima(model, turning, options.faceting)) {
    CurveSizing& z = out.at(id);
    z.min = std::max(z.min, n);
  }
  return out;
}

double whole_goal(double goal) { return std::floor(goal + 0.5 + 1e-9 * std::abs(goal)); }

}  // namespace cooperage::intervals
