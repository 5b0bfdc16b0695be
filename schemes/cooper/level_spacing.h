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

/// Piecewise-constant sizes (steps kept piecewise linear by short ramps)
/// under which t.size() - 1 intervals equidistribute onto the node
/// fractions t (0 first, 1 last) of a curve of the given length.
mesh::SizeFunction steps_through(const std::vector<double>& t, double length);

}  // namespace cooperage::cooper
