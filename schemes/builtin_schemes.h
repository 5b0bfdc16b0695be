// Registers every built-in scheme, explicitly and in order of preference.
#pragma once

#include "framework/scheme/registry.h"

namespace cooperage {

/// Surface schemes: map. Volume schemes: map.
/// (submap, pave and cooper join as they land.)
void register_builtin_schemes(scheme::Registry& registry);

}  // namespace cooperage
