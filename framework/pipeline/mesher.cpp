#include "framework/pipeline/mesher.h"

#include "framework/core/error.h"
#include "framework/core/log.h"
#include "framework/io/export/write_mesh.h"
#include "framework/pipeline/build_geometry.h"
#include "framework/pipeline/check_settings.h"
#include "framework/pipeline/commit_mesh.h"
#include "framework/pipeline/interval_setup.h"
#include "framework/pipeline/mesh_curves.h"
#include "framework/report/html_report.h"
#include "framework/report/report_from_run.h"

#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <chrono>
#include <map>
#include <memory>
#include <optional>

namespace cooperage::pipeline {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

struct Outcome {
  scheme::EntityMesh mesh;
  std::optional<MeshingError> error;
  double seconds = 0;
};

// Runs `work(id)` for every id, in parallel; results and the first error
// (by id, not by time) are deterministic.
template <class Work>
std::vector<Outcome> for_each_entity(const std::vector<int>& ids, Work work) {
  std::vector<Outcome> out(ids.size());
  tbb::parallel_for(size_t{0}, ids.size(), [&](size_t i) {
    const auto t0 = Clock::now();
    try {
      out[i].mesh = work(ids[i]);
    } catch (const MeshingError& e) {
      out[i].error = e;
    } catch (const std::exception& e) {
      out[i].error = MeshingError(ErrorCode::Internal, e.what());
    }
    out[i].seconds = seconds_since(t0);
  });
  for (const auto& o : out) {
    if (o.error) throw *o.error;
  }
  return out;
}

void report(const MeshOptions& options, const std::string& stage, size_t done, size_t total) {
  if (options.progress) options.progress(stage, done, total);
}

// One stage: mesh every entity of `ids` in parallel, then commit the results
// in id order (so the node numbering never depends on the thread count).
template <class MeshOne, class Commit>
void run_stage(const char* stage, int dim, const std::vector<int>& ids,
               const std::map<int, PlanEntry>& plan, MeshResult& result,
               const MeshOptions& options, MeshOne mesh_one, Commit commit) {
  report(options, stage, 0, ids.size());
  auto meshes = for_each_entity(ids, mesh_one);
  for (size_t i = 0; i < ids.size(); ++i) {
    for (std::string& w : meshes[i].mesh.warnings) {
      result.warnings.push_back({EntityRef{dim, ids[i]}, std::move(w)});
    }
    commit(meshes[i].mesh, ids[i], result.mesh);
    meshes[i].mesh = {};  // release the local copy now
    result.timings.push_back({dim, ids[i], plan.at(ids[i]).scheme, meshes[i].seconds});
  }
  report(options, stage, ids.size(), ids.size());
}

// The journal's HTML reports, after the exports (so they list them).
void write_reports(const io::Job& job, const MeshOptions& options, RunResult& result) {
  std::vector<std::string> written;
  for (const io::ReportSetting& r : job.reports) {
    const std::string path = resolve_path(job.base_dir, r.file);
    report(options, "report " + r.file, 0, 1);
    cooperage::report::write_report(path, cooperage::report::report_input(result, job.file));
    written.push_back(path);
  }
  result.written.insert(result.written.end(), written.begin(), written.end());
}

}  // namespace

std::string Warning::text() const {
  const std::string who = entity.name();
  return who.empty() ? message : who + ": " + message;
}

