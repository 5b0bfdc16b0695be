// Coarse vertices of a loop with the parity switching along it, so that
// every sharp corner is a coarse vertex. A skipped node's angle is split
// between two quads (quality sin(angle / 2)): a 90 deg corner on a skipped
// node gives two 45 deg corners (0.707), on a coarse vertex one 90 deg cell.
// With a single parity per loop, corners an odd number of intervals apart
// cannot all be coarse; here each run between two corners that need
// opposite parities gets one odd edge (a coarse edge over one fine edge,
// paired through the interior by parity_paths.h), placed in the run where
// the worst skipped node is best, nearest its middle.
#pragma once

#include <Eigen/Core>

#include <cmath>
#include <cstddef>
#include <vector>

namespace cooperage::pave::detail {

/// Interior angle [rad] of the face at position k of `loop` (face on the left), in (0, 2 pi).
double interior_angle(const std::vector<Eigen::Vector2d>& points, const std::vector<int>& loop,
                      size_t k);

/// True for a node that must be a coarse vertex: interior angle below
/// `sharp` or in (2 pi - `sharp`, `reflex_limit`] [rad] (sin(angle / 2)
/// below sin(sharp / 2); sharper reflex tips may be left to the corner template).
bool is_corner(double interior, double sharp, double reflex_limit = 2 * M_PI);

/// Loop positions (in loop order from the first corner, modulo the loop size) of the coarse
/// vertices: every corner (is_corner) is one, runs between corners alternate,
/// and a run of an odd number of fine edges holds one odd edge. Empty when
/// the loop has no corner. Depends only on the loop's geometry and order,
/// not on its starting node (rotation invariant in the canonical frame).
std::vector<size_t> corner_picks(const std::vector<Eigen::Vector2d>& points,
                                 const std::vector<int>& loop, double sharp,
                                 double reflex_limit = 2 * M_PI);

/// Worst sin(angle / 2) over the nodes that `picks` skips (1 when none).
double skipped_quality_of_picks(const std::vector<Eigen::Vector2d>& points,
                                const std::vector<int>& loop, const std::vector<size_t>& picks);

}  // namespace cooperage::pave::detail
