// Untangling by corner areas (Knupp, "Hexahedral and tetrahedral mesh
// untangling", Eng. with Computers 17, 2001): every corner of every quad
// spans a signed area alpha (its two edges' cross product along the surface
// normal), and a free node moves to where the sum of max(0, beta - alpha)
// over the corners it touches is least. That sum is convex and piecewise
// linear in the node's position on its tangent plane, so its minimum lies at
// a vertex of the lines alpha = beta and is found exactly. A node may then
// worsen one quad to mend two: a fold whose undoing needs a row of nodes to
// move together comes undone over a few sweeps, where untangle_quads (each
// move must raise the node's worst quad) stops at the first node (a lug's
// cone over a block's graded corner edge, plan => mesh campaign seed 11
// case 66).
#pragma once

#include "framework/geometry/evaluators.h"
#include "framework/mesh/mesh_db.h"

#include <functional>
#include <vector>

namespace cooperage::mesh {

/// Projection of a point onto the surface (closest point and unit normal);
/// `node` is the node being moved (a local search may start from it).
using CornerProjector = std::function<geom::SurfaceProjection(const Vec3& point, size_t node)>;

struct CornerUntangleOptions {
  int sweeps = 100;          ///< passes over the nodes of tangled corners
  double beta_ratio = 0.05;  ///< beta as a fraction of the mean corner area
};

/// Moves free nodes in place until no corner's area is below beta (or the
/// sweeps run out). Only nodes of corners below beta move, in ascending order
/// (deterministic). Returns true when no quad is inverted afterwards (every
/// corner area positive).
/// \param[in,out] x        node positions
/// \param[in,out] normals  unit surface normal per node (updated for moved nodes)
/// \param[in] fixed        per node: true for nodes that must not move (boundary)
/// \param[in] quads        elements over x, counter-clockwise about the normal
/// \param[in] project      projection onto the surface
bool untangle_corners(std::vector<Vec3>& x, std::vector<Vec3>& normals,
                      const std::vector<bool>& fixed, const std::vector<Quad>& quads,
                      const CornerProjector& project, const CornerUntangleOptions& options = {});

}  // namespace cooperage::mesh
