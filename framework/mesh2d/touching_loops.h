// Boundary loops that touch themselves or each other at a shared node (a
// hole tangent to the outer boundary and meeting it at a vertex, a loop
// through one vertex twice) are valid faces but no simple polygons. Here
// the loops that share a point are merged into one loop that passes the
// point twice, and each copy of the point is moved a little into its own
// corner (along the corner's bisector), so the loops become simple: a plane
// mesher meshes them, and the scheme maps both copies back to the one node.
#pragma once

#include <Eigen/Core>

#include <vector>

namespace cooperage::mesh2d {

/// Where a point of the separated loops came from.
struct LoopPointRef {
  int loop = 0;   ///< input loop
  int index = 0;  ///< point in that loop
};

struct SeparatedLoops {
  std::vector<std::vector<Eigen::Vector2d>> loops;  ///< outer loop first
  std::vector<std::vector<LoopPointRef>> source;    ///< per point of `loops`
  int moved = 0;                                    ///< copies moved apart
};

/// \param[in] loops     closed rings (outer counter-clockwise first, holes
///                      clockwise); points closer than `tolerance` are one
/// \param[in] fraction  a copy moves by this fraction of its shorter edge
SeparatedLoops separate_touching_points(const std::vector<std::vector<Eigen::Vector2d>>& loops,
                                        double tolerance, double fraction = 0.02);

}  // namespace cooperage::mesh2d
