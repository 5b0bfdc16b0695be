// Corner types of a side face chosen with its neighbours (Blacker 1996,
// sec. 3, Fig. 4/5: the sides must be jointly submappable). A corner's angle
// names its type (END, SIDE, CORNER), but an angle near the middle between
// two ideals fits both: a 45-degree chamfer or cone meets a wall at 135 or
// 225 degrees, and whether the cone's trace on the wall runs along the caps
// or between them depends on the cone, not on the angle. Such a corner takes
// the type that agrees with the roles its neighbours already gave the
// face's curves. Plain data: testable without CAD.
#pragma once

#include <optional>
#include <vector>

namespace cooperage::cooper {

/// The lattice directions of a side loop and the parity of the ones that
/// run along the caps (use k runs along when directions[k] % 2 == parity).
struct SideTyping {
  std::vector<int> turns;       ///< per corner (before use k): END 1, SIDE 0, CORNER -1
  std::vector<int> directions;  ///< d_0 = 0, d_k = d_{k-1} + turn_k (mod 4)
  int parity = 0;
};

/// Most a corner's angle may differ from the ideal of a type it takes
/// because a neighbour asks for it [degrees].
constexpr double kCornerRetypeDeg = 60.0;

/// True when some corner of `angles` (interior angles before each use) fits
/// two types within kCornerRetypeDeg, or the angles' own types do not turn
/// by four quarter turns: the typing then waits for the neighbours.
bool has_ambiguous_corner(const std::vector<double>& angles);

/// Some typing of the corners (each within kCornerRetypeDeg of its type's
/// ideal) turns by four quarter turns.
bool can_turn_four(const std::vector<double>& angles);

/// The typing of a loop with corner angles `angles` that agrees with
/// `decided` (per use: 1 runs along the caps, 0 between them, -1 not known
/// yet; with none known, parity 0 and any typing agrees), turns by four quarter turns, and keeps each
/// corner within kCornerRetypeDeg of its type's ideal angle. The angles' own
/// types when they agree; else the agreeing typing with the least total
/// departure from the ideals (the first in a fixed order on ties). None
/// when no typing agrees.
std::optional<SideTyping> type_side_corners(const std::vector<double>& angles,
                                            const std::vector<int>& decided);

}  // namespace cooperage::cooper
