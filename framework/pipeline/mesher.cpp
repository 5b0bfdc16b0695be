#include "framework/pipeline/mesher.h"

#include "framework/core/error.h"
#include "framework/core/log.h"
#include "framework/core/text.h"
#include "framework/geometry/validate.h"
#include "framework/io/export/write_mesh.h"
#include "framework/pipeline/build_geometry.h"
#include "framework/pipeline/check_settings.h"
#include "framework/pipeline/commit_mesh.h"
#include "framework/pipeline/finer_retry.h"
#include "framework/pipeline/interval_setup.h"
#include "framework/pipeline/mesh_curves.h"
#include "framework/report/html_report.h"
#include "framework/report/report_from_run.h"
#include "framework/pipeline/mesh_size.h"
#include "framework/pipeline/partial_mesh.h"
#include "framework/pipeline/worst_element.h"

#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_group.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <cstdio>
#include <exception>
#include <map>
#include <numeric>
#include <memory>
#include <optional>
#include <set>
#include <thread>

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

// Runs `work(id)` for every id, in parallel; every entity's result or error
// is kept, in id order, whatever the scheduling.
template <class Work>
std::vector<Outcome> for_each_entity(const std::vector<int>& ids, Work work) {
  std::vector<Outcome> out(ids.size());
  tbb::parallel_for(size_t{0}, ids.size(), [&](size_t i) {
    const auto t0 = Clock::now();
    try {
      out[i].mesh = work(ids[i]);
    } catch (const MeshingError& e) {
      out[i].error = e;
    } catch (const std::bad_alloc&) {
      out[i].error =
          MeshingError(ErrorCode::InvalidInput, EntityRef::none(),
                       "ran out of memory while meshing it", "use a larger element size");
    } catch (const std::exception& e) {
      out[i].error = MeshingError(ErrorCode::Internal, e.what());
    }
    out[i].seconds = seconds_since(t0);
  });
  return out;
}

void report(const MeshOptions& options, const std::string& stage, size_t done, size_t total) {
  if (options.progress) options.progress(stage, done, total);
}

/// Per entity of the run (volume in 3D, surface in 2D): its refusal, if any.
class Refusals {
 public:
  bool refused(int id) const { return refused_.count(id) > 0; }
  void refuse(int id, ErrorCode code, const std::string& reason, const std::string& hint,
              bool finer_may_help = false) {
    refused_.emplace(
        id, Verdict{EntityRef{}, Verdict::State::Refused, code, reason, hint, finer_may_help});
  }
  const std::map<int, Verdict>& all() const { return refused_; }

 private:
  std::map<int, Verdict> refused_;  // first reason wins
};

// One stage: mesh every entity of `ids` in parallel, then commit the
// successes in id order (so the node numbering never depends on the thread
// count) and hand each failure to `failed`.
template <class MeshOne, class Commit, class Failed>
void run_stage(const char* stage, int dim, const std::vector<int>& ids,
               const std::map<int, PlanEntry>& plan, MeshResult& result, const MeshOptions& options,
               MeshOne mesh_one, Commit commit, Failed failed) {
  report(options, stage, 0, ids.size());
  auto meshes = for_each_entity(ids, mesh_one);
  for (size_t i = 0; i < ids.size(); ++i) {
    if (meshes[i].error) {
      failed(ids[i], *meshes[i].error);
      continue;
    }
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

std::string percent(double fraction) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g %%", 100.0 * fraction);
  return buf;
}

/// What to do about a volume no scheme fits (issue 16 item 5: an error says
/// what to do).
constexpr const char* kNoSchemeHint =
    "`cooperage plan` gives every scheme's reason; cut the volume with <webcut> or give it a "
    "sweep hint (<volume sources/targets/direction>)";

/// What to do about a volume its scheme accepted and then failed on: in the
/// plan => mesh campaign (bench/RESULTS.md, session 20) such failures are
/// mostly features closer than an element, and half the size meshed a
/// third of them.
std::string failed_volume_hint(const io::MeshSettings& settings, int volume) {
  std::optional<double> size = settings.size;
  for (const auto& v : settings.volumes) {
    if (v.id == volume && v.sizing.size) size = v.sizing.size;
  }
  const std::string id = std::to_string(volume);
  std::string tag = "<volume id=\"" + id + "\" size=\"" +
                    (size ? number_text(0.5 * *size) : std::string("...")) + "\"/>";
  return "features closer than an element may meet here: a smaller size on volume " + id + " (" +
         tag + ") or a <webcut> between them may mesh it";
}

std::unique_ptr<tbb::global_control> limit_threads(int requested) {
  return std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                               static_cast<size_t>(limit_threads_count(requested)));
}

}  // namespace

