// Topological cleanup of a 2D all-quad mesh (Canann, Muthukrishnan &
// Phillips 1996, "Topological refinement procedures for quadrilateral
// finite element meshes"; MeshKit QuadCleanUp): doublets (a free node shared
// by exactly two quads) are removed by merging their quads, and unused nodes
// are dropped; diamonds (a quad between two valence-3 nodes) are collapsed.
// Node order is kept, so fixed boundary nodes keep their indices.
#pragma once

#include "schemes/pave/quad_quality_2d.h"

#include <Eigen/Core>

#include <vector>

namespace cooperage::pave::detail {

/// Removes doublets at free nodes (fixed[i] == 0) and compacts the nodes.
/// \returns the number of doublets removed.
int remove_doublets(std::vector<Eigen::Vector2d>& points, std::vector<Quad>& quads,
                    std::vector<char>& fixed);

/// Diamond collapse: a quad whose two opposite free nodes a, c have valence
/// 3 while the other two have valences summing to 9 or more loses c into a
/// (at the middle of the diagonal): two irregular nodes become one regular
/// node. Kept only where the merged node's quads stay valid. Compacts the
/// nodes; returns the number of collapses.
int collapse_diamonds(std::vector<Eigen::Vector2d>& points, std::vector<Quad>& quads,
                      std::vector<char>& fixed);

/// Interior nodes whose valence is not 4, and boundary nodes whose valence
/// differs from the ideal for their angle (1 for < 135 deg, 2 below 225,
/// 3 below 315, else 4), as FASTQ's node classes would have it.
int irregular_nodes(const std::vector<Eigen::Vector2d>& points, const std::vector<Quad>& quads,
                    const std::vector<char>& fixed);

}  // namespace cooperage::pave::detail
