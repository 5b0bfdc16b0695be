#include "framework/geometry/validate.h"

#include "framework/core/error.h"
#include "framework/core/text.h"

#include <cmath>
#include <cstdio>
#include <map>
#include <string>

namespace cooperage::geom {
namespace {

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

std::string point_text(const Vec3& p) { return cooperage::point_text(p.x(), p.y(), p.z()); }

[[noreturn]] void defect(EntityRef entity, const std::string& what) {
  throw MeshingError(ErrorCode::GeometryError, entity,
                     what + "; the B-rep is not valid, repair it in the CAD tool");
}

bool finite(double v) { return std::isfinite(v); }

void check_numbers(const Model& model) {
  for (const Vertex& v : model.vertices())
    if (!v.point.allFinite()) defect(EntityRef::vertex(v.id), "has a non-finite coordinate");
  for (const Curve& c : model.curves()) {
    if (!finite(c.length)) defect(EntityRef::curve(c.id), "has a non-finite length");
    const auto [t0, t1] = c.geometry->range();
    if (!finite(t0) || !finite(t1) || !(t0 < t1))
      defect(EntityRef::curve(c.id), "has an empty or non-finite parameter range");
  }
  for (const Surface& s : model.surfaces()) {
    if (!finite(s.area)) defect(EntityRef::surface(s.id), "has a non-finite area");
    if (!s.box.empty() && !(s.box.min.allFinite() && s.box.max.allFinite()))
      defect(EntityRef::surface(s.id), "has a non-finite bounding box");
  }
  for (const Volume& v : model.volumes()) {
    if (!finite(v.volume)) defect(EntityRef::volume(v.id), "has a non-finite volume");
  }
}

void check_not_empty(const Model& model, double tol) {
  for (const Curve& c : model.curves()) {
    if (c.start_vertex == c.end_vertex) continue;  // a closed curve may be short
    if (!(c.length > 0)) defect(EntityRef::curve(c.id), "has zero length");
  }
  for (const Surface& s : model.surfaces()) {
    if (!(s.area > tol * tol * 1e-6))
      defect(EntityRef::surface(s.id), "has no area (" + num(s.area) + ")");
  }
  for (const Volume& v : model.volumes()) {
    if (!(v.volume > 0)) defect(EntityRef::volume(v.id), "encloses no volume");
  }
}

void check_curve_ends(const Model& model, double tol) {
  for (const Curve& c : model.curves()) {
    const auto [t0, t1] = c.geometry->range();
    const struct {
      double t;
      int vertex;
      const char* end;
    } ends[] = {{t0, c.start_vertex, "starts"}, {t1, c.end_vertex, "ends"}};
    for (const auto& e : ends) {
      const Vec3 p = c.geometry->point(e.t);
      const Vec3& v = model.vertex(e.vertex).point;
      if (!p.allFinite()) defect(EntityRef::curve(c.id), "evaluates to a non-finite point");
      const double gap = (p - v).norm();
      if (gap > tol)
        defect(EntityRef::curve(c.id), std::string(e.end) + " at " + point_text(p) + ", " +
                                           num(gap) + " away from its vertex " +
                                           std::to_string(e.vertex) + " at " + point_text(v));
    }
  }
}

void check_curves_on_surfaces(const Model& model, double tol) {
  for (const Curve& c : model.curves()) {
    const auto [t0, t1] = c.geometry->range();
    const Vec3 mid = c.geometry->point(0.5 * (t0 + t1));
    if (!mid.allFinite()) defect(EntityRef::curve(c.id), "evaluates to a non-finite point");
    for (int sid : c.surfaces) {
      const SurfaceProjection p = model.surface(sid).geometry->project(mid);
      if (!p.point.allFinite())
        defect(EntityRef::surface(sid), "cannot be evaluated near curve " + std::to_string(c.id));
      if (p.distance > tol)
        defect(EntityRef::curve(c.id), "passes " + point_text(mid) + ", " + num(p.distance) +
                                           " away from surface " + std::to_string(sid) +
                                           ", which it bounds");
    }
  }
}

void check_closed_shells(const Model& model) {
  for (const Volume& v : model.volumes()) {
    for (const auto& shell : v.shells) {
      // curve -> (uses, signed sum of directions seen from the volume)
      std::map<int, std::pair<int, int>> uses;
      for (const SurfaceUse& su : shell) {
        for (const Loop& loop : model.surface(su.surface).loops) {
          for (const CurveUse& cu : loop.uses) {
            auto& u = uses[cu.curve];
            ++u.first;
            u.second += static_cast<int>(sign(su.sense) * sign(cu.sense));
          }
        }
      }
      for (const auto& [curve, u] : uses) {
        if (u.first == 1)
          defect(EntityRef::volume(v.id), "its boundary is open: curve " + std::to_string(curve) +
                                              " bounds only one of its surfaces");
        if (u.first != 2)
          defect(EntityRef::volume(v.id), "its boundary is not a manifold: curve " +
                                              std::to_string(curve) + " bounds " +
                                              std::to_string(u.first) + " of its surfaces");
        if (u.second != 0)
          defect(EntityRef::volume(v.id),
                 "its surfaces are not oriented consistently at curve " + std::to_string(curve));
      }
    }
  }
}

}  // namespace

double validation_tolerance(const Model& model) {
  const BoundingBox box = model.box();
  const double d =
      box.empty() || !box.min.allFinite() || !box.max.allFinite() ? 0.0 : box.diagonal();
  return std::max(1e-3 * d, 1e-7);
}

void validate(const Model& model) {
  model.validate();
  check_numbers(model);
  const double tol = validation_tolerance(model);
  check_not_empty(model, tol);
  check_curve_ends(model, tol);
  check_curves_on_surfaces(model, tol);
  check_closed_shells(model);
}

}  // namespace cooperage::geom
