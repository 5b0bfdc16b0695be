// Frontal point placement for the pave scheme's coarse triangulation: rows
// of right-angled triangles grown inward from the loops, so that the
// recombination pairs them into near-squares (a boundary-aligned lattice,
// paving's rows at the coarse level) instead of the 60/120-degree rhombi
// and leftover triangles that circumcentre refinement gives.
//
// Rebay's frontal Delaunay insertion (J. Comput. Phys. 106, 1993) with the
// point placed for right triangles, the idea of Remacle et al.'s L-infinity
// frontal mesher for quads (IJNME 94, 2013): a triangle is accepted when
// its circumradius is at most accept_radius local sizes; an unaccepted
// triangle next to an accepted one or to a loop edge is active, and its
// front edge (a, b) gets a new point
//   - at a + n h or b + n h (the one farther from the existing points) when
//     |ab| is about one size h (a leg: the new triangle is right-angled at
//     the endpoint), or
//   - at the apex m + n |ab| / 2 when |ab| is about sqrt(2) h (a
//     hypotenuse: the triangle is right-angled at the new point),
// with n the unit normal into the triangle. Triangles are processed first
// in, first out, so the rows advance together. A point that would not
// remove its triangle, falls outside the domain or comes closer than
// ~0.55 h to a point is not inserted; its triangle is left to the
// circumcentre refinement that follows.
#pragma once

#include "schemes/pave/cdt_kernel.h"

#include <vector>

namespace cooperage::pave::detail {

/// Fills the inside of `cdt` (loops recovered, inside marked) frontally;
/// sizes of new points are the mean of their front edge's. Returns the
/// number of points inserted.
int frontal_fill(cdt::Cdt& cdt, const std::vector<std::vector<int>>& loops, double accept_radius);

}  // namespace cooperage::pave::detail
