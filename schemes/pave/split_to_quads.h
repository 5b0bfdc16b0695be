// All-quad refinement of a mixed quad/triangle mesh (step (d) of the pave
// pipeline, pave_2d.h): every quad becomes 4 quads and every triangle 3 quads
// through its edge midpoints and centroid (cells that lost midpoints to a
// parity path become 1, 2 or 3 quads). Edges on the boundary loops do not
// get a new midpoint: their midpoint is the boundary node the coarse loop
// skipped, so the boundary keeps exactly its given nodes.
#pragma once

#include "schemes/pave/quad_quality_2d.h"
#include "schemes/pave/recombine.h"

#include <Eigen/Core>

#include <cstdint>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace cooperage::pave::detail {

/// Key of the undirected edge {a, b}.
inline std::uint64_t undirected_key(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) |
         static_cast<std::uint32_t>(b);
}

/// \param[in]     cells           coarse cells over coarse point ids
/// \param[in]     coarse_points   coarse point positions
/// \param[in]     fine_of_coarse  fine node of each coarse point, -1 for a new node
/// \param[in]     edge_midpoint   coarse edge key -> fine node (given for loop edges; the
///                                other edges' midpoints are new nodes, not added here)
/// \param[in,out] fine_points     fine node positions; new nodes are appended
/// \param[out]    quads           counter-clockwise fine quads
/// \param[in]     no_midpoint     coarse edges without midpoint (parity_paths.h); their
///                                cells become 1, 2 or 3 quads
void split_to_quads(const std::vector<Cell>& cells,
                    const std::vector<Eigen::Vector2d>& coarse_points,
                    std::vector<int> fine_of_coarse,
                    const std::unordered_map<std::uint64_t, int>& edge_midpoint,
                    std::vector<Eigen::Vector2d>& fine_points, std::vector<Quad>& quads,
                    const std::unordered_set<std::uint64_t>& no_midpoint = {});

}  // namespace cooperage::pave::detail
