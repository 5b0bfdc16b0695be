// The map between a surface and the plane of pave_2d (pave_2d.h).
//
// * Planar surfaces: an orthonormal frame of the plane: origin at the first
//   boundary node, x along the first boundary edge, y = natural normal x x.
//   Exact, and a rigidly moved face gives the same 2D coordinates.
// * Other surfaces: the surface parameters (u, v) of the boundary nodes from
//   project(), unwrapped continuously along each loop across the periodic
//   seam of a closed direction, and scaled per direction by the mean
//   |dS/du|, |dS/dv| over the boundary nodes (exact for a cylinder; an
//   approximation of the metric for cones and B-splines), with v negated if
//   S_u x S_v opposes the natural normal so that outer loops stay
//   counter-clockwise. Interior points go back through point(u, v).
// If the outer loop still comes out clockwise (the loops disagree with the
// normal), the plane is mirrored; the scheme then reverses the quads.
#pragma once

#include "framework/geometry/evaluators.h"

#include <Eigen/Core>

#include <vector>

namespace cooperage::pave {

class SurfaceTo2D {
 public:
  /// \param[in] surface  the face's geometry
  /// \param[in] loops    boundary node positions, loop by loop (closed rings,
  ///                     outer first, face on the left against the natural normal)
  SurfaceTo2D(const geom::SurfaceGeometry& surface,
              const std::vector<std::vector<geom::Vec3>>& loops);

  /// The loops in the plane (same order as given).
  const std::vector<std::vector<Eigen::Vector2d>>& loops_2d() const { return loops_2d_; }
  /// The surface point of a plane point (exact: planes map linearly, other
  /// surfaces through point(u, v); no projection needed).
  geom::Vec3 to_3d(const Eigen::Vector2d& x) const;
  /// The natural unit normal of the surface at a plane point.
  geom::Vec3 normal_at(const Eigen::Vector2d& x) const;
  bool planar() const { return planar_; }
  /// True when the plane coordinates were mirrored because the outer loop
  /// came out clockwise (a normal the loops disagree with): quads made
  /// counter-clockwise in the plane are then clockwise on the surface.
  bool mirrored() const { return mirrored_; }

 private:
  void mirror_if_clockwise();

  const geom::SurfaceGeometry& surface_;
  bool planar_ = false;
  bool mirrored_ = false;
  geom::Vec3 origin_, ex_, ey_, normal_;
  double su_ = 1.0, sv_ = 1.0;  // plane = (u * su_, v * sv_)
  std::vector<std::vector<Eigen::Vector2d>> loops_2d_;
};

}  // namespace cooperage::pave
