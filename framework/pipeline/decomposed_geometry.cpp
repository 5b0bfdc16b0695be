#include "framework/pipeline/decomposed_geometry.h"

#include "framework/core/error.h"
#include "framework/geometry/occ/solid_pieces.h"
#include "framework/geometry/occ/workbench.h"
#include "framework/pipeline/build_geometry.h"
#include "framework/pipeline/mesher.h"
#include "framework/pipeline/relative_size.h"

#include <algorithm>
#include <chrono>
#include <map>
#include <string>
#include <variant>
#include <vector>

namespace cooperage::pipeline {
namespace {

std::string place(const io::SourceLocation& where) {
  if (where.file.empty()) return "the job";
  return where.line > 0 ? where.file + ":" + std::to_string(where.line) : where.file;
}

// The first per-entity setting of the job, as "<surface> at job.xml:12", or "".
std::string entity_setting(const io::MeshSettings& s) {
  const auto at = [](const char* tag, const io::SourceLocation& where) {
    return std::string("<") + (where.element.empty() ? tag : where.element.c_str()) + "> at " +
           place(where);
  };
  if (!s.curves.empty()) return at("curve", s.curves.front().where);
  if (!s.surfaces.empty()) return at("surface", s.surfaces.front().where);
  if (!s.volumes.empty()) return at("volume", s.volumes.front().where);
  if (!s.vertex_types.empty()) return at("vertex_type", s.vertex_types.front().where);
  return {};
}

// The first <block>/<sideset>/<nodeset> of the job, as "<block> at job.xml:12", or "".
std::string group_setting(const io::GroupSettings& g) {
  const auto at = [](const char* tag, const io::SourceLocation& where) {
    return std::string("<") + tag + "> at " + place(where);
  };
  if (!g.blocks.empty()) return at("block", g.blocks.front().where);
  if (!g.side_sets.empty()) return at("sideset", g.side_sets.front().where);
  if (!g.node_sets.empty()) return at("nodeset", g.node_sets.front().where);
  return {};
}

bool scheme_pinned(const io::MeshSettings& s, int volume) {
  for (const auto& v : s.volumes) {
    if (v.id == volume && v.scheme != "auto") return true;
  }
  return false;
}

// A volume mesh of a model that has surfaces but no volume (a surface
// model that no sewing closed, issue 16) is refused saying why, with the
// curves that bound a single surface counted, not run as a surface mesh.
void require_a_volume(const geom::Model& model, const io::Job& job) {
  if (!model.volumes().empty() || model.surfaces().empty()) return;
  std::vector<std::string> files;
  for (const io::GeometryStep& step : job.geometry) {
    if (const auto* import = std::get_if<io::ImportOp>(&step.op)) files.push_back(import->file);
  }
  std::map<int, int> uses;
  for (const geom::Surface& s : model.surfaces()) {
    for (const geom::Loop& loop : s.loops) {
      for (const geom::CurveUse& use : loop.uses) ++uses[use.curve];
    }
  }
  const auto open =
      std::count_if(uses.begin(), uses.end(), [](const auto& u) { return u.second == 1; });
  throw MeshingError(
      ErrorCode::InvalidInput, EntityRef::none(),
      (files.size() == 1 ? files.front() + ": " : std::string()) + "no volume to mesh: " +
          (model.surfaces().size() == 1
               ? std::string("its one surface bounds none (")
               : "its " + std::to_string(model.surfaces().size()) + " surfaces bound none (") +
          std::to_string(open) + " curves bound a single surface, even after sewing)",
      "`cooperage mesh FILE --dim 2` meshes the surfaces");
}

}  // namespace

double decomposition_size(const io::MeshSettings& settings, const geom::Model& model) {
  if (settings.size) return *settings.size;
  const double d = model.box().diagonal();
  return d > 0 ? d / 40.0 : 1.0;
}

DecomposedGeometry build_decomposed_geometry(const io::Job& job, const scheme::Registry& registry,
                                             const Planner& planner, int dim, int threads) {
  const auto t0 = std::chrono::steady_clock::now();
  occ::Workbench bench;
  bench.set_imprint_merge(job.imprint_merge);
  run_geometry(job, bench, /*will_mesh=*/true);
  occ::BuildOptions build;
  build.imprint_merge = job.imprint_merge;
  DecomposedGeometry out;
  out.model = bench.build_model(build);
  out.geometry_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (dim == 3) require_a_volume(out.model, job);
  out.decomposition.origin.clear();
  for (const geom::Volume& v : out.model.volumes()) out.decomposition.origin.push_back(v.id);
  if (!job.mesh) return out;
  io::MeshSettings settings = *job.mesh;
  resolve_relative_size(settings, out.model);
  out.size = settings.size;
  if (dim != 3 || settings.decompose == io::Decompose::Off) return out;

  const scheme::Settings job_settings = scheme::Settings::of(settings);
  const std::vector<decompose::RefusedVolume> refused =
      decompose::refused_volumes(out.model, registry, &job_settings);
  if (refused.empty()) return out;
  for (const auto& r : refused) {
    if (scheme_pinned(settings, r.volume)) return out;  // the planner refuses the pin, naming it
  }
  std::string setting = entity_setting(settings);
  if (setting.empty()) setting = group_setting(job.groups);
  if (!setting.empty()) {
    const int v = refused.front().volume;
    throw MeshingError(ErrorCode::NotApplicable, EntityRef::volume(v),
                       job_settings.no_scheme_applies(v) +
                           ", and automatic decomposition would renumber the "
                           "entities that " +
                           setting +
                           " refers to by id; cut the volume with "
                           "<webcut> in the journal, or remove the per-entity settings");
  }
  if (!planner) throw MeshingError(ErrorCode::Internal, "decomposition needs a planner");
  io::MeshSettings piece_settings = settings;
  const decompose::ModelCheck check = [&](const geom::Model& pieces, bool rings) -> std::string {
    try {
      // The planner refuses volumes one by one in an assembly (per-volume
      // verdicts): a cut is good only when no piece is refused.
      const SchemePlan plan = planner(pieces, registry, piece_settings, 3);
      if (!plan.refused_volumes.empty()) {
        const auto& [volume, refusal] = *plan.refused_volumes.begin();
        return "volume " + std::to_string(volume) + ": " + refusal.message;
      }
      if (!rings && !plan.ring_closers.empty()) {
        return "volume " + std::to_string(*plan.ring_closers.begin()) +
               " would close a ring of sweeps (a cut needing that is the last resort)";
      }
      return {};
    } catch (const MeshingError& e) {
      return e.what();
    }
  };
  decompose::DecomposeOptions options;
  options.size = decomposition_size(settings, out.model);
  options.settings = &job_settings;
  options.threads = limit_threads_count(threads > 0 ? threads : settings.threads);
  decompose::Decomposed d = decompose::decompose(occ::SolidPieces::of(bench, build), out.model,
                                                 registry, check, options, refused);
  out.model = std::move(d.model);
  out.decomposition = std::move(d.report);
  return out;
}

}  // namespace cooperage::pipeline
