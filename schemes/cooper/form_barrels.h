// Barrel formation by rib propagation (Blacker 1996, sec. 4): ribs start at
// the upper cap's boundary nodes and advance one complete layer at a time
// down the submapped side meshes, each rib extending to the only attached
// node not yet in a rib, until a rib reaches a node of another cap. Value
// types only: testable without CAD.
#pragma once

#include "framework/mesh/mesh_db.h"

#include <string>
#include <vector>

namespace cooperage::cooper {

struct BarrelInput {
  /// Quads of all side faces, as node indices (any orientation, any order).
  std::vector<mesh::Quad> side_quads;
  /// Boundary nodes of the upper cap, loop by loop, each loop in order
  /// without repeating its first node.
  std::vector<std::vector<int>> upper_loops;
  /// Nodes of the other caps (sorted or not); a rib stops on reaching one.
  std::vector<int> stop_nodes;
  /// Side nodes already in the ribs of a barrel above (a side face spanning
  /// several barrels, sec. 4 Fig. 8): never taken by a rib.
  std::vector<int> blocked_nodes;
  /// 0: stop at the first layer where a rib reaches a stop node. Else the
  /// layer count known from the plan: advance exactly that many layers and
  /// fail when a rib reaches a stop node earlier.
  int layers = 0;
};

struct Barrel {
  bool ok = false;
  std::string why;  ///< reason for !ok (no entity prefix)
  /// ribs[r] = node chain of rib r from the upper cap down, layers + 1 nodes;
  /// ribs follow upper_loops' order (loop 0 first).
  std::vector<std::vector<int>> ribs;
  int layers = 0;
  /// True when every rib ended on a stop node: the terminated ribs form the
  /// lower cap (a one-to-one barrel). False: some ribs ended elsewhere
  /// (the barrel ends on several caps: many-to-one, part II).
  bool all_ribs_on_stop_nodes = false;
};

/// Forms one barrel from its upper cap. Deterministic and independent of the
/// order of side_quads (the side graph is built as sorted adjacency).
/// Fails (ok false) when a rib end has no or several unused neighbours (an
/// irregular side mesh) or a rib runs into another rib.
Barrel form_barrels(const BarrelInput& input);

}  // namespace cooperage::cooper
