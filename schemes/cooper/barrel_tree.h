// The barrels of a volume (Blacker 1996, sec. 4): a barrel is a maximal run
// of slab regions whose cycles of sides pass from slab to slab unchanged
// with no cap in between ("as soon as any rib on the front reaches another
// existing cap, rib formation ceases"). Its upper cap is made of the real
// caps on its upper level and the virtual caps it shares with the barrels
// above (the lower cap "re-formed to contain subcaps which account for the
// attached caps", Fig. 8d); likewise its lower cap. The set is unique: it
// depends on the levels and cycles only, not on an order of formation.
// Plain data: testable without CAD.
#pragma once

#include "schemes/cooper/slab_regions.h"

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace cooperage::cooper {

/// A subcap of a barrel end: a real cap face, or a virtual cap shared with
/// another barrel (an interface).
struct EndPiece {
  int cap = 0;         ///< cap face id, or 0
  int interface = -1;  ///< index into BarrelTree::interfaces, or -1
};

/// A virtual cap: the lower end of barrel `above` meets the upper end of
/// barrel `below` there (the paper's "virtual face" of Fig. 2).
struct BarrelInterface {
  int above = -1;
  int below = -1;
};

struct BarrelNode {
  double top = 0;     ///< height of its upper level
  double bottom = 0;  ///< height of its lower level
  size_t first_slab = 0;
  size_t last_slab = 0;
  std::vector<int> sides;                ///< side faces of its cycles, ascending
  std::vector<std::vector<int>> cycles;  ///< face sets, the outer cycle first
  std::vector<EndPiece> upper;           ///< upper cap: real caps first, then virtual
  std::vector<EndPiece> lower;
  /// Level classes of its ends (one layer count from any of them).
  std::vector<int> upper_classes;
  std::vector<int> lower_classes;
};

struct BarrelTree {
  bool ok = false;
  std::string why;
  std::vector<BarrelNode> barrels;  ///< upper level highest first (ties: first side)
  std::vector<BarrelInterface> interfaces;
  /// cap -> (barrel, true when in its upper cap)
  std::map<int, std::pair<int, bool>> cap_end;
};

/// A one-to-one sweep's caps (upper, lower): one barrel from one real cap
/// to one real cap; (0, 0) for any other tree.
inline std::pair<int, int> one_to_one_caps(const BarrelTree& tree) {
  if (tree.barrels.size() != 1) return {0, 0};
  const BarrelNode& barrel = tree.barrels.front();
  if (barrel.upper.size() != 1 || barrel.lower.size() != 1) return {0, 0};
  const int upper = barrel.upper.front().cap, lower = barrel.lower.front().cap;
  return upper && lower ? std::make_pair(upper, lower) : std::make_pair(0, 0);
}

BarrelTree form_barrel_tree(const VolumeFacts& facts, const SideLattice& lattice,
                            const SweepOrder& order, const SlabRegions& slabs);

}  // namespace cooperage::cooper
