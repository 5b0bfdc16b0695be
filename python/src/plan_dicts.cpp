#include "plan_dicts.h"

#include <pybind11/stl.h>

#include "framework/core/error.h"
#include "framework/pipeline/check_settings.h"
#include "framework/pipeline/model_job.h"
#include "option_values.h"
#include "framework/scheme/scheme.h"
#include "schemes/builtin_schemes.h"
#include "framework/pipeline/mesh_size.h"
#include "selector/select_schemes.h"

namespace py = pybind11;

namespace cooperage::python {
namespace {

std::string entity_name(int dim, int id) {
  return (dim == 3 ? "volume " : "surface ") + std::to_string(id);
}

py::dict choice_dict(const selector::Choice& c) {
  py::dict d;
  d["entity"] = entity_name(c.dim, c.id);
  d["dim"] = c.dim;
  d["id"] = c.id;
  d["scheme"] = c.scheme;
  py::object score = py::none();
  py::list candidates;
  for (const auto& k : c.candidates) {
    py::dict kd;
    kd["scheme"] = k.scheme;
    kd["ok"] = k.applicability.ok;
    kd["score"] = k.applicability.score;
    kd["why"] = k.applicability.why;
    candidates.append(kd);
    if (k.scheme == c.scheme) score = py::float_(k.applicability.score);
  }
  d["score"] = score;
  d["reason"] = c.reason;
  d["pinned"] = c.pinned;
  d["candidates"] = candidates;
  return d;
}

}  // namespace

py::list plan_file(const std::filesystem::path& file,
                   const std::optional<std::variant<double, std::string>>& size_value, int dim,
                   const std::optional<std::string>& elements, std::optional<bool> imprint,
                   const std::optional<std::string>& decompose) {
  pipeline::PlanOverrides overrides;
  overrides.origin = "cooperage.plan()";
  overrides.imprint_option = "imprint";
  if (elements) overrides.elements = element_kind(*elements, overrides.origin);
  if (imprint) overrides.imprint_merge = *imprint;
  if (decompose) overrides.decompose = decompose_mode(*decompose, overrides.origin);
  std::optional<io::ElementSize> size;
  if (size_value) size = element_size(*size_value, overrides.origin);
  if (dim != 2 && dim != 3) {
    throw MeshingError(ErrorCode::InvalidInput,
                       "cooperage.plan(): dim must be 2 or 3, got " + std::to_string(dim));
  }
  selector::Selection selection;
  {
    py::gil_scoped_release release;
    // Volumes no scheme fits are cut as cooperage.mesh() and `cooperage
    // plan` cut them; when no cut helps, the undecomposed model is planned
    // and select_schemes() names the refused volume.
    scheme::Registry defaults;
    register_schemes(defaults, {});
    pipeline::PlanInput input;
    try {
      input = dim == 3 ? pipeline::plan_input(file.string(), size, &defaults, selector::planner(),
                                              overrides)
                       : pipeline::plan_input(file.string(), size, nullptr, {}, overrides);
    } catch (const MeshingError& e) {
      if (e.code() != ErrorCode::NotApplicable || e.entity().dim != 3) throw;
      input = pipeline::plan_input(file.string(), size, nullptr, {}, overrides);
    }
    pipeline::check_elements_for_dim(input.settings, dim);
    pipeline::check_planned_size(input.model, input.settings, dim);
    scheme::Registry registry;
    register_schemes(registry, input.plugins);
    selector::SelectOptions options;
    options.dim = dim;
    options.check_intervals = input.settings.size.has_value();
    selection = selector::select_schemes(input.model, registry, input.settings, options);
  }
  py::list out;
  for (const auto& c : selection.volumes) out.append(choice_dict(c));
  for (const auto& c : selection.surfaces) out.append(choice_dict(c));
  return out;
}

py::list plan_entries(const pipeline::SchemePlan& plan) {
  py::list out;
  for (int dim : {3, 2}) {
    for (const auto& [id, e] : dim == 3 ? plan.volumes : plan.surfaces) {
      py::dict d;
      d["entity"] = entity_name(dim, id);
      d["dim"] = dim;
      d["id"] = id;
      d["scheme"] = e.scheme;
      d["reason"] = e.reason;
      d["details"] = e.details;
      out.append(d);
    }
  }
  return out;
}

}  // namespace cooperage::python
