// Many-to-one classification and barrel formation a priori (Blacker 1996,
// sec. 3-4), cooper part II. Faces are sorted into caps (facing a sweep
// axis) and sides (jointly submappable); side faces joined by linking curves
// form rings; a ring whose ends meet both caps at dihedral angles below pi
// is "closed" (it ends on two caps), a ring meeting one cap re-entrantly
// (above pi, e.g. a boss on a shoulder) ends in a virtual cap that fills a
// hole loop of that cap and becomes a subcap of the barrel below it.
// Barrels are the rings grouped by the cap they start from; they form a tree
// that flows into the one barrel ending on a real cap, the target. The
// result depends only on the model (ids and geometry), never on the order of
// the faces in the volume's shells (barrel uniqueness, sec. 4).
// A priori: never meshes (asks the registry's surface schemes applicable()).
#pragma once

#include "schemes/cooper/classify_faces.h"

#include <map>
#include <string>
#include <vector>

namespace cooperage::cooper {

/// One barrel of a many-to-one volume.
struct BarrelPlan {
  /// Real cap the barrel starts from (its upper cap; with the virtual caps
  /// of the `inflow` barrels as further subcaps in its hole loops).
  int upper = 0;
  /// Barrels (indices into ManyToOne::barrels, all earlier) whose virtual
  /// lower caps are subcaps of this barrel's upper cap.
  std::vector<int> inflow;
  /// Barrels whose virtual caps are subcaps of the real lower cap (a closed
  /// barrel with subcaps on both ends, e.g. appendages on top and bottom);
  /// then both real caps are meshed by cooper from imprinted subcaps.
  std::vector<int> lower_inflow;
  /// Real lower cap (the volume's target) or 0 for a virtual lower cap.
  int lower = 0;
  /// With lower == 0: the cap whose hole loop(s) the virtual lower cap fills.
  int into = 0;
  /// With lower == 0: the virtual lower cap lies beside `into` rather than in
  /// a hole loop of it (a step flush with an outer wall: the sides run on
  /// past `into`'s level, sec. 4 Fig. 8); the barrel below starts from the
  /// outer loop of `into` and this cap together. A flush barrel may also
  /// step up into the lower end of a closed barrel (a foot flush with a wall
  /// below): then that barrel has flush subcaps on its lower end.
  bool flush = false;
  /// Meshed from the middle (sec. 6.1: a stack is meshed once, from any of
  /// its caps): an open barrel whose virtual cap overlaps a subcap arriving
  /// on the other end of the barrel it flows into (an intersection, sec.
  /// 5.3). Its real cap is then meshed by cooper: the imprinted pieces are
  /// meshed in the barrel with subcaps on both ends and swept out to it.
  bool from_middle = false;
  std::vector<int> sides;  ///< side surfaces, ascending
  /// Linking chains of its sides (each must have the barrel's layer count).
  std::vector<std::vector<int>> linking_chains;
};

struct ManyToOne {
  bool ok = false;
  std::string why;        ///< a sentence naming the volume, faces and rule
  double score = 0.0;     ///< in [0.3, 0.45]: below every one-to-one score
  geom::Vec3 axis = geom::Vec3::Zero();  ///< sweep axis (unit, sign not meaningful)
  int target = 0;                        ///< the real lower cap, meshed by cooper
  /// Caps meshed by cooper (role kMeshedByVolume): the target, and the upper
  /// cap of a barrel with subcaps on both ends.
  std::vector<int> volume_caps;
  std::map<int, std::string> cap_schemes;  ///< every other cap -> map/submap/pave
  /// All sides, ascending; source_curves = upper run, target_curves = lower run.
  std::vector<SideFace> sides;
  /// Upstream first: a barrel comes after every barrel flowing into it; the
  /// last one ends on the target.
  std::vector<BarrelPlan> barrels;
  /// True when the rejection is the paper's Fig. 3a case (virtual faces in
  /// different directions): the user must decompose the volume.
  bool needs_decomposition = false;
};

/// Classifies a volume for a many-to-one sweep (several source caps, one
/// target) along one axis.
/// \param[in] hints  a direction hint ranks that axis first; source/target
///                   hints must agree with the result (else rejected)
/// \param[in] polygon_mesher_available  a barrel with subcaps on both ends
///                   needs its imprinted subcaps meshed in 2D (sec. 5.2, 6.1)
ManyToOne classify_barrels(const geom::Model& model, int volume_id,
                           const scheme::Registry& registry, const SweepHints& hints = {},
                           bool polygon_mesher_available = false);

}  // namespace cooperage::cooper
