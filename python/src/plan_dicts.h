// Plans as Python lists of dicts: cooperage.plan() (the selector's full
// answer, as `cooperage plan --json`) and Mesh.plan (what a run used).
#pragma once

#include <pybind11/pybind11.h>

#include <filesystem>
#include <optional>

#include "framework/pipeline/scheme_plan.h"

namespace cooperage::python {

/// cooperage.plan(): plans a journal or CAD file (pipeline::plan_input,
/// the built-in schemes, the selector) without meshing. One dict per volume,
/// then per surface: entity, dim, id, scheme, score (the chosen scheme's,
/// None when a volume meshes the surface), reason, pinned, candidates (dicts:
/// scheme, ok, score, why).
pybind11::list plan_file(const std::filesystem::path& file, std::optional<double> size, int dim);

/// Mesh.plan: dicts (entity, dim, id, scheme, reason, details).
pybind11::list plan_entries(const pipeline::SchemePlan& plan);

}  // namespace cooperage::python
