// Registers every built-in scheme, explicitly and in order of preference.
#pragma once

#include "framework/io/job.h"
#include "framework/scheme/registry.h"

#include <string>
#include <vector>

namespace cooperage {

/// Surface schemes, most preferred first: map, submap, pave, tri (triangles,
/// only when pinned or a cooper role), quad_dominant (pave's quads with the
/// poor ones split into triangles, likewise). Volume schemes: map, then cooper (which asks the
/// registry for submap/map/pave/tri/quad_dominant by name, so the registry must outlive it). The
/// schemes keep no per-job state (a job's vertex types, sweep hints and element kinds reach them as
/// scheme::Settings), so one registry serves any number of jobs.
void register_builtin_schemes(scheme::Registry& registry);

/// The plug-ins of a run, in load order: the command line's (`--plugin`,
/// relative to the working directory), then the journal's <plugin>
/// elements (Job::plugins, relative to the journal).
std::vector<io::PluginSetting> run_plugins(const std::vector<std::string>& command_line,
                                           const std::vector<io::PluginSetting>& journal);

/// The registry of a run: the built-in schemes, then every plug-in of the
/// COOPERAGE_PLUGIN_PATH variable (when `plugin_path`), then `plugins` in
/// order (framework/scheme/plugin_loader.h). Throws MeshingError naming the
/// library (and where it was given) when one cannot be loaded.
void register_schemes(scheme::Registry& registry, const std::vector<io::PluginSetting>& plugins,
                      bool plugin_path = true);

}  // namespace cooperage
