// Where subcap imprinting stopped, for a person (issue 16, item 5: an error
// says where). The rims left unmatched on the two ends of a barrel come
// closest where features meet: where they cross, or where one passes the
// other by a sliver (campaign parts whose features were drawn 0.01-0.06
// apart at element sizes of 1-4). The gap alone does not tell those apart
// (a node beside a clean crossing is as close), so it names a place only.
#pragma once

#include "schemes/cooper/imprint_subcaps.h"

#include <limits>

namespace cooperage::cooper {

struct ImprintSite {
  int node = -1;           ///< node (of r.ends) at the closest approach; -1: none
  Vec2 at = Vec2::Zero();  ///< where, in the barrel's chart
  /// Its distance from the other end's rim (model units); infinity: none.
  double gap = std::numeric_limits<double>::infinity();
  /// Mean edge of the unmatched subcaps' loops: the local element size.
  double edge = 0.0;
};

/// The closest approach between the loops of the upper and the lower
/// subcaps `r` left unmatched: a node of one end off an edge of the other
/// by the least distance above a millionth of their mean edge (a node on
/// the edge up to rounding, or a shared node, is a contact, not a gap).
/// Nodes of the exterior ribs (r.ends.ribs but r.interior_ribs) and edges
/// between two of them are left out: the outer rims are joined already.
/// Without unmatched subcaps on both ends, node -1.
ImprintSite narrowest_gap(const ImprintResult& r);

}  // namespace cooperage::cooper
