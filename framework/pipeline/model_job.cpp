#include "framework/pipeline/model_job.h"

#include <cmath>
#include <filesystem>

#include "framework/core/error.h"
#include "framework/core/text.h"
#include "framework/io/journal_reader.h"
#include "framework/pipeline/build_geometry.h"
#include "framework/pipeline/check_settings.h"
#include "framework/pipeline/decomposed_geometry.h"
#include "framework/pipeline/relative_size.h"

namespace cooperage::pipeline {

io::Job model_job(const std::string& model, const ModelJobOptions& options) {
  if (!(options.size.value > 0) || !std::isfinite(options.size.value)) {
    throw MeshingError(ErrorCode::InvalidInput,
                       options.origin + ": the element size must be positive, got " +
                           std::string(options.size.of_diagonal ? "D/" : "") +
                           std::to_string(options.size.value));
  }
  if (lower_extension(model) == ".xml") {
    throw MeshingError(ErrorCode::InvalidInput,
                       clip_path(model) + ": a journal, not a CAD file: `cooperage run " +
                           clip_path(model) + "` runs it (its <mesh> gives the size)");
  }
  io::Job job;
  job.file = model;
  io::ImportOp import;
  // The shape's name (and so the volumes' names in the exports) is the file
  // name, bounded like a journal name.
  import.name = std::filesystem::path(model).stem().string().substr(0, 64);
  if (import.name.empty()) import.name = "part";
  import.file = model;
  job.geometry.push_back({import, {model, 0, "import"}});
  job.imprint_merge = options.imprint_merge;
  job.mesh = io::MeshSettings{};
  io::set_element_size(*job.mesh, options.size);
  job.mesh->decompose = options.decompose;
  job.mesh->finer_retries = options.finer_retries;
  job.mesh->elements = options.elements;
  for (const std::string& e : options.exports) {
    const std::string ext = std::filesystem::path(e).extension().string();
    if (options.binary && ext != ".vtu" && ext != ".msh" && ext != ".stl" && ext != ".ply") {
      throw MeshingError(ErrorCode::InvalidInput,
                         options.origin + ": " + options.binary_option +
                             " is for .vtu, .msh, .stl and .ply outputs (Exodus is always binary), "
                             "not '" +
                             e + "'");
    }
    job.exports.push_back({e, {options.origin, 0, options.export_option}, options.binary});
  }
  for (const std::string& r : options.reports) {
    job.reports.push_back({r, {options.origin, 0, options.report_option}});
  }
  if (options.min_scaled_jacobian) {
    const double floor = *options.min_scaled_jacobian;
    if (!(floor >= -1.0 && floor <= 1.0)) {
      throw MeshingError(ErrorCode::InvalidInput,
                         options.origin + ": " + options.min_scaled_jacobian_option +
                             " must be from -1 to 1, got " + number_text(floor));
    }
    io::QualityCheck check;
    check.metric = "scaled_jacobian";
    check.min = floor;
    check.action = io::QualityCheck::Action::Fail;
    check.where = {options.origin, 0, options.min_scaled_jacobian_option};
    job.quality.push_back(check);
  }
  return job;
}

PlanInput plan_input(const std::string& file, std::optional<io::ElementSize> size,
                     const scheme::Registry* registry, const Planner& planner,
                     const PlanOverrides& overrides) {
  PlanInput in;
  if (lower_extension(file) == ".xml") {
    // A journal says how its solids are merged (<imprint_merge>): its
    // geometry operations may depend on it.
    if (overrides.imprint_merge) {
      throw MeshingError(ErrorCode::InvalidInput,
                         overrides.origin + ": " + overrides.imprint_option +
                             " is for a CAD file; a journal sets it itself "
                             "(<imprint_merge enabled=\"false\"/>)");
    }
    io::Job job = io::read_journal(file);
    if (job.mesh) in.settings = *job.mesh;
    if (overrides.decompose) in.settings.decompose = *overrides.decompose;
    if (overrides.elements) in.settings.elements = *overrides.elements;
    if (overrides.max_elements) in.settings.max_elements = *overrides.max_elements;
    in.plugins = job.plugins;
    if (size) io::set_element_size(in.settings, *size);
    if (registry) {
      job.mesh = in.settings;
      DecomposedGeometry g = build_decomposed_geometry(job, *registry, planner);
      in.settings.size = g.size;
      in.settings.size_divisor.reset();
      in.model = std::move(g.model);
      in.decomposition = std::move(g.decomposition);
    } else {
      in.model = build_geometry(job);
    }
  } else {
    ModelJobOptions options;
    options.size = size.value_or(io::ElementSize{1.0, false});
    options.origin = overrides.origin;
    options.imprint_merge = overrides.imprint_merge.value_or(true);
    options.elements = overrides.elements.value_or(io::ElementKind::Hex);
    options.decompose = overrides.decompose.value_or(io::Decompose::Auto);
    io::Job job = model_job(file, options);
    if (!size) job.mesh->size.reset();  // a plan without a size skips the interval check
    in.settings = *job.mesh;
    if (overrides.max_elements) in.settings.max_elements = *overrides.max_elements;
    if (registry) {
      DecomposedGeometry g = build_decomposed_geometry(job, *registry, planner);
      in.settings.size = g.size;
      in.settings.size_divisor.reset();
      in.model = std::move(g.model);
      in.decomposition = std::move(g.decomposition);
    } else {
      in.model = load_any(file, options.imprint_merge);
    }
  }
  resolve_relative_size(in.settings, in.model);
  check_settings(in.model, in.settings);
  return in;
}

}  // namespace cooperage::pipeline
