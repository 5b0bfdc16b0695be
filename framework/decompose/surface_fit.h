// The analytic shape of a planar or cylindrical face, read back from its
// evaluator (point/normal), so the decomposition can extend the face into a
// cutting surface without asking the CAD kernel.
#pragma once

#include "framework/geometry/model.h"

#include <optional>

namespace cooperage::decompose {

using geom::Vec3;

/// A plane through `point` with unit `normal`.
struct Plane {
  Vec3 point = Vec3::Zero();
  Vec3 normal = Vec3::UnitZ();
};

/// A circular cylinder: axis through `point` along unit `axis`, `radius`.
struct Cylinder {
  Vec3 point = Vec3::Zero();
  Vec3 axis = Vec3::UnitZ();
  double radius = 0.0;
};

/// The plane of a surface whose geometry is a plane; nullopt otherwise.
std::optional<Plane> plane_of(const geom::Surface& surface);

/// The cylinder of a surface whose geometry is a cylinder; nullopt
/// otherwise. Found from three points of one parameter line that lies on a
/// circle (whichever of u and v runs round the axis).
std::optional<Cylinder> cylinder_of(const geom::Surface& surface);

/// A torus's axis: `point` and `axis` of the circle its u lines run round
/// (through the middle of the face), `radius` that circle's; nullopt for
/// other surfaces or a face too short round the axis to fit one.
std::optional<Cylinder> torus_axis_of(const geom::Surface& surface);

/// Circle through three points: centre, unit normal of their plane, radius;
/// nullopt when they are (nearly) collinear.
std::optional<Cylinder> circle_through(const Vec3& a, const Vec3& b, const Vec3& c);

/// Signed distance of p from the plane (positive on the normal's side).
double signed_distance(const Plane& plane, const Vec3& p);
/// Signed distance of p from the cylinder (positive outside).
double signed_distance(const Cylinder& cylinder, const Vec3& p);

}  // namespace cooperage::decompose
