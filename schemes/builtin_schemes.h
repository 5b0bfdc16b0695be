// Registers every built-in scheme, explicitly and in order of preference.
#pragma once

#include "framework/io/job.h"
#include "framework/scheme/registry.h"

#include <string>
#include <vector>

namespace cooperage {

/// What the built-in schemes take from a job.
struct BuiltinOptions {
  /// Hard vertex classifications for submap (journal <vertex_type>).
  std::vector<io::VertexTypeSetting> vertex_types;
  /// Volume settings: cooper takes their sweep hints (sources, targets,
  /// direction) and element kinds (elements="wedge" / "mixed").
  std::vector<io::VolumeSetting> volumes;
};

/// The options a journal's mesh settings give.
BuiltinOptions builtin_options(const io::MeshSettings& settings);

/// Surface schemes, most preferred first: map, submap, pave, tri (triangles,
/// only when pinned or a cooper role), quad_dominant (pave's quads with the
/// poor ones split into triangles, likewise). Volume schemes: map, then cooper (which asks the registry for
/// submap/map/pave/tri/quad_dominant by name, so the registry must outlive it).
void register_builtin_schemes(scheme::Registry& registry, const BuiltinOptions& options = {});

/// The plug-ins of a run, in load order: the command line's (`--plugin`,
/// relative to the working directory), then the journal's <plugin>
/// elements (Job::plugins, relative to the journal).
std::vector<io::PluginSetting> run_plugins(const std::vector<std::string>& command_line,
                                           const std::vector<io::PluginSetting>& journal);

/// The registry of a run: the built-in schemes, then every plug-in of the
/// COOPERAGE_PLUGIN_PATH variable (when `plugin_path`), then `plugins` in
/// order (framework/scheme/plugin_loader.h). Throws MeshingError naming the
/// library (and where it was given) when one cannot be loaded.
void register_schemes(scheme::Registry& registry, const BuiltinOptions& options,
                      const std::vector<io::PluginSetting>& plugins, bool plugin_path = true);

}  // namespace cooperage
