// A library with a registration function but no ABI symbol: not a plug-in.
#include "framework/scheme/plugin.h"

extern "C" COOPERAGE_PLUGIN_EXPORT void cooperage_register(cooperage::scheme::Registry&) {}
