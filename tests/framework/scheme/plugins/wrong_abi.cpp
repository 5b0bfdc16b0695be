// A plug-in built for another ABI version: refused before registration.
#include "framework/scheme/plugin.h"

#include <cstdlib>

extern "C" COOPERAGE_PLUGIN_EXPORT int cooperage_plugin_abi() { return 999; }
// Must never be called: a call would end the test program.
extern "C" COOPERAGE_PLUGIN_EXPORT void cooperage_register(cooperage::scheme::Registry&) {
  std::abort();
}
