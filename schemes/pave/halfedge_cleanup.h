// Topological clean-up of a 2D all-quad mesh on OpenMesh's half-edge mesh
// (issue 19 item 5): the array clean-up of cleanup_2d.h (doublets, diamonds)
// plus edge rotation, which needs the two quads of an edge and the rings of
// their corners, i.e. half-edge navigation.
//
// Operations (Canann, Muthukrishnan & Phillips 1996; edge rotation as the
// "edge swap" of Kinney 1997 / the "rotation" of Anderson et al. 2008):
//  * doublet: a free node in exactly two quads; the two quads merge into one;
//  * diamond: a quad between two free valence-3 nodes a, c; c is merged into
//    a at the middle of the diagonal (two irregular nodes become one regular);
//  * edge rotation: two quads sharing an edge form a hexagon; the shared edge
//    moves to one of the hexagon's other two diagonals.
// Every change is judged by the irregularity of the nodes it touches (the sum
// of |quads - ideal|: ideal 4 inside, FASTQ's count for the angle on the
// boundary, as irregular_nodes() counts) and kept only when that sum drops
// without more nodes deviating (a doublet is always removed: its sum always
// drops, and no smoothing can mend its two flat angles) and the changed
// quads stay valid: worst scaled
// Jacobian above zero and not below min(threshold, worst before). Boundary
// (fixed) nodes never move and are never removed.
//
// Working mesh: OpenMesh::PolyMesh_ArrayKernelT with z = 0, built from the
// arrays and written back to them; no OCCT header may meet this file's (the
// Handle macro breaks OpenMesh).
#pragma once

#include "schemes/pave/quad_quality_2d.h"

#include <Eigen/Core>

#include <vector>

namespace cooperage::pave::detail {

struct HalfEdgeCleanupOptions {
  /// A change may leave its quads' worst scaled Jacobian below the worst
  /// before only down to this (the smoothing that follows repairs shape,
  /// not topology).
  double min_quality = 0.2;
  int max_passes = 8;  ///< rounds of (doublets, diamonds, rotations)
  bool rotate = true;  ///< edge rotation (off: doublets and diamonds only)
  /// Let diamonds and rotations change how many quads a boundary node has
  /// (off: only free nodes' counts change, doublets aside).
  bool boundary_counts = true;
};

/// Number of changes of each kind made.
struct HalfEdgeCleanupCounts {
  int doublets = 0;
  int diamonds = 0;
  int rotations = 0;
};

/// Cleans up the counter-clockwise quads over `points` on a half-edge mesh.
/// Nodes no quad uses any more are dropped; the others keep their order, so
/// the fixed (boundary) nodes keep their indices when they come first.
/// \param[in,out] points, quads, fixed  the mesh (fixed[i] != 0: never moved
///                or removed)
/// \throws std::runtime_error when the half-edge mesh cannot hold the quads
///         (a non-manifold input) or a change cannot be applied
HalfEdgeCleanupCounts halfedge_cleanup(std::vector<Eigen::Vector2d>& points,
                                       std::vector<Quad>& quads, std::vector<char>& fixed,
                                       const HalfEdgeCleanupOptions& options = {});

}  // namespace cooperage::pave::detail
