#include "cooperage/cooperage.h"

#include "framework/io/journal_reader.h"
#include "framework/pipeline/model_job.h"
#include "schemes/builtin_schemes.h"
#include "selector/select_schemes.h"

namespace cooperage {
namespace {

Result run_one(const io::Job& job, int dim, const Options& options) {
  scheme::Registry registry;
  register_schemes(registry, run_plugins(options.plugins, job.plugins));
  pipeline::RunResult run =
      pipeline::run_job(job, registry, selector::mesh_options(dim, options.threads));
  Result r;
  r.model = std::move(run.model);
  r.mesh = std::move(run.mesh.mesh);
  r.quality = std::move(run.quality);
  r.plan = std::move(run.mesh.plan);
  r.decomposition = std::move(run.decomposition);
  r.warnings = std::move(run.mesh.warnings);
  r.written = std::move(run.written);
  r.stages = std::move(run.stages);
  return r;
}

}  // namespace

Result mesh_file(const std::string& path, double size, const Options& options) {
  if (options.dim != 2 && options.dim != 3) {
    throw MeshingError(ErrorCode::InvalidInput, "cooperage::mesh_file(): dim must be 2 or 3, got " +
                                                    std::to_string(options.dim));
  }
  if (options.finer_retries < 0 || options.finer_retries > io::MeshSettings::kMaxFinerRetries) {
    throw MeshingError(ErrorCode::InvalidInput,
                       "cooperage::mesh_file(): Options::finer_retries must be 0 to " +
                           std::to_string(io::MeshSettings::kMaxFinerRetries) + ", got " +
                           std::to_string(options.finer_retries));
  }
  pipeline::ModelJobOptions job;
  job.size = size;
  job.decompose = options.decompose;
  job.finer_retries = options.finer_retries;
  job.min_scaled_jacobian = options.min_scaled_jacobian;
  job.min_scaled_jacobian_option = "Options::min_scaled_jacobian";
  job.imprint_merge = options.imprint_merge;
  job.elements = options.elements;
  job.exports = options.exports;
  job.origin = "cooperage::mesh_file()";
  job.export_option = "Options::exports";
  io::Job built = pipeline::model_job(path, job);
  built.groups = options.groups;
  const io::SourceLocation where{"cooperage::mesh_file()", 0, "Options::groups"};
  auto named = [&](auto& groups, const char* prefix) {
    for (auto& g : groups) {
      if (g.name.empty()) g.name = prefix + std::to_string(g.id);
      g.where = where;
    }
  };
  named(built.groups.blocks, "block_");
  named(built.groups.side_sets, "sideset_");
  named(built.groups.node_sets, "nodeset_");
  return run_one(built, options.dim, options);
}

Result run_journal(const std::string& journal, const Options& options) {
  io::Job job = io::read_journal(journal);
  for (const std::string& e : options.exports) {
    job.exports.push_back({e, {"cooperage::run_journal()", 0, "Options::exports"}});
  }
  return run_one(job, 3, options);
}

}  // namespace cooperage
