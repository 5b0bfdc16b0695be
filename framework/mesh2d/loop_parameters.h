// The boundary loops of a face in its parameter plane (u, v), made into
// polygons a plane mesher can use: continuous across the periodic seam of a
// closed direction (the seam curve is walked on both sides, so its nodes get
// two parameter copies), with every pole (a node where a whole parameter
// line collapses to a point: a cone apex, a sphere pole, a degenerate
// B-spline edge) opened into the segment of parameter space it really is,
// and holes shifted by whole periods into the outer loop.
//
// The winding of a pole's segment (which way round a periodic direction it
// runs) is chosen so that every loop closes without winding around the
// surface and the outer loop has the largest area; this is what the CAD
// kernel's p-curves say, recovered from the 3D nodes alone.
#pragma once

#include "framework/geometry/evaluators.h"

#include <Eigen/Core>

#include <vector>

namespace cooperage::mesh2d {

struct LoopParameters {
  /// Per loop, the polygon in (u, v): the nodes in loop order, a pole
  /// replaced by several points along its segment.
  std::vector<std::vector<Eigen::Vector2d>> uv;
  /// Per loop and polygon point: the index of its node in the loop (a pole's
  /// points all carry the pole node's index).
  std::vector<std::vector<int>> node;
  /// Per loop and polygon point: whether it is one of a pole's points.
  std::vector<std::vector<char>> pole;
  /// Periods of u and v (0: not closed in that direction).
  Eigen::Vector2d period = Eigen::Vector2d::Zero();
  /// +1 when S_u x S_v agrees with the natural normal (a loop counter-
  /// clockwise about the normal is counter-clockwise in (u, v)), else -1.
  double orientation = 1.0;
  bool has_poles() const {
    for (const auto& l : pole) {
      for (char c : l) {
        if (c) return true;
      }
    }
    return false;
  }
};

/// \param[in] surface  the face's geometry
/// \param[in] loops    the boundary nodes, loop by loop (closed rings, no
///                     repeated node; the face on the left against the
///                     natural normal; outer loop first)
/// \param[in] pole_points  points per pole segment (>= 2)
/// Throws MeshingError(MeshingFailed) when a loop winds around a closed
/// direction (no seam: no polygon in the parameter plane exists).
LoopParameters loop_parameters(const geom::SurfaceGeometry& surface,
                               const std::vector<std::vector<geom::Vec3>>& loops,
                               int pole_points = 2);

/// True when the face's surface closes on itself in direction dir (0: u, 1:
/// v): the points at both ends of the parameter box coincide.
bool closed_direction(const geom::SurfaceGeometry& surface, int dir);

/// The period of direction dir (0: not closed): a full turn (2 pi) for the u
/// of surfaces of revolution (cylinder, cone, sphere, torus, revolution) and
/// the v of a torus, whatever the face's box; else the box's extent when
/// closed_direction() holds.
double closed_period(const geom::SurfaceGeometry& surface, int dir);

}  // namespace cooperage::mesh2d
