#include "framework/geometry/types.h"

namespace cooperage::geom {

const char* to_string(CurveType type) {
  switch (type) {
    case CurveType::Line: return "line";
    case CurveType::Circle: return "circle";
    case CurveType::Ellipse: return "ellipse";
    case CurveType::Hyperbola: return "hyperbola";
    case CurveType::Parabola: return "parabola";
    case CurveType::Bezier: return "bezier";
    case CurveType::BSpline: return "bspline";
    case CurveType::Offset: return "offset";
    case CurveType::Other: return "other";
  }
  return "other";
}

const char* to_string(SurfaceType type) {
  switch (type) {
    case SurfaceType::Plane: return "plane";
    case SurfaceType::Cylinder: return "cylinder";
    case SurfaceType::Cone: return "cone";
    case SurfaceType::Sphere: return "sphere";
    case SurfaceType::Torus: return "torus";
    case SurfaceType::Bezier: return "bezier";
    case SurfaceType::BSpline: return "bspline";
    case SurfaceType::Revolution: return "revolution";
    case SurfaceType::Extrusion: return "extrusion";
    case SurfaceType::Offset: return "offset";
    case SurfaceType::Other: return "other";
  }
  return "other";
}

}  // namespace cooperage::geom
