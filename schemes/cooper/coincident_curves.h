// Cap curves that project onto each other along a straight sweep (Blacker
// 1996, sec. 5.4): a boss above a foot of the same footprint, a bore's rim
// on the top and on the bottom. No side face ties their interval counts
// (the block's interior lies between them), yet imprinting seams the one
// loop onto the other node for node, so the plan asks for equal counts.
// Plain data: testable without CAD.
#pragma once

#include "schemes/cooper/barrel_constraints.h"

#include <string>
#include <utility>
#include <vector>

namespace cooperage::cooper {

/// Pairs (a < b) of distinct curves of `caps` whose projections along `down`
/// coincide: sample for sample (either way round) within 1e-6 of the
/// volume's size, or for curved rims within 5 % of how far the curves spread
/// across their main direction (0.035 r for circles of radius r).
std::vector<std::pair<int, int>> coincident_cap_curves(const VolumeFacts& facts,
                                                       const std::vector<int>& caps,
                                                       const geom::Vec3& down);

/// Pairs (a < b) of curves of `caps` whose projections along `down` run on
/// one line over part of their length (a shared stretch longer than 1e-3 of
/// the shorter curve) without coinciding as in coincident_cap_curves: a
/// boss's footprint and a foot's that share part of an edge.
std::vector<std::pair<int, int>> overlapping_cap_curves(const VolumeFacts& facts,
                                                        const std::vector<int>& caps,
                                                        const geom::Vec3& down);

/// One equality row per pair; `tag` starts every label.
std::vector<IntervalRow> coincident_curve_rows(const std::vector<std::pair<int, int>>& pairs,
                                               const std::string& tag);

}  // namespace cooperage::cooper
