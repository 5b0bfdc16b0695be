// A ring of side faces that spans several caps (Blacker 1996, sec. 4,
// Fig. 8): a step flush with an outer wall makes one wall face touch the
// step top, the shoulder and the bottom, and the front face run from the
// step top to the bottom past the shoulder. Rib formation stops at the
// shoulder's level (sec. 4: "as soon as any rib reaches another cap"), so
// the ring is split virtually at the level of every cap it touches: one
// segment per pair of caps at consecutive levels, with the sides whose
// extent covers it. A priori, on the model only.
#pragma once

#include "schemes/cooper/classify_faces.h"

#include <set>
#include <string>
#include <vector>

namespace cooperage::cooper {

/// One cap as the ring sees it.
struct RingCap {
  int id = 0;
  std::set<int> curves;
};

/// The part of a stepped ring between two caps at consecutive levels.
struct RingSegment {
  int upper = 0;  ///< cap at the higher level along the axis
  int lower = 0;  ///< cap at the next level down
  bool convex_upper = false;  ///< the segment's sides meet `upper` below pi
  bool convex_lower = false;  ///< ... `lower` below pi (else re-entrant: a virtual cap)
  std::vector<int> sides;     ///< surfaces whose extent covers the segment, ascending
  /// Linking chains running from `upper` to `lower` (chains spanning more
  /// than one segment are left to the sides' own submap constraints).
  std::vector<std::vector<int>> linking_chains;
};

struct SteppedRing {
  std::string why;  ///< empty on success
  /// Top segment first (highest level along `axis`).
  std::vector<RingSegment> segments;
  /// Every side once: source = its curves on all but its lowest cap, target =
  /// its curves on its lowest cap (upper runs = lower run, sec. 3).
  std::vector<SideFace> sides;
};

/// Splits the ring formed by `side_ids` (one connected set of submappable
/// sides) at the levels of the caps it touches, along `axis`.
SteppedRing split_stepped_ring(const geom::Model& model, int volume_id, const geom::Vec3& axis,
                               const std::vector<int>& side_ids, const std::vector<RingCap>& caps);

}  // namespace cooperage::cooper