// A journal asking for 2,147,483,647 threads ran out of memory (issue 21).
int limit_threads_count(int requested) {
  const int hardware = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  return requested > 0 ? std::min(requested, hardware) : hardware;
}

std::string Warning::text() const {
  const std::string who = entity.name();
  return who.empty() ? message : who + ": " + message;
}

bool MeshResult::incomplete() const {
  return std::any_of(verdicts.begin(), verdicts.end(),
                     [](const Verdict& v) { return v.state != Verdict::State::Meshed; });
}

bool RunResult::failed() const { return quality.failed() || mesh.incomplete(); }

IncompleteMesh::IncompleteMesh(const Verdict& first, std::vector<Verdict> verdicts,
                               const std::string& hint)
    : MeshingError(first.code, first.entity, first.reason, hint), verdicts_(std::move(verdicts)) {}

namespace {

// One pass of the pipeline at the sizes of `job_settings`: every entity
// gets a verdict; refusals are not thrown here (finish_result does).
MeshResult mesh_attempt(const geom::Model& model, const io::MeshSettings& job_settings,
                        const scheme::Registry& registry, const MeshOptions& options) {
  // --volume-tolerance overrides the journal's for the sizing too (the
  // faceting budget of curve_sizing.h takes half of it).
  std::optional<io::MeshSettings> overridden;
  if (options.volume_tolerance) {
    overridden = job_settings;
    overridden->volume_tolerance = options.volume_tolerance;
  }
  const io::MeshSettings& settings = overridden ? *overridden : job_settings;
  MeshResult result;
  auto stage_start = Clock::now();
  const auto lap = [&](const char* stage) {
    result.stages.push_back({stage, seconds_since(stage_start)});
    stage_start = Clock::now();
  };
  if (!options.planner) {
    throw MeshingError(ErrorCode::Internal,
                       "MeshOptions::planner is not set (use selector::planner())");
  }
  const double max_elements = element_limit(settings, options.max_elements);
  const double tolerance =
      options.volume_tolerance.value_or(settings.volume_tolerance.value_or(0.01));
  const int dim = options.dim;

  geom::validate(model);
  check_settings(model, settings);
  // Before planning: the selector solves interval problems already.
  check_mesh_size(estimate_mesh_size(model, interval_goals(model, settings), dim), max_elements);

  result.volume_tolerance = tolerance;
  report(options, "plan", 0, 1);
  result.plan = options.planner(model, registry, settings, dim);
  lap("plan");
  report(options, "intervals", 0, 1);
  // The planner solved this very problem when it checked feasibility.
  result.intervals =
      result.plan.intervals
          ? *result.plan.intervals
          : intervals::solve(build_interval_problem(model, registry, result.plan, settings));
  {
    std::map<int, double> counts;
    for (const auto& [curve, n] : result.intervals.intervals) counts[curve] = n;
    check_mesh_size(estimate_mesh_size(model, counts, dim), max_elements);
  }
  lap("intervals");
  // The one settings object every scheme reads (view.job and mesh()'s
  // argument); each gets back the plan its applicable() made (PlanEntry::data).
  const scheme::Settings params = scheme::Settings::of(settings, options.dim);

  report(options, "curves", 0, model.curves().size());
  // The volume schemes place the nodes along their curves (by volume id:
  // the same for every run); only when they mesh the volumes. The curves
  // whose sizes they changed are marked (submap keeps their grading).
  if (dim == 3) {
    const auto before = result.intervals.sizes;
    for (const auto& [id, entry] : result.plan.volumes) {
      if (const auto* s = registry.volume_scheme(entry.scheme))
        s->space_curves(scheme::VolumeView{model, id, &result.mesh, &params, entry.data.get()},
                        result.intervals.intervals, result.intervals.sizes);
    }
    for (const auto& [curve, f] : result.intervals.sizes) {
      const auto was = before.find(curve);
      if (was == before.end() || was->second.at != f.at || was->second.size != f.size)
        result.mesh.set_curve_placed_by_volume(curve);
    }
  }
  mesh_curves(model, result.intervals.intervals, settings, result.mesh, &result.intervals.sizes);
  lap("curves");

  // Verdict entities: volumes in 3D, surfaces in 2D.
  Refusals refusals;
  for (const auto& [vid, r] : result.plan.refused_volumes)
    refusals.refuse(vid, r.code, r.message,
                    r.hint.empty() && r.code == ErrorCode::NotApplicable ? kNoSchemeHint : r.hint);
  auto surface_blocked = [&](int sid) {  // every volume it bounds is refused
    const auto& vols = model.surface(sid).volumes;
    return dim == 3 && !vols.empty() &&
           std::all_of(vols.begin(), vols.end(), [&](int v) { return refusals.refused(v); });
  };
  auto surface_failed = [&](int sid, const MeshingError& e) {
    if (dim == 2 || model.surface(sid).volumes.empty()) {
      refusals.refuse(sid, e.code(), e.message(), e.hint());
      return;
    }
    for (int v : model.surface(sid).volumes)
      refusals.refuse(v, e.code(), "surface " + std::to_string(sid) + ": " + e.message(), e.hint(),
                      e.code() == ErrorCode::MeshingFailed);
  };

  std::vector<int> surfaces;
  for (const auto& [id, entry] : result.plan.surfaces) {
    if (entry.scheme != scheme::kMeshedByVolume && !surface_blocked(id)) surfaces.push_back(id);
  }
  run_stage(
      "surfaces", 2, surfaces, result.plan.surfaces, result, options,
      [&](int id) {
        const PlanEntry& entry = result.plan.surfaces.at(id);
        const auto* s = registry.surface_scheme(entry.scheme);
        if (dim == 3 && entry.any_quad_mesh) {
          scheme::Settings own = params;
          own.allow_quad_fallback = true;
          return s->mesh(scheme::SurfaceView{model, id, &result.mesh, &own, entry.data.get()}, own);
        }
        return s->mesh(scheme::SurfaceView{model, id, &result.mesh, &params, entry.data.get()},
                       params);
      },
      commit_surface, surface_failed);
  lap("surfaces");

  // Volumes in waves: a volume that takes a neighbour's mesh of a shared
  // surface (plan.waits_for) is meshed after it, in parallel with the rest
  // of its wave; commits stay in wave-then-id order (deterministic).
  // The scaled Jacobians the schemes computed on their final nodes, taken
  // by the quality report below instead of computing every element again.
  KnownScaledJacobians known;
  auto commit_volume_keep_quality = [&known](scheme::EntityMesh& m, int id, mesh::MeshDB& db) {
    if (!m.hex_scaled_jacobian.empty()) known.hexes[id] = std::move(m.hex_scaled_jacobian);
    if (!m.wedge_scaled_jacobian.empty()) known.wedges[id] = std::move(m.wedge_scaled_jacobian);
    commit_volume(m, id, db);
  };
  std::vector<int> pending;
  for (const auto& [id, entry] : result.plan.volumes)
    if (!refusals.refused(id)) pending.push_back(id);
  std::set<int> done;
  while (!pending.empty()) {
    std::vector<int> wave, later;
    for (int id : pending) {
      const auto w = result.plan.waits_for.find(id);
      bool ready = true;
      if (w != result.plan.waits_for.end()) {
        for (int other : w->second) {
          if (refusals.refused(other)) {
            refusals.refuse(id, ErrorCode::MeshingFailed,
                            "it takes the mesh of a shared surface from volume " +
                                std::to_string(other) + ", which could not be meshed",
                            "");
            ready = false;
            break;
          }
          ready = ready && done.count(other) > 0;
        }
      }
      if (refusals.refused(id)) continue;
      (ready ? wave : later).push_back(id);
    }
    if (wave.empty() && later.empty()) break;  // the rest was refused: its makers failed
    if (wave.empty()) {                        // the selector keeps the waits acyclic
      throw MeshingError(ErrorCode::Internal, "volumes wait for each other's meshes");
    }
    run_stage(
        "volumes", 3, wave, result.plan.volumes, result, options,
        [&](int id) {
          const PlanEntry& entry = result.plan.volumes.at(id);
          const auto* s = registry.volume_scheme(entry.scheme);
          return s->mesh(scheme::VolumeView{model, id, &result.mesh, &params, entry.data.get()},
                         params);
        },
        commit_volume_keep_quality,
        [&](int id, const MeshingError& e) {
          const bool failed = e.code() == ErrorCode::MeshingFailed;
          refusals.refuse(id, e.code(), e.message(),
                          e.hint().empty() && failed ? failed_volume_hint(settings, id) : e.hint(),
                          failed);
        });
    done.insert(wave.begin(), wave.end());
    pending = std::move(later);
  }
  lap("volumes");

  // The caller's work on the finished mesh (the exports) runs beside the
  // checks below; it is waited for on every way out of this function.
  tbb::task_group beside;
  struct Wait {
    tbb::task_group& group;
    ~Wait() { group.wait(); }
  } wait_beside{beside};
  if (options.beside_checks && refusals.all().empty()) {
    beside.run([&] {
      try {
        options.beside_checks(result.mesh);
      } catch (...) {  // documented not to throw; never let it end the process
      }
    });
  }

  // Never hand back inverted elements silently.
  result.quality = assess_quality(result.mesh, model, options.quality_checks, &known);
  known = {};
  for (const auto& block : result.quality.blocks) {
    const auto* sj = block.find("scaled_jacobian");
    if (!sj || sj->inverted == 0) continue;
    const int entity = dim == 3 && block.dim == 2 ? (model.surface(block.id).volumes.empty()
                                                         ? 0
                                                         : model.surface(block.id).volumes.front())
                                                  : block.id;
    if (entity == 0) {  // a free face in a volume run: no verdict entity to carry it
      throw MeshingError(ErrorCode::MeshingFailed, EntityRef{block.dim, block.id},
                         std::to_string(sj->inverted) + " inverted elements");
    }
    refusals.refuse(entity, ErrorCode::MeshingFailed,
                    (block.dim == 2 && dim == 3 ? "surface " + std::to_string(block.id) + ": "
                                                : std::string()) +
                        std::to_string(sj->inverted) + " inverted " +
                        std::string(quality::to_string(block.type)) +
                        " elements (minimum scaled Jacobian " + std::to_string(sj->min) + ")",
                    "", dim == 3);
  }

  // The meshed volume (area) against the CAD's, for what meshed.
  std::map<int, std::string> deviates;
  for (MeasureCheck& m : compare_measures(model, result.mesh)) {
    if (refusals.refused(m.entity.id)) continue;
    const double d = m.deviation();
    const char* what = m.entity.dim == 3 ? "volume" : "area";
    const std::string text = "its meshed " + std::string(what) + " " +
                             number_text(m.mesh + m.faceting) + " deviates " + percent(d) +
                             " from the CAD's " + number_text(m.cad) +
                             (m.faceting != 0 ? " (faceting of curved faces credited)" : "");
    if (d > 0.01) {
      result.warnings.push_back({m.entity, text});
    } else if (const double raw = m.cad > 0 ? std::abs(m.mesh - m.cad) / m.cad : 0.0; raw > 0.01) {
      // Correct facets, yet a person asked for the part and gets this much
      // less of it (a rod at a coarse size is a hexagonal prism): say so.
      result.warnings.push_back({m.entity, "its meshed " + std::string(what) + " " +
                                               number_text(m.mesh) + " is " + percent(raw) +
                                               (m.mesh < m.cad ? " below" : " above") +
                                               " the CAD's " + number_text(m.cad) +
                                               ": the elements facet its curved faces coarsely; a "
                                               "smaller size follows them closer"});
    }
    if (d > tolerance) deviates[m.entity.id] = text + "; the tolerance is " + percent(tolerance);
    result.measures.push_back(m);
  }

  // A valid but poor volume mesh says where its worst element is and
  // whether the part's corners allow better.
  if (dim == 3) {
    std::set<int> poor;
    for (const auto& block : result.quality.blocks) {
      const auto* sj = block.find("scaled_jacobian");
      if (block.dim == 3 && sj && sj->inverted == 0 && sj->min < kPoorElement)
        poor.insert(block.id);
    }
    for (int v : poor) {
      if (refusals.refused(v)) continue;
      std::string note = worst_element_note(model, result.mesh, v);
      if (!note.empty()) result.warnings.push_back({EntityRef::volume(v), std::move(note)});
    }
  }

  // Verdicts, in id order.
  std::vector<int> entities;
  if (dim == 3) {
    for (const geom::Volume& v : model.volumes()) entities.push_back(v.id);
  } else {
    for (const auto& [id, entry] : result.plan.surfaces) entities.push_back(id);
  }
  const int verdict_dim = dim == 3 ? 3 : 2;
  for (int id : entities) {
    Verdict v{EntityRef{verdict_dim, id}, Verdict::State::Meshed, ErrorCode::NotApplicable, "", ""};
    if (auto it = refusals.all().find(id); it != refusals.all().end()) {
      v = it->second;
      v.entity = EntityRef{verdict_dim, id};
    } else if (auto d = deviates.find(id); d != deviates.end()) {
      v.state = Verdict::State::Deviates;
      v.reason = d->second;
    }
    result.verdicts.push_back(std::move(v));
  }

  lap("quality");
  beside.wait();  // before `result` leaves this function
  return result;
}

// The refusals of an attempt: thrown (the first one, or IncompleteMesh for
// an assembly) unless allow_partial, which keeps what meshed.
void finish_result(MeshResult& result, const geom::Model& model, const MeshOptions& options) {
  const auto t0 = Clock::now();
  const int verdict_dim = options.dim == 3 ? 3 : 2;
  std::set<int> good;
  for (const Verdict& v : result.verdicts)
    if (v.state == Verdict::State::Meshed) good.insert(v.entity.id);
  const auto first_refused =
      std::find_if(result.verdicts.begin(), result.verdicts.end(),
                   [](const Verdict& v) { return v.state == Verdict::State::Refused; });
  if (first_refused != result.verdicts.end() && !options.allow_partial) {
    if (result.verdicts.size() == 1)
      throw MeshingError(first_refused->code, first_refused->entity, first_refused->reason,
                         first_refused->hint);
    Verdict first = *first_refused;
    for (const Verdict& v : result.verdicts)
      if (v.state == Verdict::State::Refused && v.code == ErrorCode::Internal) first.code = v.code;
    const std::size_t refused = static_cast<std::size_t>(
        std::count_if(result.verdicts.begin(), result.verdicts.end(),
                      [](const Verdict& v) { return v.state == Verdict::State::Refused; }));
    const char* kind = verdict_dim == 3 ? "volumes" : "surfaces";
    const std::string hint =
        std::to_string(refused) + " of " + std::to_string(result.verdicts.size()) + " " + kind +
        " could not be meshed" +
        (good.empty()
             ? std::string()
             : "; --allow-partial writes the " + std::to_string(good.size()) + " that meshed") +
        // What to do about the first refusal too (issue 16 item 5).
        (first.hint.empty() ? std::string() : "; for " + first.entity.name() + ": " + first.hint);
    throw IncompleteMesh(first, result.verdicts, hint);
  }
  if (options.allow_partial && result.incomplete()) {
    if (good.empty()) {
      const Verdict& v =
          first_refused != result.verdicts.end() ? *first_refused : result.verdicts.front();
      throw MeshingError(v.state == Verdict::State::Refused ? v.code : ErrorCode::MeshingFailed,
                         v.entity, v.reason.empty() ? "nothing could be meshed" : v.reason, v.hint);
    }
    result.mesh = keep_entities(result.mesh, model, verdict_dim == 3 ? good : std::set<int>{},
                                verdict_dim == 3 ? std::set<int>{} : good);
    result.mesh_replaced = true;
    result.quality = assess_quality(result.mesh, model, options.quality_checks);
  }
  if (!result.stages.empty()) result.stages.back().seconds += seconds_since(t0);
}

}  // namespace

