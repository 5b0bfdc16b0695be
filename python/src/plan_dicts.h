// Plans as Python lists of dicts: cooperage.plan() (the selector's full
// answer, as `cooperage plan --json`) and Mesh.plan (what a run used).
#pragma once

#include <pybind11/pybind11.h>

#include <filesystem>
#include <optional>
#include <string>
#include <variant>

#include "framework/pipeline/scheme_plan.h"

namespace cooperage::python {

/// cooperage.plan(): plans a journal or CAD file (pipeline::plan_input,
/// the built-in schemes, the selector) without meshing. One dict per volume,
/// then per surface: entity, dim, id, scheme, score (the chosen scheme's,
/// None when a volume meshes the surface), reason, pinned, candidates (dicts:
/// scheme, ok, score, why). `elements`, `imprint` and `decompose`, when
/// given, as cooperage.mesh() takes them (pipeline::PlanOverrides).
pybind11::list plan_file(const std::filesystem::path& file,
                         const std::optional<std::variant<double, std::string>>& size, int dim,
                         const std::optional<std::string>& elements = std::nullopt,
                         std::optional<bool> imprint = std::nullopt,
                         const std::optional<std::string>& decompose = std::nullopt);

/// Mesh.plan: dicts (entity, dim, id, scheme, reason, details).
pybind11::list plan_entries(const pipeline::SchemePlan& plan);

}  // namespace cooperage::python
