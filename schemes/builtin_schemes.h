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
};

/// Surface schemes, most preferred first: map, submap. Volume schemes: map.
void register_builtin_schemes(scheme::Registry& registry, const BuiltinOptions& options = {});

}  // namespace cooperage