MeshResult mesh_model(const geom::Model& model, const io::MeshSettings& settings,
                      const scheme::Registry& registry, const MeshOptions& options) {
  const auto threads = limit_threads(options.threads);
  MeshResult result = mesh_attempt(model, settings, registry, options);
  if (options.dim == 3 && settings.finer_retries > 0) {
    io::MeshSettings finer = settings;
    std::map<int, FinerRetry> retries;
    const SchemePlan first_plan = result.plan;
    double earlier = 0;  // seconds of the attempts that failed
    const auto seconds = [](const MeshResult& r) {
      return std::accumulate(r.stages.begin(), r.stages.end(), 0.0,
                             [](double t, const StageTime& st) { return t + st.seconds; });
    };
    for (int round = 0; round < settings.finer_retries; ++round) {
      const std::vector<int> halved = halve_failed_volumes(result.verdicts, finer, retries);
      if (halved.empty()) break;
      for (int volume : halved)
        log::info("volume " + std::to_string(volume) + " failed at size " +
                  number_text(2 * retries.at(volume).size) + "; meshing again at " +
                  number_text(retries.at(volume).size));
      earlier += seconds(result);
      result = mesh_attempt(model, finer, registry, options);
    }
    // Straight sweeps that failed at every size, the other way at the size
    // asked for and then finer again; kept when fewer volumes are refused
    // than before.
    note_planned_sweeps(first_plan, settings, retries);
    std::map<int, FinerRetry> turned_retries = retries;
    const std::vector<int> turned = turn_failed_sweeps(result.verdicts, finer, turned_retries);
    if (!turned.empty()) {
      for (int volume : turned)
        log::info("volume " + std::to_string(volume) + " failed at every size; sweeping it the " +
                  "other way at size " + number_text(turned_retries.at(volume).asked));
      MeshResult other = mesh_attempt(model, finer, registry, options);
      for (int round = 0; round < settings.finer_retries; ++round) {
        if (halve_failed_volumes(other.verdicts, finer, turned_retries, &turned).empty()) break;
        earlier += seconds(other);
        other = mesh_attempt(model, finer, registry, options);
      }
      const auto refused = [](const MeshResult& r) {
        return std::count_if(r.verdicts.begin(), r.verdicts.end(),
                             [](const Verdict& v) { return v.state == Verdict::State::Refused; });
      };
      if (refused(other) < refused(result)) {
        earlier += seconds(result);
        result = std::move(other);
      } else {
        earlier += seconds(other);
      }
      retries = std::move(turned_retries);
    }
    // Volumes that meshed worse than a failing quality check allows: the
    // run would write nothing, so they are meshed again at half their size,
    // and half that, at most finer_retries times; the best attempt is kept
    // (every retried volume better, nothing refused).
    const std::optional<double> floor = failing_scaled_jacobian_floor(options.quality_checks);
    if (floor && retries.empty() && !result.incomplete()) {
      io::MeshSettings current = settings;  // the latest attempt's
      std::map<int, FinerRetry> tried;      // the latest attempt's halvings
      std::vector<int> halved;
      std::optional<MeshResult> latest;  // the latest attempt, when not kept
      bool restaged = false;             // an attempt after the kept one staged exports
      for (int round = 0; round < settings.finer_retries; ++round) {
        // From the latest attempt: its volumes still below the floor, or,
        // when it was refused, the same volumes once more.
        halved = latest && latest->incomplete()
                     ? halve_volumes_again(halved, current, tried)
                     : halve_poor_volumes(latest ? *latest : result, *floor, current, tried);
        if (halved.empty()) break;
        for (int volume : halved)
          log::info("volume " + std::to_string(volume) + " below the quality check's " +
                    number_text(*floor) + "; meshing it again at size " +
                    number_text(tried.at(volume).size));
        restaged = true;
        try {
          latest = mesh_attempt(model, current, registry, options);
        } catch (const MeshingError& e) {  // e.g. above max_elements
          log::info("meshing again failed: " + e.message());
          break;
        }
        bool better = !latest->incomplete();
        for (const auto& [volume, r] : tried) {
          const auto before = worst_scaled_jacobian(result, volume);
          const auto after = worst_scaled_jacobian(*latest, volume);
          better = better && after && before && *after > *before;
        }
        if (better) {
          earlier += seconds(result);
          result = std::move(*latest);
          latest.reset();
          retries = tried;
          restaged = false;
        } else {
          earlier += seconds(*latest);
        }
      }
      // The exports staged beside a later attempt are another mesh's.
      if (restaged) result.mesh_replaced = true;
    }
    // Straight sweeps that meshed poorly at the size asked for, once the
    // other way there; kept when nothing is refused and every one of them
    // is better so by kTurnPoorSweepsGain.
    if (retries.empty() && !result.incomplete()) {
      io::MeshSettings other_way = settings;
      std::map<int, FinerRetry> poor;
      const std::vector<int> poorly =
          turn_poor_sweeps(result, kTurnPoorSweepsBelow, other_way, poor);
      for (int volume : poorly)
        log::info("volume " + std::to_string(volume) + " meshed with a worst scaled Jacobian of " +
                  number_text(*poor.at(volume).planned_worst) +
                  "; sweeping it the other way at the same size");
      if (!poorly.empty()) {
        try {
          MeshResult other = mesh_attempt(model, other_way, registry, options);
          bool better = !other.incomplete();
          for (int volume : poorly) {
            const auto before = worst_scaled_jacobian(result, volume);
            const auto after = worst_scaled_jacobian(other, volume);
            better = better && after && before && *after > *before + kTurnPoorSweepsGain;
          }
          if (better) {
            earlier += seconds(result);
            result = std::move(other);
            retries = std::move(poor);
          } else {
            earlier += seconds(other);
            result.mesh_replaced = true;  // the exports staged beside it are its mesh's
          }
        } catch (const MeshingError& e) {  // e.g. above max_elements
          log::info("sweeping the other way failed: " + e.message());
        }
      }
    }
    if (earlier > 0) result.stages.insert(result.stages.begin(), {"failed attempts", earlier});
    report_finer_retries(retries, result);
  }
  finish_result(result, model, options);
  return result;
}

