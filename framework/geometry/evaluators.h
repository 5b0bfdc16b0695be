// Evaluator interfaces for curve and surface geometry. The CAD backend
// implements them; nothing here names a CAD kernel type.
#pragma once

#include "framework/geometry/types.h"

#include <utility>

namespace cooperage::geom {

/// A parametric curve restricted to the parameter range of its edge.
/// Implementations must be safe to call from several threads at once.
class CurveGeometry {
 public:
  virtual ~CurveGeometry() = default;
  virtual CurveType type() const = 0;
  /// Parameter range [t0, t1] of the edge, t0 < t1.
  virtual std::pair<double, double> range() const = 0;
  /// Point at parameter t.
  virtual Vec3 point(double t) const = 0;
  /// First derivative dC/dt at t (not normalised).
  virtual Vec3 tangent(double t) const = 0;
  /// Arc length between parameters a and b (a <= b), in model units.
  virtual double length(double a, double b) const = 0;
  /// Parameter of the point of the edge closest to p, within range().
  virtual double closest_parameter(const Vec3& p) const = 0;
  /// Parameter at arc length s from t0 (0 <= s <= length()).
  virtual double parameter_at_length(double s) const = 0;

  double length() const {
    const auto r = range();
    return length(r.first, r.second);
  }
};

/// Result of projecting a point onto a surface.
struct SurfaceProjection {
  Vec3 point = Vec3::Zero();   ///< closest point on the bounded face
  Vec3 normal = Vec3::Zero();  ///< unit normal there, the surface's natural orientation
  Vec2 uv = Vec2::Zero();      ///< surface parameters of point
  double distance = 0.0;       ///< |p - point|
};

/// A parametric surface restricted to its face. The natural normal is the
/// outward normal of the surface's first volume (see Surface).
/// Implementations must be safe to call from several threads at once.
class SurfaceGeometry {
 public:
  virtual ~SurfaceGeometry() = default;
  virtual SurfaceType type() const = 0;
  /// Closest point of the surface to p (within the face's parameter box).
  virtual SurfaceProjection project(const Vec3& p) const = 0;
  /// Closest point near a known position: `uv_hint` are the parameters of a
  /// point close to the answer (the node's previous position, a neighbour's
  /// parameters). Backends may run a local Newton step from it and fall back
  /// to the global search of project() when that step fails; the result is
  /// then the local minimum of the distance nearest the hint. The default is
  /// project(p), so implementations without a local solver stay correct.
  virtual SurfaceProjection project_near(const Vec3& p, const Vec2& uv_hint) const {
    (void)uv_hint;
    return project(p);
  }
  /// Point at parameters uv.
  virtual Vec3 point(const Vec2& uv) const = 0;
  /// Unit natural normal at parameters uv.
  virtual Vec3 normal(const Vec2& uv) const = 0;
  /// Parameter box of the face: (umin, umax), (vmin, vmax).
  virtual std::pair<Vec2, Vec2> uv_bounds() const = 0;
};

}  // namespace cooperage::geom
