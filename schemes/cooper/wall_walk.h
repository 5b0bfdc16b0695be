// The walk round a side wall's loop in its lattice (column_spacing.h,
// column_order.h): from its first curve running along the caps, the
// direction turns by a quarter at every corner (90 degrees one way, 270 the
// other, 180 straight on); curves along the caps go +-i, the others +-j.
// Plain data: testable without CAD.
#pragma once

#include "schemes/cooper/side_lattice.h"

#include <vector>

namespace cooperage::cooper {

/// One use of the loop, in walk order.
struct WallStep {
  size_t use = 0;  ///< index in the loop
  int dir = 0;     ///< 0: +i, 1: +j, 2: -i, 3: -j
  bool along = false;
};

/// The walk round a single-loop side face; empty when the face has more
/// loops, no corner angles, no curve along the caps, or a curve whose role
/// (along or not) disagrees with the direction the corners give it.
std::vector<WallStep> wall_walk(const FaceFact& face, const SideLattice& lattice);

/// Whether the face's curves between its rims run along `d` (unit) within
/// `tol`: a wall parallel to the sweep, where a vertex seen along the sweep
/// is its column's foot.
bool upright_wall(const VolumeFacts& facts, const FaceFact& face, const SideLattice& lattice,
                  const geom::Vec3& d, double tol);

}  // namespace cooperage::cooper
