// Odd loops for pave_2d. A loop with an odd number of nodes leaves one
// coarse loop edge without a midpoint (coarse_loops.h). The quad count is
// only right when such edges come in pairs joined through the interior:
// every coarse edge a path of cells crosses also loses its midpoint. A cell
// crossed by a path then has 4 or 6 boundary nodes instead of 6 or 8 and is
// split into 1, 2 or 3 quads (split_to_quads.h). Paving does the same with
// its seams between fronts; only the total boundary count must be even.
#pragma once

#include "schemes/pave/recombine.h"

#include <Eigen/Core>

#include <cstdint>
#include <unordered_set>
#include <vector>

namespace cooperage::pave::detail {

/// Which triangles split_loop_triangles() splits.
enum class LoopTriangles {
  /// Those holding one odd loop edge and another loop edge that is not odd
  /// (a boundary ear): no path can leave them, since crossing one leaves a
  /// straight angle at the fixed midpoint of its other loop edge.
  OddEars,
  /// Every triangle with a loop edge that is not odd: paths may then pass
  /// anywhere (the fallback when parity_paths() finds no path).
  All,
};

/// Splits the chosen triangles at their centroids. Each of the three new
/// triangles has at most one loop edge, and a path passes by crossing two of
/// them through their interior edges, leaving only interior midpoints.
/// Appends the centroids to `points`; returns how many triangles were split.
int split_loop_triangles(std::vector<Cell>& cells, std::vector<Eigen::Vector2d>& points,
                         const std::vector<std::vector<int>>& loops,
                         const std::vector<std::uint64_t>& odd_edges, LoopTriangles which);

/// The coarse edges that get no midpoint: the odd loop edges and the edges
/// crossed by shortest cell paths pairing them (each odd edge is joined to
/// the nearest unpaired one, in cell steps). Throws std::runtime_error for an
/// odd number of odd edges or when no path exists.
std::unordered_set<std::uint64_t> parity_paths(const std::vector<Cell>& cells,
                                               const std::vector<std::uint64_t>& odd_edges);

}  // namespace cooperage::pave::detail
