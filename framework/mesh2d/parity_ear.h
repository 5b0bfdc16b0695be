// The corner to cut off as one triangle when a domain's boundary has an odd
// number of nodes: no all-quad mesh exists then (every quad mesh has an
// even boundary), but the rest of the domain, one node fewer, has one. A
// quad-dominant mesher takes it (cooper's mixed elements: one column of
// wedges where imprinting left a subcap odd, Blacker 1996 sec. 5.3).
#pragma once

#include "framework/mesh2d/predicates.h"

#include <optional>
#include <vector>

namespace cooperage::mesh2d {

/// A boundary node (loop, index in it) whose two neighbours close a
/// triangle inside the domain: a convex corner (the domain on the loops'
/// left: outer loop counter-clockwise, holes clockwise) of a loop of at
/// least five nodes, whose triangle holds no other boundary node and whose
/// chord crosses no boundary edge. Of those, the corner nearest 60 degrees
/// (then the lowest loop and index); nullopt when none qualifies.
struct Ear {
  size_t loop = 0;
  size_t index = 0;
};
std::optional<Ear> parity_ear(const std::vector<std::vector<Point2>>& loops);

}  // namespace cooperage::mesh2d
