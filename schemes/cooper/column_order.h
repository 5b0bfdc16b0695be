// The lattice columns of a notched wall's corners in the order the wall has
// them (Blacker 1996, sec. 4: ribs progress straight down a barrel's side).
// A wall notched at both ends -- a hole's wall under a pocket at its top
// and a crossing hole's ceiling at its bottom -- has its corners' columns
// set by the interval counts of the rims between them. Nothing tied those
// to where the corners are: campaign seed 10 case 66 gave a pocket floor's
// arc 7 intervals instead of 4, its corner's column fell 4 columns past a
// ceiling's corner that lies 3 degrees beyond it, and the ribs ran 90
// degrees round the wall in one layer. The pocket's image then cut the
// ceiling, which its surface scheme had meshed already. Plain data:
// testable without CAD.
#pragma once

#include "schemes/cooper/barrel_constraints.h"
#include "schemes/cooper/side_lattice.h"

#include <string>
#include <vector>

namespace cooperage::cooper {

/// Rows "column(b) - column(a) >= 0" for the corners a, b of a side face
/// where b lies past a along its rims, seen along the straight sweep
/// `down`. Only single-loop faces whose curves between the rims run along
/// the sweep (walls parallel to it: there a corner seen along the sweep is
/// its column's foot), and only rows the counts' positivity does not give
/// already. Equal columns are allowed: corners closer than an element may
/// share one. The rows are preferences (IntervalRow::preferred): a wall's
/// geometry read from sampled curves can misjudge an order the scheme's own
/// rows then contradict. `tag` starts every label.
std::vector<IntervalRow> column_order_rows(const VolumeFacts& facts, const SideLattice& lattice,
                                           const geom::Vec3& down, const std::string& tag);

}  // namespace cooperage::cooper
