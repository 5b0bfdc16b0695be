// Where a hole's lattice walk goes inside the outer loop's lattice: the
// integer offsets to try, best first. Value types only: testable without CAD.
#pragma once

#include <vector>

#include "schemes/submap/lattice.h"

namespace cooperage::submap {

/// Integer offsets for a hole's walk, best first: every offset in the box
/// [lo, hi] (per axis, inclusive), by distance to `predicted` (lattice units,
/// the least-squares estimate). Distances within `tie` of the smallest of
/// their group count as equal; equal ones are ranked by the offset itself
/// (i, then j, ascending). Lattice coordinates follow from the topology (the
/// walk starts at the first END of the loop), so a tie -- e.g. a centred
/// hole whose prediction is a half-integer -- is broken the same way however
/// the model is placed (Blacker 1996, sec. 1: orientation insensitivity),
/// not by floating-point noise in `predicted`.
/// \param[in] predicted  real-valued offset estimate
/// \param[in] lo, hi     inclusive bounds of the offsets that keep the hole
///                       strictly inside the outer lattice box (empty when
///                       lo > hi on an axis)
/// \param[in] tie        distance tolerance for ties, lattice units (>= 0)
std::vector<LatticePoint> rank_hole_offsets(const Vec2& predicted, const LatticePoint& lo,
                                            const LatticePoint& hi, double tie = 1e-6);

}  // namespace cooperage::submap
