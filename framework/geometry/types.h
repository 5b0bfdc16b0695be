// Small value types shared by the geometry layer.
#pragma once

#include <Eigen/Core>

#include <limits>
#include <string>

namespace cooperage::geom {

using Vec3 = Eigen::Vector3d;
using Vec2 = Eigen::Vector2d;

/// Orientation of a use of an entity: Forward follows the entity's own
/// parameterisation (curve) or natural normal (surface).
enum class Sense { Forward = 1, Reversed = -1 };

inline Sense flip(Sense s) { return s == Sense::Forward ? Sense::Reversed : Sense::Forward; }
inline double sign(Sense s) { return s == Sense::Forward ? 1.0 : -1.0; }

/// Axis-aligned bounding box; empty until a point is added.
struct BoundingBox {
  Vec3 min = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 max = Vec3::Constant(-std::numeric_limits<double>::infinity());

  bool empty() const { return min.x() > max.x(); }
  void add(const Vec3& p) {
    min = min.cwiseMin(p);
    max = max.cwiseMax(p);
  }
  void add(const BoundingBox& b) {
    if (b.empty()) return;
    add(b.min);
    add(b.max);
  }
  Vec3 size() const { return empty() ? Vec3::Zero() : Vec3(max - min); }
  double diagonal() const { return size().norm(); }
};

/// Geometric type of a curve, as the CAD kernel reports it.
enum class CurveType { Line, Circle, Ellipse, Hyperbola, Parabola, Bezier, BSpline, Offset, Other };
/// Geometric type of a surface, as the CAD kernel reports it.
enum class SurfaceType {
  Plane,
  Cylinder,
  Cone,
  Sphere,
  Torus,
  Bezier,
  BSpline,
  Revolution,
  Extrusion,
  Offset,
  Other
};

const char* to_string(CurveType type);    ///< "line", "circle", "bspline", ...
const char* to_string(SurfaceType type);  ///< "plane", "cylinder", "bspline", ...

}  // namespace cooperage::geom
