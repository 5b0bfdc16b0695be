// Intervals of the ribs that leave a cap tangentially (issue 16: fillets,
// domes; tangent_departure.h): the first interval at the tangent end is at
// least the length over which the rib rises kTangentLiftDeg off the cap,
// the rest keep the curve's size; the count is capped so that the solver's
// choice cannot shrink that first interval again.
#pragma once

#include "framework/intervals/interval_problem.h"
#include "schemes/cooper/side_lattice.h"

namespace cooperage::cooper {

/// For every curve in `lattice.graded`: when even intervals at the count
/// the solver aims at are already long enough, only caps the count (at
/// length / first interval); else sets its size function and caps the
/// count at that aim. Never below the curve's minimum; a user's fixed count
/// is left alone.
void grade_tangent_ribs(const VolumeFacts& facts, const SideLattice& lattice,
                        intervals::IntervalProblem& problem);

}  // namespace cooperage::cooper
