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
/// COOPERAGE_DEBUG_IMPRINT is set; returns whether it wrote them.
bool write_imprint_debug(const std::string& name, const BarrelEnds& in, const ImprintResult& out);

}  // namespace cooperage::cooper
