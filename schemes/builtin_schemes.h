// Registers every built-in scheme, explicitly and in order of preference.
#pragma once

#include "framework/io/job.h"
#include "framework/scheme/registry.h"

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

}  // namespace cooperage
