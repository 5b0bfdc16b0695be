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
// front edge (a, b) gets a new point placed against the local lattice frame
// (a cross field: the loop tangents at loop points, the mean of the front
// edge's endpoints for a new point):
//   - a loop edge, or an edge within 22.5 degrees of a frame axis (a leg):
//     at a + h e or b + h e, e the frame axis nearest the edge's inward
//     normal (the normal itself on a loop edge), the one farther from the
//     existing points first: the triangle is right-angled at the endpoint;
//   - an edge across the frame (a diagonal): the lattice corner of the
//     rectangle on (a, b) on the triangle's side, right-angled there.
// h is the size at the point, linear over the triangulation of the loop
// points alone (a background mesh: sizes grade between loops instead of
// being carried along the rows). Triangles are processed first in, first
// out, so the rows advance together. A point that lies outside its
// triangle's circumcircle or the domain, or comes closer than 0.55 h to a
// point, is not inserted; its triangle is left to the circumcentre
// refinement that follows (a diagonal has no second candidate).
#pragma once

#include "schemes/pave/cdt_kernel.h"

#include <vector>

namespace cooperage::pave::detail {

/// Fills the inside of `cdt` (loops recovered, inside marked, no point yet
/// but the loops' `loops`) frontally. Returns the number of points inserted.
int frontal_fill(cdt::Cdt& cdt, const std::vector<std::vector<int>>& loops, double accept_radius);

}  // namespace cooperage::pave::detail
