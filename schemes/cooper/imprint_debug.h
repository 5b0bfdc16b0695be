// A barrel's ends as imprinting saw and left them, written as JSON for a
// person drawing them (fuzz/draw_imprint.py) when the environment variable
// COOPERAGE_DEBUG_IMPRINT names a folder. Imprinting failures are found by
// looking at both ends in the barrel's chart; nothing is written otherwise.
#pragma once

#include "schemes/cooper/imprint_subcaps.h"

#include <string>

namespace cooperage::cooper {

/// Writes `<folder>/<name>-in.json` (the ends given) and `-out.json` (the
/// ends after imprinting, with the reason it stopped) when
/// COOPERAGE_DEBUG_IMPRINT is set, and `-step<k>.json` for every entry of
/// out.trace (the ends before step k; "why" names the step before it);
/// returns whether it wrote them.
bool write_imprint_debug(const std::string& name, const BarrelEnds& in, const ImprintResult& out);

/// How many steps imprinting should trace for write_imprint_debug: the
/// number in COOPERAGE_DEBUG_IMPRINT_STEPS when COOPERAGE_DEBUG_IMPRINT is
/// set too, else 0.
int imprint_debug_steps();

}  // namespace cooperage::cooper
