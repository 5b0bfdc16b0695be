#include "framework/pipeline/model_job.h"

#include <cctype>
#include <filesystem>

#include "framework/core/error.h"
#include "framework/io/journal_reader.h"
#include "framework/pipeline/build_geometry.h"
#include "framework/pipeline/check_settings.h"

namespace cooperage::pipeline {

io::Job model_job(const std::string& model, const ModelJobOptions& options) {
  if (!(options.size > 0)) {
    throw MeshingError(ErrorCode::InvalidInput, options.origin +
                                                    ": the element size must be positive, got " +
                                                    std::to_string(options.size));
  }
  io::Job job;
  job.file = model;
  io::ImportOp import;
  import.name = std::filesystem::path(model).stem().string();
  import.file = model;
  job.geometry.push_back({import, {model, 0, "import"}});
  job.imprint_merge = options.imprint_merge;
  job.mesh = io::MeshSettings{};
  job.mesh->size = options.size;
  if (options.elements != io::ElementKind::Hex) {
    const geom::Model m = load_any(model, options.imprint_merge);
    for (const geom::Volume& v : m.volumes()) {
      io::VolumeSetting setting;
      setting.id = v.id;
      setting.elements = options.elements;
      setting.where = {options.origin, 0, options.elements_option};
      job.mesh->volumes.push_back(setting);
    }
  }
  for (const std::string& e : options.exports) {
    const std::string ext = std::filesystem::path(e).extension().string();
    if (options.binary && ext != ".vtu" && ext != ".msh") {
      throw MeshingError(ErrorCode::InvalidInput,
                         options.origin + ": " + options.binary_option +
                             " is for .vtu and .msh outputs (Exodus is always binary), not '" + e +
                             "'");
    }
    job.exports.push_back({e, {options.origin, 0, options.export_option}, options.binary});
  }
  for (const std::string& r : options.reports) {
    job.reports.push_back({r, {options.origin, 0, options.report_option}});
  }
  return job;
}

PlanInput plan_input(const std::string& file, std::optional<double> size) {
  std::string ext = std::filesystem::path(file).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  PlanInput in;
  if (ext == ".xml") {
    const io::Job job = io::read_journal(file);
    if (job.mesh) in.settings = *job.mesh;
    in.plugins = job.plugins;
    in.model = build_geometry(job);
  } else {
    in.model = load_any(file);
  }
  if (size) in.settings.size = size;
  check_settings(in.model, in.settings);
  return in;
}

}  // namespace cooperage::pipeline
