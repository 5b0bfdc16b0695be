// SurfaceGeometry over an OCCT face. Holds the immutable Geom_Surface (with
// the face location applied) and the face's parameter box; projectors are
// created per call, so the evaluator is safe to share across threads.
#include "framework/geometry/occ/detail.h"

#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <GeomLProp_SLProps.hxx>
#include <Geom_Surface.hxx>
#include <ShapeAnalysis_Surface.hxx>

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

class FaceSurface final : public geom::SurfaceGeometry {
 public:
  explicit FaceSurface(const TopoDS_Face& face)
      : surface_(BRep_Tool::Surface(face)), flip_(face.Orientation() == TopAbs_REVERSED) {
    BRepTools::UVBounds(face, u0_, u1_, v0_, v1_);
    type_ = surface_type(GeomAdaptor_Surface(surface_).GetType());
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
    const gp_Pnt q = to_pnt(p);
    double u = 0.5 * (u0_ + u1_), v = 0.5 * (v0_ + v1_);
    bool found = false;
    try {
      GeomAPI_ProjectPointOnSurf proj(q, surface_, u0_, u1_, v0_, v1_);
      if (proj.NbPoints() > 0) {
        proj.LowerDistanceParameters(u, v);
        found = true;
      }
    } catch (const Standard_Failure&) {
    }
    if (!found) {
      ShapeAnalysis_Surface sas(surface_);
      const gp_Pnt2d uv = sas.ValueOfUV(q, 1e-9);
      u = uv.X();
      v = uv.Y();
    }
    u = std::clamp(u, u0_, u1_);
    v = std::clamp(v, v0_, v1_);
    geom::SurfaceProjection out;
    out.uv = Vec2(u, v);
    out.point = point(out.uv);
    out.normal = normal(out.uv);
    out.distance = (p - out.point).norm();
    return out;
  }

 private:
  Handle(Geom_Surface) surface_;
  bool flip_ = false;
  double u0_ = 0, u1_ = 0, v0_ = 0, v1_ = 0;
  geom::SurfaceType type_ = geom::SurfaceType::Other;
};

}  // namespace

std::shared_ptr<const geom::SurfaceGeometry> make_surface_geometry(const TopoDS_Face& face) {
  return std::make_shared<FaceSurface>(face);
}

}  // namespace cooperage::occ::detail
