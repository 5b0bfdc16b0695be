// Round features keep their volume at coarse sizes (issue 16, item 4).
// Elements have straight edges, so a round face meshed with few intervals
// around it loses the sliver between its facets and the surface: a rod of
// diameter 10 at size 5 is a hexagon, 17 % short of its volume. The turning
// rule of curve_sizing.h (>= 6 intervals a circle) keeps the feature's
// shape but not its volume; this budget raises the interval minima of the
// curves around round faces until the estimated loss of every volume is
// within a fraction of it (and of its surface area, for surface meshes).
//
// Estimate, per non-planar face f with boundary curves c that turn by
// Theta_c over length l_c (treated as arcs of radius r_c = l_c / Theta_c)
// and get n_c intervals:
//   - a chord of angle phi = Theta_c / n_c cuts off the circular segment
//     r^2 (phi - sin phi) / 2, so the arc loses a_c = r^2 (Theta - n sin(Theta/n)) / 2;
//   - the face sweeps that section over its other extent A_f / l: the
//     volume lost is A_f * sum(a_c) / sum(l_c) (exact for a cylinder, close
//     for a cone, a fillet or a loft), gained where the face is concave (a
//     hole); losses and gains cancel, as in the run's volume check;
//   - a flat panel of angle phi is 1 - sin(phi/2)/(phi/2) shorter than its
//     arc, so the face's area loss is A_f times the length-weighted mean of
//     that fraction.
// Where a volume is over budget, the faces erring most (in the direction of
// the total, for the volume) get 25 % more intervals on their turning curves (never finer than
// min_turn_deg an interval), until within budget. The cost goes where the volume goes: a rod is
// refined, a small hole in a large plate is not.
#pragma once

#include "framework/geometry/model.h"

#include <map>

namespace cooperage::intervals {

struct FacetingOptions {
  /// Estimated faceting loss allowed per volume, as a fraction of its
  /// volume and of its boundary's area (0: no budget, the turning rule alone).
  double fraction = 0.005;
  /// Never more than one interval per this many degrees of turning.
  double min_turn_deg = 3.0;
};

/// One curve's input to the budget.
struct TurningCurve {
  double turning = 0.0;  ///< total turning of the tangent [rad]
  int intervals = 1;     ///< count before the budget (at least the minimum)
};

/// Per curve id: the raised interval minimum, for curves the budget raised
/// (others are absent). Deterministic.
std::map<int, int> faceting_minima(const geom::Model& model,
                                   const std::map<int, TurningCurve>& curves,
                                   const FacetingOptions& options = {});

/// The estimated faceting loss of volume v with the given counts: what the
/// budget compares with its fraction (for tests and reports).
struct FacetingLoss {
  double volume = 0.0;  ///< estimated net volume lost (negative: gained)
  double area = 0.0;    ///< estimated boundary area lost
};
FacetingLoss faceting_loss(const geom::Model& model, int volume,
                           const std::map<int, TurningCurve>& curves);

}  // namespace cooperage::intervals
