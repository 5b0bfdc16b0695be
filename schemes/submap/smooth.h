// Guarded smoothing of a quad surface mesh: length-weighted Laplacian sweeps
// over the free nodes with projection onto the surface. Topology never
// changes, and a move is rejected when an adjacent quad's scaled Jacobian
// (against the surface normal) would drop below `min_quality`, or below its
// previous value when it already was lower.
#pragma once

#include <array>
#include <functional>
#include <vector>

#include "framework/geometry/evaluators.h"
#include "framework/mesh/mesh_db.h"

namespace cooperage::submap {

using geom::Vec3;

struct SmoothOptions {
  int sweeps = 4;            ///< Laplacian sweeps over all free nodes
  double min_quality = 0.2;  ///< scaled Jacobian floor a move must respect
};

/// Projection of a point onto the surface (closest point and unit normal).
/// `node` is the node being moved, so the caller can start a local search
/// from where that node was (geom::SurfaceGeometry::project_near).
using Projector = std::function<geom::SurfaceProjection(const Vec3& point, size_t node)>;

/// Scaled Jacobian of a quad against a normal: the minimum over its corners
/// of the sine of the corner angle between unit edges, signed by `normals`
/// (one per corner). 1 for a square, <= 0 when inverted; -1 for a degenerate edge.
double quad_scaled_jacobian(const std::array<Vec3, 4>& p, const std::array<Vec3, 4>& normals);

/// The same for quad `q` of a mesh: its nodes in `x`, their normals.
double quad_scaled_jacobian(const std::vector<Vec3>& x, const std::vector<Vec3>& normals,
                            const mesh::Quad& q);

/// Smooths in place.
/// \param[in,out] x        node positions
/// \param[in,out] normals  unit surface normal per node (updated for moved nodes)
/// \param[in] fixed        per node: true for nodes that must not move (boundary)
/// \param[in] quads        elements over x, counter-clockwise about the normal
/// \param[in] project      projection onto the surface
void smooth_quads(std::vector<Vec3>& x, std::vector<Vec3>& normals, const std::vector<bool>& fixed,
                  const std::vector<mesh::Quad>& quads, const Projector& project,
                  const SmoothOptions& options = {});

}  // namespace cooperage::submap
