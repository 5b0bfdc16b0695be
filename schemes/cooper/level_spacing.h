// Nodes of the curves running between the caps placed on the levels of the
// caps they pass (Blacker 1996, sec. 4: a barrel ends where any rib reaches
// a cap, so every ring of ribs should lie on one level). A wall from the
// top to the bottom of a part runs past a blind hole's floor without a
// vertex there; spaced by its own size function (graded by a small feature
// near one end) its node of the floor's layer landed 10 mm off the floor,
// and the virtual caps between the barrels were warped so much that the
// projected cap stacks folded (gmsh_918_pump_carter_sup, issue 15). After
// the interval solve every level class has a layer potential; on a straight
// axis each potential a cap sits on has a height, and the node of every
// chain with that potential is put at that height (in proportion to the
// chain's own drop, so an inclined cap stays inclined), the potentials in
// between spread linearly. Plain data: testable without CAD.
#pragma once

#include "framework/mesh/curve_spacing.h"
#include "schemes/cooper/sweep_order.h"

#include <map>

namespace cooperage::cooper {

/// Size functions for the curves of the lattice's chains that put their
/// nodes on the cap levels, given every curve's interval count. Curves
/// graded for a tangent departure (`lattice.graded`), curves of one
/// interval, curves whose height does not fall monotonically along them,
/// and chains of components whose potentials and heights disagree are left
/// out. Empty unless the sweep is straight (`order.straight`).
/// \param[in] down   the sweep direction (heights are -x . down)
/// \param[in] counts interval count per curve (the solver's)
std::map<int, mesh::SizeFunction> level_spacing(const VolumeFacts& facts,
                                                const SideLattice& lattice, const SweepOrder& order,
                                                const geom::Vec3& down,
                                                const std::map<int, int>& counts);

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
