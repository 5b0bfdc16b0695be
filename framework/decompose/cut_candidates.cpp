#include "framework/decompose/cut_candidates.h"

#include "framework/decompose/cone_candidates.h"
#include "framework/decompose/surface_fit.h"
#include "framework/decompose/volume_samples.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace cooperage::decompose {
namespace {

constexpr double kParallel = 1.0 - 1e-9;

void add_unique(std::vector<CutCandidate>& out, CutCandidate c, double tol) {
  for (const auto& k : out) {
    if (same_surface(k.surface, c.surface, tol)) return;
  }
  out.push_back(std::move(c));
}

std::string axis_text(const geom::Vec3& a) {
  static const char* names[] = {"x", "y", "z"};
  for (int k = 0; k < 3; ++k) {
    if (std::abs(std::abs(a[k]) - 1.0) < 1e-9) return names[k];
  }
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.4g %.4g %.4g)", a.x(), a.y(), a.z());
  return buf;
}

// Whether the straight curve c is a feature edge of the volume: the outward
// normals of its faces there differ by more than the angle.
bool is_feature(const geom::Model& model, int volume, int c, double angle_deg) {
  const std::vector<geom::Vec3> normals = outward_normals_at(model, volume, c);
  if (normals.size() != 2) return true;  // a seam or non-manifold: keep it
  return normals[0].dot(normals[1]) < std::cos(angle_deg * M_PI / 180.0);
}

// The meridian plane of a cylinder's axis holding the coordinate direction
// least along it: any meridian halves a solid of revolution alike.
CutCandidate meridian_of(const Cylinder& c, int surface) {
  int least = 0;
  for (int k = 1; k < 3; ++k) {
    if (std::abs(c.axis[k]) < std::abs(c.axis[least])) least = k;
  }
  const geom::Vec3 n = c.axis.cross(geom::Vec3::Unit(least)).normalized();
  return {{CutSurface::Kind::Plane, c.point, n, 0.0},
          "plane through the axis of surface " + std::to_string(surface)};
}

}  // namespace

std::vector<geom::Vec3> sweep_axes(const geom::Model& model, int volume) {
  std::vector<geom::Vec3> axes;
  std::vector<double> area;
  std::vector<int> order;
  const auto add = [&](const geom::Vec3& a, double w) {
    for (size_t k = 0; k < axes.size(); ++k) {
      if (std::abs(axes[k].dot(a)) >= kParallel) {
        area[k] += w;
        return;
      }
    }
    axes.push_back(a);
    area.push_back(w);
  };
  for (int s : model.surfaces_of(volume)) {
    const geom::Surface& surface = model.surface(s);
    if (auto p = plane_of(surface))
      add(p->normal, surface.area);
    else if (auto c = cylinder_of(surface))
      add(c->axis, surface.area);
  }
  for (size_t k = 0; k < axes.size(); ++k) order.push_back(static_cast<int>(k));
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    // Areas equal to 1e-9 relative count as ties (placement-independent).
    const double scale = std::max(area[a], area[b]);
    return area[a] > area[b] + 1e-9 * scale;
  });
  std::vector<geom::Vec3> out;
  for (int k : order) out.push_back(axes[k]);
  return out;
}

std::vector<CutCandidate> cut_candidates(const geom::Model& model, int volume,
                                         const CandidateOptions& options) {
  std::vector<CutCandidate> out;
  const double tol = options.tolerance;
  const std::vector<int> surfaces = model.surfaces_of(volume);
  for (int s : surfaces) {
    if (auto p = plane_of(model.surface(s))) {
      add_unique(out,
                 {{CutSurface::Kind::Plane, p->point, p->normal, 0.0},
                  "plane of surface " + std::to_string(s)},
                 tol);
    }
  }
  for (int s : surfaces) {
    if (auto c = cylinder_of(model.surface(s))) {
      add_unique(out,
                 {{CutSurface::Kind::Cylinder, c->point, c->axis, c->radius},
                  "cylinder of surface " + std::to_string(s)},
                 tol);
    }
  }
  std::vector<geom::Vec3> axes = sweep_axes(model, volume);
  if (static_cast<int>(axes.size()) > options.max_axes)
    axes.resize(static_cast<size_t>(options.max_axes));
  const std::vector<int> curves = curves_of(model, volume);
  for (const geom::Vec3& axis : axes) {
    for (int c : curves) {
      const geom::Curve& curve = model.curve(c);
      if (!curve.geometry || curve.geometry->type() != geom::CurveType::Line) continue;
      const auto [t0, t1] = curve.geometry->range();
      const geom::Vec3 a = curve.geometry->point(t0), b = curve.geometry->point(t1);
      if (!((b - a).norm() > tol)) continue;
      const geom::Vec3 d = (b - a).normalized();
      const geom::Vec3 n = d.cross(axis);
      if (n.norm() < 1e-6) continue;  // the edge runs along the axis
      if (!is_feature(model, volume, c, options.feature_angle_deg)) continue;
      add_unique(out,
                 {{CutSurface::Kind::Plane, a, n.normalized(), 0.0},
                  "plane through curve " + std::to_string(c) + " along " + axis_text(axis)},
                 tol);
    }
  }
  for (CutCandidate& c : cone_candidates(model, volume)) add_unique(out, std::move(c), tol);
  return out;
}

std::vector<CutCandidate> meridian_candidates(const geom::Model& model, int volume,
                                              const CandidateOptions& options) {
  std::vector<CutCandidate> out;
  for (int s : model.surfaces_of(volume)) {
    if (auto c = cylinder_of(model.surface(s)))
      add_unique(out, meridian_of(*c, s), options.tolerance);
  }
  // A torus's too: a ring (an O-ring, a toroidal tank) has no other face
  // to cut along, and its halves sweep round the axis.
  for (int s : model.surfaces_of(volume)) {
    if (auto c = torus_axis_of(model.surface(s)))
      add_unique(out, meridian_of(*c, s), options.tolerance);
  }
  return out;
}

std::vector<CoreCut> core_candidates(const geom::Model& model, int volume,
                                     const CandidateOptions& options) {
  // Coaxial cylinders: one entry per axis line, with the smallest radius.
  struct Axis {
    Cylinder smallest;
    int surface = 0;
  };
  std::vector<Axis> axes;
  for (int s : model.surfaces_of(volume)) {
    const auto c = cylinder_of(model.surface(s));
    if (!c) continue;
    bool known = false;
    for (Axis& a : axes) {
      const geom::Vec3 d = c->point - a.smallest.point;
      const bool parallel = std::abs(c->axis.dot(a.smallest.axis)) >= kParallel;
      if (!parallel || (d - d.dot(a.smallest.axis) * a.smallest.axis).norm() > options.tolerance)
        continue;
      known = true;
      if (c->radius < a.smallest.radius) a = {*c, s};
    }
    if (!known) axes.push_back({*c, s});
  }
  std::vector<CoreCut> out;
  for (const Axis& a : axes) {
    char radius[32];
    std::snprintf(radius, sizeof radius, "%.4g", 0.5 * a.smallest.radius);
    CoreCut cut;
    cut.core.surface.kind = CutSurface::Kind::Cylinder;
    cut.core.surface.origin = a.smallest.point;
    cut.core.surface.direction = a.smallest.axis;
    cut.core.surface.radius = 0.5 * a.smallest.radius;
    cut.core.through = "core cylinder r = " + std::string(radius) +
                       ", half the radius of surface " + std::to_string(a.surface);
    cut.meridian = meridian_of(a.smallest, a.surface);
    out.push_back(std::move(cut));
  }
  return out;
}

}  // namespace cooperage::decompose
