// The decomposition in lines for a person (cooperage plan, run reports).
#pragma once

#include "framework/decompose/decompose.h"

#include <string>
#include <vector>

namespace cooperage::decompose {

/// One line per cut volume, one per cut and one for its pieces, e.g.
///   "volume 1 (part): cut into volumes 1, 2 (tried 12 cuts): no hex scheme applies (...)"
///   "  cut 1: plane y = 2.5, the plane of surface 14 -> 2 pieces, thinnest 1.5"
/// Empty when nothing was cut.
std::vector<std::string> report_lines(const Report& report);

}  // namespace cooperage::decompose
