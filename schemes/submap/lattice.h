// The lattice fill of a submap face (ALGORITHMS.md sec. 1b): boundary nodes
// get integer lattice coordinates (i, j) by a cumulative walk along their
// curves' directions; interior lattice points inside the region get
// parameter values by blending the interpolations along their row and column
// between the boundary points they see; every unit cell inside the region is
// a quad. Value types only: testable without CAD.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "framework/geometry/types.h"

namespace cooperage::submap {

using geom::Vec2;
using LatticePoint = std::array<int, 2>;

/// Lattice coordinates of the nodes of one loop, by a cumulative walk.
/// \param[in] directions  direction (directions.h) of every use of the loop
/// \param[in] intervals   interval count of every use (>= 1)
/// \param[in] start       coordinates of the loop's first node
/// \return one point per node: the first node of use 0, then every further
///         node of every use; the node that closes the loop is not repeated.
///         `closure` receives the position the walk returns to (== start for
///         a balanced loop).
std::vector<LatticePoint> walk_loop(const std::vector<int>& directions,
                                    const std::vector<int>& intervals, LatticePoint start,
                                    LatticePoint* closure = nullptr);

/// A boundary node with its lattice coordinates and parameter value.
struct BoundaryPoint {
  LatticePoint ij{0, 0};
  int node = -1;  ///< the caller's node id (e.g. a MeshDB node), >= 0
  Vec2 uv = Vec2::Zero();
};

/// The filled lattice: boundary points and interior points, and the quads.
struct LatticeFill {
  bool ok = false;
  std::string why;               ///< why the lattice is not a valid region
  std::vector<LatticePoint> ij;  ///< per point
  std::vector<int> node;         ///< per point: boundary node id, -1 when interior
  std::vector<Vec2> uv;          ///< per point: given (boundary) or blended (interior)
  std::vector<std::array<int, 4>>
      cells;  ///< unit cells inside, point indices, counter-clockwise in (i, j)
};

/// How interior points get their parameters.
enum class FillInterior {
  Blend,   ///< every point blends its row and its column
  Blocks,  ///< the boundary edges at reentrant corners are extended first
           ///< (each cut line spaced as the nearest boundary chain beside it
           ///< over the same span, else evenly), cutting the region into
           ///< blocks whose points then blend between their block's sides only
};

/// Fills the region bounded by the loops (outer loop counter-clockwise in
/// (i, j), holes clockwise). The region's winding number must be 0 or 1 in
/// every cell and no two different nodes may share a lattice point (one node
/// at two points is fine: a seam). Interior point (i, j) gets
///   uv = (w_r * row + w_c * col) / (w_r + w_c),
/// row/col the linear interpolations between the boundary points hit going
/// -i/+i and -j/+j, w = 1 / (distance in index space to the nearer of the two).
LatticeFill fill_lattice(const std::vector<std::vector<BoundaryPoint>>& loops,
                         FillInterior interior = FillInterior::Blend);

/// True when the cells of `fill` cover its whole (i, j) box: one rectangular
/// block (a mapped face).
bool fills_its_box(const LatticeFill& fill);

}  // namespace cooperage::submap
