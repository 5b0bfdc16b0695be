// The two rings of a sweep's side spaced alike (side_along_pairs): the
// sweep links node k of one ring to node k of the next, so a size function
// graded on one ring only shears the ribs; a ring graded to a sliver corner
// of its cap needs its grading, or its first chord crosses the corner's
// other curve.
#pragma once

#include <vector>

#include "framework/intervals/interval_problem.h"
#include "schemes/cooper/side_lattice.h"

namespace cooperage::cooper {

/// Rings whose profiles (sizes over their mean) differ by more than 10 %
/// (either way round) become uniform, unless a pair ends in a sliver corner
/// (AlongPair::sliver_end): then every ring linked to it through such sides
/// takes the finer of their profiles (sizes over their largest), each
/// facing its own way. Closed rings, chains whose orientations disagree and
/// chains that meet a uniform pair become uniform.
void space_alike_rings(const std::vector<AlongPair>& pairs, intervals::IntervalProblem& problem);

}  // namespace cooperage::cooper
