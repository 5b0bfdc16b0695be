// SurfaceGeometry over an OCCT face. Holds the immutable Geom_Surface (with
// the face location applied), the face's parameter box and its projector
// (surface_projector.h: closed forms, a warm-started Newton step, and OCCT's
// global projector kept per thread), so it is safe to share across threads.
#include "framework/geometry/occ/detail.h"
#include "framework/geometry/occ/shape_memo.h"
#include "framework/geometry/occ/surface_projector.h"

#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <GeomLProp_SLProps.hxx>
#include <Geom_Surface.hxx>

#include <algorithm>
#include <cmath>

namespace cooperage::occ::detail {
namespace {

geom::SurfaceType surface_type(GeomAbs_SurfaceType t) {
  switch (t) {
    case GeomAbs_Plane: return geom::SurfaceType::Plane;
    case GeomAbs_Cylinder: return geom::SurfaceType::Cylinder;
    case GeomAbs_Cone: return geom::SurfaceType::Cone;
    case GeomAbs_Sphere: return geom::SurfaceType::Sphere;
    case GeomAbs_Torus: return geom::SurfaceType::Torus;
    case GeomAbs_BezierSurface: return geom::SurfaceType::Bezier;
    case GeomAbs_BSplineSurface: return geom::SurfaceType::BSpline;
    case GeomAbs_SurfaceOfRevolution: return geom::SurfaceType::Revolution;
    case GeomAbs_SurfaceOfExtrusion: return geom::SurfaceType::Extrusion;
    case GeomAbs_OffsetSurface: return geom::SurfaceType::Offset;
    default: return geom::SurfaceType::Other;
  }
}

// A face's projector, kept for the calling thread while the face lives on in
// later models: a decomposition builds a model of every trial's pieces, most
// of whose faces are the uncut faces of the solid, and each new projector
// built OCCT's sampling grid again for its first global projection
// (occt_CrankArm --dim 3: 11 % of a refusal). A projector's answers depend
// on the query alone, so sharing it changes no result. Fewer entries than
// face_facts keeps: a B-spline face's projector holds sample grids.
using KnownProjectors = ShapeMemo<std::shared_ptr<const SurfaceProjector>, 4096>;

class FaceSurface final : public geom::SurfaceGeometry {
 public:
  explicit FaceSurface(const TopoDS_Face& face)
      : surface_(BRep_Tool::Surface(face)), flip_(face.Orientation() == TopAbs_REVERSED) {
    BRepTools::UVBounds(face, u0_, u1_, v0_, v1_);
    type_ = surface_type(GeomAdaptor_Surface(surface_).GetType());
    if (const auto* known = KnownProjectors::find(face)) {
      projector_ = *known;
    } else {
      projector_ = std::make_shared<const SurfaceProjector>(surface_, u0_, u1_, v0_, v1_);
      KnownProjectors::remember(face, projector_);
    }
  }

  geom::SurfaceType type() const override { return type_; }

  Vec3 point(const Vec2& uv) const override { return to_vec3(surface_->Value(uv.x(), uv.y())); }

  Vec3 normal(const Vec2& uv) const override {
    // At singular points (apex, pole) step towards the box centre.
    const Vec2 centre(0.5 * (u0_ + u1_), 0.5 * (v0_ + v1_));
    for (double step : {0.0, 1e-9, 1e-6, 1e-4, 1e-2}) {
      const Vec2 q = uv + step * (centre - uv);
      GeomLProp_SLProps props(surface_, q.x(), q.y(), 1, 1e-12);
      if (props.IsNormalDefined()) {
        const Vec3 n = to_vec3(props.Normal());
        return flip_ ? Vec3(-n) : n;
      }
    }
    return Vec3::Zero();
  }

  std::pair<Vec2, Vec2> uv_bounds() const override { return {Vec2(u0_, u1_), Vec2(v0_, v1_)}; }

  geom::SurfaceProjection project(const Vec3& p) const override {
    return at(p, projector_->closest(to_pnt(p)));
  }

  geom::SurfaceProjection project_near(const Vec3& p, const Vec2& uv_hint) const override {
    const gp_Pnt q = to_pnt(p);
    if (auto uv = projector_->closed_form(q)) return at(p, *uv);
    if (auto uv = projector_->newton(q, uv_hint)) return at(p, *uv);
    return at(p, projector_->closest(q));
  }

 private:
  Handle(Geom_Surface) surface_;
  bool flip_ = false;
  double u0_ = 0, u1_ = 0, v0_ = 0, v1_ = 0;
  geom::SurfaceType type_ = geom::SurfaceType::Other;
  std::shared_ptr<const SurfaceProjector> projector_;

  geom::SurfaceProjection at(const Vec3& p, const Vec2& uv) const {
    geom::SurfaceProjection out;
    out.uv = uv;
    // Point and normal from one first-derivative evaluation (a second one,
    // and GeomLProp's, cost as much as the projection on a B-spline face);
    // where the tangents are parallel (apex, pole) normal() steps aside.
    gp_Pnt s;
    gp_Vec su, sv;
    projector_->d1(uv.x(), uv.y(), s, su, sv);
    out.point = to_vec3(s);
    const gp_Vec n = su.Crossed(sv);
    if (n.Magnitude() > 1e-12 * su.Magnitude() * sv.Magnitude()) {
      const Vec3 unit = to_vec3(n) / n.Magnitude();
      out.normal = flip_ ? Vec3(-unit) : unit;
    } else {
      out.normal = normal(uv);
    }
    out.distance = (p - out.point).norm();
    return out;
  }
};

}  // namespace

std::shared_ptr<const geom::SurfaceGeometry> make_surface_geometry(const TopoDS_Face& face) {
  return std::make_shared<FaceSurface>(face);
}

}  // namespace cooperage::occ::detail
