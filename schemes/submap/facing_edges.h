// Region validity of a submap lattice on a planar face of straight curves:
// the loop balance (per axis, + sum = - sum) closes the lattice boundary but
// does not keep it simple. In a C-shaped face whose notch is deep, an
// interval count that makes the notch longer in the lattice than the face
// is wide puts two boundary nodes on one lattice point (submap then fails at
// mesh time, after the plan accepted the face). Two curves running along
// one lattice axis that face each other across the face (a straight segment
// across the axis joins them through the face, crossing no other curve)
// keep at least one row of cells between them in the lattice.
#pragma once

#include "framework/geometry/model.h"
#include "framework/intervals/interval_problem.h"
#include "schemes/submap/submap_plan.h"

namespace cooperage::submap {

/// Adds "far curve's lattice coordinate - near curve's >= 1" for every pair
/// of curves of `loop` (the outer loop of surface `surface_id`) running
/// along one axis that face each other. Adds nothing unless every curve of
/// the loop is straight and the loop lies in one plane (the polygon is then
/// exact), nor for loops of more than 64 curves.
void add_facing_edge_constraints(const geom::Model& model, int surface_id, const LoopPlan& loop,
                                 intervals::IntervalProblem& problem);

}  // namespace cooperage::submap
