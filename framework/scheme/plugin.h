// The plug-in interface: a shared library that adds schemes to the registry
// of a run. It exports two C functions, the ABI version it was built for
// (checked first) and its registration function:
//
//   #include <framework/scheme/plugin.h>
//   COOPERAGE_PLUGIN_ABI
//   extern "C" COOPERAGE_PLUGIN_EXPORT void cooperage_register(cooperage::scheme::Registry& r) {
//     r.add(std::make_unique<MyScheme>());
//   }
//
// `cooperage --plugin lib.so`, `<plugin file="lib.so"/>` in a journal and
// the COOPERAGE_PLUGIN_PATH variable load it (plugin_loader.h);
// examples/plugin/ is a complete plug-in project.
#pragma once

#include "framework/scheme/registry.h"

/// The version of the interface between cooperage and its plug-ins: the
/// scheme interfaces (scheme.h), Registry and the types they pass (the
/// views, Settings with the journal's io::MeshSettings, PlanData). Bumped
/// whenever any of them changes layout or meaning; a plug-in built for
/// another version is refused with a message, never called. 3: Settings
/// and the scheme's own plan reach it through the views (docs/plugins.md).
/// 4: VolumeView::neighbours.
#define COOPERAGE_PLUGIN_ABI_VERSION 4

#define COOPERAGE_PLUGIN_EXPORT __attribute__((visibility("default")))

/// Defines `int cooperage_plugin_abi()`, returning the ABI version the
/// plug-in is compiled against.
#define COOPERAGE_PLUGIN_ABI                                      \
  extern "C" COOPERAGE_PLUGIN_EXPORT int cooperage_plugin_abi() { \
    return COOPERAGE_PLUGIN_ABI_VERSION;                          \
  }

namespace cooperage::scheme {

inline constexpr int kPluginAbiVersion = COOPERAGE_PLUGIN_ABI_VERSION;
/// The symbols a plug-in exports.
inline constexpr const char* kPluginAbiSymbol = "cooperage_plugin_abi";
inline constexpr const char* kPluginRegisterSymbol = "cooperage_register";
/// Their types.
using PluginAbiFunction = int (*)();
using PluginRegisterFunction = void (*)(Registry&);

}  // namespace cooperage::scheme
