// Loads plug-in libraries (plugin.h) into a registry: from a file given on
// the command line or in a journal, or from every entry of
// COOPERAGE_PLUGIN_PATH. A library stays loaded for the life of the process
// (its schemes' code lives in it).
#pragma once

#include "framework/scheme/registry.h"

#include <string>
#include <vector>

namespace cooperage::scheme {

/// The environment variable listing plug-ins: entries separated by ':',
/// each a plug-in library or a directory whose `*.so` files are all loaded
/// (in name order).
inline constexpr const char* kPluginPathVariable = "COOPERAGE_PLUGIN_PATH";

/// Loads the plug-in library at `path` and calls its registration function;
/// the schemes it adds have the library's absolute path as origin. Loading
/// a library a second time into the same registry does nothing.
/// @throws MeshingError(InvalidInput) naming the library: no such file, not
///         loadable (dlerror's reason), no cooperage_plugin_abi symbol (not a
///         plug-in), another ABI version than kPluginAbiVersion, no
///         cooperage_register, or what registration threw (a duplicate
///         scheme name, ...). `what` names where the path was given
///         ("--plugin", "job.xml:3").
void load_plugin(Registry& registry, const std::string& path, const std::string& what = {});

/// The libraries a COOPERAGE_PLUGIN_PATH value lists: files as given,
/// directories expanded to their `*.so` files in name order; empty entries
/// are skipped. @throws MeshingError(InvalidInput) for an entry that does
/// not exist.
std::vector<std::string> plugin_path_libraries(const std::string& value);

/// Loads every library of the COOPERAGE_PLUGIN_PATH variable (none when it
/// is unset or empty).
void load_plugin_path(Registry& registry);

}  // namespace cooperage::scheme
