// Region validity of a submap lattice whose picture is exact: the loop
// balance (per axis, + sum = - sum) closes the lattice boundary but does
// not keep it simple. In a C-shaped face whose notch is deep, an interval
// count that makes the notch longer in the lattice than the face is wide
// puts two boundary nodes on one lattice point (submap then fails at mesh
// time, after the plan accepted the face). Two curves running along one
// lattice axis that face each other across the face (a straight segment
// across the axis joins them through the face, crossing no other curve)
// keep at least one row of cells between them in the lattice; so do two
// that meet at one level from either side of it with the face around the
// segment between their ends (a hole's wall cut open by the block's side,
// continued above by a boss's: plan => mesh campaign, seed 10 case 118).
// The picture: a planar face of straight curves, or a face whose every curve
// is a line of constant u or v (a cylinder's, a cone's), unwrapped.
#pragma once

#include "framework/geometry/model.h"
#include "framework/intervals/interval_problem.h"
#include "schemes/submap/submap_plan.h"

namespace cooperage::submap {

/// Adds "far curve's lattice coordinate - near curve's >= 1" for every pair
/// of curves of `loop` (the outer loop of surface `surface_id`) running
/// along one axis that face each other or meet at one level. Adds nothing
/// unless the loop's picture is exact (every curve straight and the loop in
/// one plane, or every curve iso-parametric and the unwrapped loop closed),
/// nor for loops of more than 64 curves. Rows asking a single count to be at
/// least 1 are left out. On a plane the rows are constraints; off a plane
/// they are preferences (IntervalProblem::add_preference), so that answers
/// keeping them stay as they were.
void add_facing_edge_constraints(const geom::Model& model, int surface_id, const LoopPlan& loop,
                                 intervals::IntervalProblem& problem);

}  // namespace cooperage::submap
