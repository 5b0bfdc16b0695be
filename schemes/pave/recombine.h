// Greedy recombination of triangle pairs into quadrilaterals (step (c) of
// the pave pipeline, pave_2d.h): every interior edge whose two triangles form
// a convex quad of acceptable shape is a candidate, scored by the quad's
// scaled Jacobian; candidates are taken best first while both triangles are
// free (a greedy matching; cf. Blossom-Quad, Remacle et al. 2012, which uses
// an optimal matching instead).
#pragma once

#include "schemes/pave/cdt_2d.h"

#include <array>
#include <vector>

namespace cooperage::pave::detail {

/// Cells of a mixed mesh: a quad (4 nodes, counter-clockwise) or a triangle
/// (cells[k][3] == -1).
using Cell = std::array<int, 4>;

/// Pairs triangles of `tri` into quads; unpaired triangles stay.
/// \param[in] min_quality  smallest scaled Jacobian of an accepted quad
/// \param[in] min_cells    per point (may be shorter than points: 0 beyond):
///                         a merge never leaves a point in fewer cells; the
///                         points it covers count as loop points, from which
///                         leftover triangles are moved (none without it)
std::vector<Cell> recombine(const Triangulation2D& tri, double min_quality = 0.3,
                            const std::vector<int>& min_cells = {});

}  // namespace cooperage::pave::detail
