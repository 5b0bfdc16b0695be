// The interval program's optimum when it needs no search. The objective is a
// sum of one convex piecewise-linear term per column (ilp.h), so the vector
// of the columns' own minimisers is optimal whenever it satisfies every row;
// when each minimiser is also unique, it is the program's only optimum, the
// answer CBC would return. Each CBC solve costs its driver's set-up and
// fresh memory: a journal of one brick ran 13 ms faster without them, and a
// journal that solves nothing never opens the CBC module (issue 20).
#pragma once

#include <optional>
#include <vector>

#include "framework/intervals/ilp.h"

namespace cooperage::intervals::detail {

/// Every column at the unique integer minimiser of its cost terms, if those
/// values satisfy every row and bound; nullopt when some column's minimiser
/// is not unique (a flat or cost-free column) or a row does not hold.
std::optional<std::vector<int>> separable_optimum(const std::vector<Column>& columns,
                                                  const std::vector<Row>& rows);

}  // namespace cooperage::intervals::detail
