// Who meshes each cap (Blacker 1996, sec. 3 and 6.1: "if cap faces are
// unmeshed, they initially remain so to allow greater flexibility during
// the barrel formation"; each cap stack is meshed once, from one of its
// caps). Every stack holds exactly one upper cap piece (the top of its
// column of volume), so an upper cap is meshed beforehand by its surface
// scheme when nothing will be imprinted on it: no loop of another cap
// projects inside it along the axis. Every other cap is meshed here, by
// projection through the barrels or (stacks without a pre-meshed cap) by
// the polygon mesher. Without a straight axis the footprints cannot be
// compared, and only trees whose barrels end on one piece each (nothing is
// imprinted upwards) are accepted. Plain data: testable without CAD.
#pragma once

#include "schemes/cooper/barrel_tree.h"

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace cooperage::cooper {

struct CapRoles {
  bool ok = false;
  std::string why;
  /// cap -> its surface scheme (meshed beforehand), absent: meshed by cooper
  std::map<int, std::string> scheme;
  std::vector<int> by_volume;  ///< caps meshed by cooper, ascending
  /// Some stack has no cap meshed beforehand: its mesh comes from the
  /// polygon mesher (then every cap loop must be even for all-quad).
  bool needs_polygon_mesher = false;
  /// Upper caps into which another cap's loop projects (imprinted).
  std::vector<int> cut;
};

/// The surface scheme of a cap for the volume's element kind, or "" with why.
using CapSchemeOf = std::function<std::string(int cap, std::string& why)>;

/// \param[in] down  the sweep direction when the sweep is straight (footprints
///                  along it decide which upper caps are cut); else null
CapRoles cap_roles(const VolumeFacts& facts, const SweepOrder& order, const BarrelTree& tree,
                   const geom::Vec3* down, const CapSchemeOf& scheme_of, bool polygon_mesher);

/// Footprint test used by cap_roles: the caps of `facts` into whose region
/// (projected along `down`) a loop of another cap of `caps` reaches: a point
/// of it, or of an edge crossing it between two points, lies inside deeper
/// than `relative` times the cap's width (twice its area over its
/// perimeter), at most `relative` times the volume's size.
std::vector<int> cut_caps(const VolumeFacts& facts, const std::vector<int>& caps,
                          const geom::Vec3& down, double relative);

}  // namespace cooperage::cooper