RunResult run_job(const io::Job& job, const scheme::Registry& registry,
                  const MeshOptions& options) {
  if (!job.mesh) {
    throw MeshingError(
        ErrorCode::InvalidInput,
        clip_path(job.file) + ": the journal has no <mesh> element, so there is nothing to run");
  }
  check_elements_for_dim(*job.mesh, options.dim);
  // Every target is checked before any work, and no two name one file.
  std::map<std::string, const io::ExportSetting*> targets;
  for (const io::ExportSetting& e : job.exports) {
    const std::string path = resolve_path(job.base_dir, e.file);
    try {
      io::check_export_target(path);
    } catch (const MeshingError& err) {
      throw MeshingError(err.code(), where_prefix(e.where) + err.message());
    }
    std::error_code ec;
    std::string key = std::filesystem::weakly_canonical(path, ec).string();
    if (ec) key = path;
    if (auto [it, fresh] = targets.emplace(key, &e); !fresh)
      throw MeshingError(ErrorCode::InvalidInput, where_prefix(e.where) + "\"" + clip_path(e.file) +
                                                      "\" is the same file as the export at line " +
                                                      std::to_string(it->second->where.line));
  }
  auto stage_start = Clock::now();
  RunResult result;
  io::MeshSettings settings = *job.mesh;  // with "D/N" resolved below
  {
    DecomposedGeometry g =
        build_decomposed_geometry(job, registry, options.planner, options.dim, options.threads);
    result.model = std::move(g.model);
    result.decomposition = std::move(g.decomposition);
    settings.size = g.size;
    settings.size_divisor.reset();
    result.size = g.size;
    check_groups(result.model, job.groups);
    result.stages.push_back({"geometry", g.geometry_seconds});
    if (!result.decomposition.volumes.empty())
      result.stages.push_back({"decompose", seconds_since(stage_start) - g.geometry_seconds});
  }
  if (options.after_geometry) options.after_geometry();
  MeshOptions opts = options;
  if (opts.threads == 0) opts.threads = settings.threads;
  // The exports are written (staged, not yet renamed) beside the mesher's
  // checks, and renamed below only when the run passes them.
  auto stage_exports = [&](io::ExportBatch& batch, const mesh::MeshDB& db) {
    for (const io::ExportSetting& e : job.exports) {
      io::ExportOptions export_options;
      export_options.binary = e.binary;
      export_options.groups = job.groups;
      export_options.skip_empty_groups = options.allow_partial;
      try {
        batch.stage(resolve_path(job.base_dir, e.file), db, result.model, export_options);
      } catch (const MeshingError& err) {
        throw MeshingError(err.code(), err.entity(), where_prefix(e.where) + err.message(),
                           err.hint());
      }
    }
  };
  auto early = std::make_unique<io::ExportBatch>();
  std::exception_ptr early_error;
  std::optional<double> early_seconds;
  if (!job.exports.empty()) {
    opts.beside_checks = [&](const mesh::MeshDB& db) {
      const auto t0 = Clock::now();
      // Called again after a retry at a finer size (finer_retry.h): what
      // the failed attempt staged is discarded.
      early = std::make_unique<io::ExportBatch>();
      early_error = nullptr;
      try {
        stage_exports(*early, db);
      } catch (...) {
        early_error = std::current_exception();
      }
      early_seconds = seconds_since(t0);
    };
  }
  // With two threads or more, the Exodus library loads beside the meshing
  // instead of in the export (~40 ms of dynamic linking). Only after the
  // geometry: its import forks a child, which must not inherit a thread in
  // the middle of dlopen.
  std::thread preload;
  if (limit_threads_count(opts.threads) > 1) {
    std::vector<std::string> paths;
    for (const io::ExportSetting& e : job.exports)
      paths.push_back(resolve_path(job.base_dir, e.file));
    if (!paths.empty()) {
      preload = std::thread([paths] {
        for (const std::string& p : paths) io::prepare_export(p);
      });
    }
  }
  struct Join {
    std::thread& t;
    ~Join() {
      if (t.joinable()) t.join();
    }
  } join_preload{preload};
  // The mesher's quality report evaluates the journal's checks too, taking
  // the scaled Jacobians the schemes computed (one evaluation per metric).
  opts.quality_checks = job.quality;
  try {
    result.mesh = mesh_model(result.model, settings, registry, opts);
  } catch (IncompleteMesh& e) {
    // The verdicts name volumes after the cuts: say which input volume each was.
    if (!result.decomposition.volumes.empty()) e.set_origin(result.decomposition.origin);
    throw;
  }
  result.stages.insert(result.stages.end(), result.mesh.stages.begin(), result.mesh.stages.end());
  result.quality = result.mesh.quality;
  const bool deviates =
      std::any_of(result.mesh.verdicts.begin(), result.mesh.verdicts.end(),
                  [](const Verdict& v) { return v.state == Verdict::State::Deviates; });
  if (result.quality.failed() || (deviates && !options.allow_partial)) {
    result.exports_skipped = !job.exports.empty();
    write_reports(job, options, result);
    return result;
  }
  stage_start = Clock::now();
  for (const io::ExportSetting& e : job.exports)
    report(options, "export " + clip_path(e.file), 0, 1);
  double staged_beside = 0;  // the time of the writes made beside the checks
  if (early_seconds && !result.mesh.mesh_replaced) {
    if (early_error) std::rethrow_exception(early_error);
    staged_beside = *early_seconds;
    result.written = early->commit();
  } else {
    early.reset();  // a partial mesh replaced the one staged
    io::ExportBatch batch;
    stage_exports(batch, result.mesh.mesh);
    result.written = batch.commit();
  }
  if (!job.exports.empty())
    result.stages.push_back({"exports", staged_beside + seconds_since(stage_start)});
  write_reports(job, options, result);
  return result;
}

}  // namespace cooperage::pipeline