MeshResult mesh_model(const geom::Model& model, const io::MeshSettings& settings,
                      const scheme::Registry& registry, const MeshOptions& options) {
  std::unique_ptr<tbb::global_control> threads;
  if (options.threads > 0) {
    threads = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                    static_cast<size_t>(options.threads));
  }
  MeshResult result;
  auto stage_start = Clock::now();
  const auto lap = [&](const char* stage) {
    result.stages.push_back({stage, seconds_since(stage_start)});
    stage_start = Clock::now();
  };
  check_settings(model, settings);
  report(options, "plan", 0, 1);
  if (!options.planner) {
    throw MeshingError(ErrorCode::Internal,
                       "MeshOptions::planner is not set (use selector::planner())");
  }
  result.plan = options.planner(model, registry, settings, options.dim);
  lap("plan");
  report(options, "intervals", 0, 1);
  result.intervals =
      intervals::solve(build_interval_problem(model, registry, result.plan, settings));
  lap("intervals");
  report(options, "curves", 0, model.curves().size());
  mesh_curves(model, result.intervals.intervals, settings, result.mesh);
  lap("curves");

  scheme::MeshParams params;
  params.size = settings.size.value_or(1.0);

  std::vector<int> surfaces;
  for (const auto& [id, entry] : result.plan.surfaces) {
    if (entry.scheme != scheme::kMeshedByVolume) surfaces.push_back(id);
  }
  run_stage(
      "surfaces", 2, surfaces, result.plan.surfaces, result, options,
      [&](int id) {
        const auto* s = registry.surface_scheme(result.plan.surfaces.at(id).scheme);
        return s->mesh(scheme::SurfaceView{model, id, &result.mesh}, params);
      },
      commit_surface);
  lap("surfaces");

  std::vector<int> volumes;
  for (const auto& [id, entry] : result.plan.volumes) volumes.push_back(id);
  run_stage(
      "volumes", 3, volumes, result.plan.volumes, result, options,
      [&](int id) {
        const auto* s = registry.volume_scheme(result.plan.volumes.at(id).scheme);
        return s->mesh(scheme::VolumeView{model, id, &result.mesh}, params);
      },
      commit_volume);
  lap("volumes");

  // Never hand back inverted elements silently.
  result.quality = assess_quality(result.mesh, model, {});
  for (const auto& block : result.quality.blocks) {
    const auto* sj = block.find("scaled_jacobian");
    if (sj && sj->inverted > 0) {
      throw MeshingError(ErrorCode::MeshingFailed, EntityRef{block.dim, block.id},
                         std::to_string(sj->inverted) + " inverted " +
                             std::string(quality::to_string(block.type)) +
                             " elements (minimum scaled Jacobian " + std::to_string(sj->min) +
                             ")");
    }
  }
  lap("quality");
  return result;
}

RunResult run_job(const io::Job& job, const scheme::Registry& registry,
                  const MeshOptions& options) {
  if (!job.mesh) {
    throw MeshingError(ErrorCode::InvalidInput,
                       job.file + ": the journal has no <mesh> element, so there is nothing to run");
  }
  auto stage_start = Clock::now();
  RunResult result{build_geometry(job), {}, {}, {}, false, {}};
  result.stages.push_back({"geometry", seconds_since(stage_start)});
  MeshOptions opts = options;
  if (opts.threads == 0) opts.threads = job.mesh->threads;
  result.mesh = mesh_model(result.model, *job.mesh, registry, opts);
  result.stages.insert(result.stages.end(), result.mesh.stages.begin(), result.mesh.stages.end());
  stage_start = Clock::now();
  // The mesher's report already has the scaled Jacobian of every block;
  // evaluate again only when the journal checks metrics.
  result.quality = job.quality.empty() ? result.mesh.quality
                                       : assess_quality(result.mesh.mesh, result.model, job.quality);
  if (!job.quality.empty()) result.stages.push_back({"quality checks", seconds_since(stage_start)});
  if (result.quality.failed()) {
    result.exports_skipped = !job.exports.empty();
  } else {
    stage_start = Clock::now();
    for (const io::ExportSetting& e : job.exports) {
      const std::string path = resolve_path(job.base_dir, e.file);
      report(options, "export " + e.file, 0, 1);
      io::ExportOptions export_options;
      export_options.binary = e.binary;
      io::write_mesh(path, result.mesh.mesh, result.model, export_options);
      result.written.push_back(path);
    }
    if (!job.exports.empty()) result.stages.push_back({"exports", seconds_since(stage_start)});
  }
  write_reports(job, options, result);
  return result;
}

}  // namespace cooperage::pipeline
