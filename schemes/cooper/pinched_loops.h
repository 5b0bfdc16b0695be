// Subcaps whose loops touch at a node (Blacker 1996, sec. 5.2 and 6.1): two
// bosses meeting at a corner leave the top's remainder with an outer loop
// and a hole through one vertex, and subtraction carries that shape to the
// opposing subcaps. A polygon mesher needs rings without repetition, so the
// loops are joined at each touching node into one loop that passes the node
// twice, and each pass is moved a little into its own wedge of the domain;
// the mesh's copies are the node again (each copy is a corner of its wedge).
#pragma once

#include "schemes/cooper/imprint_polygons.h"

#include <map>
#include <vector>

namespace cooperage::cooper {

/// Loops ready for a polygon mesher: positions and, for each position (loop
/// by loop), the node it stands for (a touching node appears once per pass).
struct UnpinchedLoops {
  std::vector<std::vector<Vec2>> points;
  std::vector<int> nodes;
  int pinches = 0;  ///< touching nodes passed twice
};

/// \param[in] loops node loops of one domain, outer first counter-clockwise,
///   holes clockwise (oriented_loops()); a node may repeat across or within loops.
/// \param[in] xy node positions [model units].
/// \param[in] nudge how far a repeated pass moves into its wedge, as a
///   fraction of its shorter boundary edge.
UnpinchedLoops unpinch_loops(const std::vector<std::vector<int>>& loops,
                             const std::map<int, Vec2>& xy, double nudge = 0.02);

}  // namespace cooperage::cooper
