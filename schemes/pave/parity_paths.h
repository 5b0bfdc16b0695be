// Odd loops for pave_2d. A loop with an odd number of nodes leaves one
// coarse loop edge without a midpoint (coarse_loops.h). The quad count is
// only right when such edges come in pairs joined through the interior:
// every coarse edge a path of cells crosses also loses its midpoint. A cell
// crossed by a path then has 4 or 6 boundary nodes instead of 6 or 8 and is
// split into 1, 2 or 3 quads (split_to_quads.h). Paving does the same with
// its seams between fronts; only the total boundary count must be even.
#pragma once

#include "schemes/pave/recombine.h"

#include <cstdint>
#include <unordered_set>
#include <vector>

namespace cooperage::pave::detail {

/// The coarse edges that get no midpoint: the odd loop edges and the edges
/// crossed by shortest cell paths pairing them (each odd edge is joined to
/// the nearest unpaired one, in cell steps). Throws std::runtime_error for an
/// odd number of odd edges or when no path exists.
std::unordered_set<std::uint64_t> parity_paths(const std::vector<Cell>& cells,
                                               const std::vector<std::uint64_t>& odd_edges);

}  // namespace cooperage::pave::detail
