// Nodes of the rims of the side faces put over the vertices of the other
// rims, seen along a straight sweep (Blacker 1996, sec. 4: ribs progress
// straight down a barrel's side). The companion of level_spacing.h, which
// puts the nodes of the curves between the caps on the caps' levels. Plain
// data: testable without CAD.
#pragma once

#include "framework/mesh/curve_spacing.h"
#include "schemes/cooper/sweep_order.h"

#include <map>

namespace cooperage::cooper {

/// Size functions for the curves running along the caps (rings of ribs) of
/// the side faces that put a ring's nodes over the vertices of the face's
/// other rings, seen along the sweep: a lug whose wall ends on two levels
/// (its foot partly on a flange, partly past it) has its top rim in one
/// curve and its bottom rim in two; evenly spaced, the top rim's nodes did
/// not lie over the bottom rims' and the ribs ran 5 mm sideways along the
/// wall, which the cap stacks projected through the barrels then folded. A
/// knot is put where another ring's vertex lies over the curve, at the
/// node the lattice puts there (the intervals of the rings between the
/// curve's start and the vertex); curves of two faces that disagree are left
/// out. \param[in] down the straight sweep direction
/// `sizes` (null: none): the curves' sizes so far; a closed rim follows the
/// nodes they give the other rim's curves.
std::map<int, mesh::SizeFunction> column_spacing(
    const VolumeFacts& facts, const SideLattice& lattice, const geom::Vec3& down,
    const std::map<int, int>& counts, const std::map<int, mesh::SizeFunction>* sizes = nullptr);

}  // namespace cooperage::cooper
