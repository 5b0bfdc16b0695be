// Which way the sweep runs through every side face and cap (Blacker 1996,
// sec. 3-4: barrels are logically single-axis sweeps; the upper and lower
// caps of a barrel are arbitrary, but one direction must hold along every
// rib). Unknowns: per cap, whether it is an upper cap (the volume lies
// below it: ribs leave it) or a lower one; per side face, whether its
// lattice's +j runs up. Every contact of a side with a cap, and every curve
// shared by two sides, fixes their relative parity (a convex contact below
// an upper cap, a re-entrant one above it, ...). One anchor (the axis, or
// the cap a sweep starts from) decides the rest, or they contradict each
// other: then no single sweep direction exists (Fig. 3a). Heights order
// the levels: projections on the axis, else path lengths along the chains.
// Plain data: testable without CAD.
#pragma once

#include "schemes/cooper/side_lattice.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace cooperage::cooper {

struct OrderAnchor {
  /// Axis mode: the sweep direction (from upper caps to lower caps); caps
  /// whose outward normal points against it are upper caps.
  std::optional<geom::Vec3> down;
  /// Without an axis: this cap is an upper cap (the sweep leaves it), or
  /// with `flip` a lower one.
  int upper_cap = 0;
  bool flip = false;
};

struct SweepOrder {
  bool ok = false;
  std::string why;
  std::map<int, bool> upper;     ///< cap -> upper cap (the volume below it)
  std::map<int, int> face_up;    ///< side -> +1 when its lattice +j runs up, else -1
  std::vector<int> chain_upper;  ///< per chain of the lattice: its upper level class
  std::vector<int> chain_lower;  ///< ... and its lower one
  std::vector<double> height;    ///< per level class; larger is upstream
  bool straight = false;         ///< heights are projections on `down`
};

/// Orients the lattice. Not ok when the parities contradict each other, a
/// part is not connected to the anchor, or (axis mode) a chain runs
/// against the axis.
SweepOrder sweep_order(const VolumeFacts& facts, const SideLattice& lattice,
                       const OrderAnchor& anchor);

}  // namespace cooperage::cooper
