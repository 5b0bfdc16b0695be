// The meshing pipeline (docs/design.md; the seed brief "Data flow"): plan schemes -> assign
// intervals -> mesh curves -> surfaces -> volumes -> quality -> exports.
// Every stage is a function of the previous stage's value.
#pragma once

#include "framework/core/error.h"
#include "framework/geometry/model.h"
#include "framework/intervals/solve.h"
#include "framework/io/job.h"
#include "framework/mesh/mesh_db.h"
#include "framework/pipeline/measure_check.h"
#include "framework/pipeline/decomposed_geometry.h"
#include "framework/pipeline/planner.h"
#include "framework/pipeline/quality_report.h"
#include "framework/pipeline/scheme_plan.h"
#include "framework/scheme/registry.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace cooperage::pipeline {

// The planning stage (Planner, planner.h): a scheme for every volume (dim 3)
// and surface. The selector provides it (selector::planner(),
// selector/select_schemes.h); the pipeline does not depend on the selector,
// so it is passed in.

struct MeshOptions {
  Planner planner;  ///< required: selector::planner()
  int dim = 3;      ///< 3: volumes (and their surfaces); 2: surfaces only
  int threads = 0;  ///< 0: all cores (capped at the hardware's); the result does not depend on it
  /// Refuse before meshing when the estimated element count exceeds this
  /// (mesh_size.h); unset: MeshSettings::max_elements, else 200 M.
  std::optional<double> max_elements;
  /// Largest relative deviation of a volume's meshed volume (a surface's
  /// area) from the CAD's before the run fails (measure_check.h); unset:
  /// MeshSettings::volume_tolerance, else 0.01. Above 0.01 it is a warning.
  std::optional<double> volume_tolerance;
  /// Keep what meshed when some volumes (surfaces, in 2D) cannot be meshed
  /// or fail the volume check, instead of throwing; see MeshResult::verdicts.
  bool allow_partial = false;
  /// Checks the quality report evaluates along with every block's scaled
  /// Jacobian (a journal's <quality>; their metrics too), so that no
  /// metric is computed twice: MeshResult::quality carries their outcomes.
  std::vector<io::QualityCheck> quality_checks;
  /// Called as work advances: stage name, items done, items in the stage.
  std::function<void(const std::string& stage, std::size_t done, std::size_t total)> progress;
  /// Optional: called once with the finished mesh, as a task beside the
  /// quality report and the volume check (after them on one thread), when
  /// no entity was refused before them; mesh_model waits for it before it
  /// returns or throws. It must only read the mesh, and must not throw. The
  /// mesh returned is the one it saw unless MeshResult::mesh_replaced.
  std::function<void(const mesh::MeshDB&)> beside_checks;
  /// Optional: called by run_job once the geometry (and its decomposition)
  /// is built, before the meshing starts its threads (the command tunes its
  /// heap there: app/huge_pages.cpp).
  std::function<void()> after_geometry;
};

/// Wall-clock time of one stage of a run.
struct StageTime {
  std::string stage;  ///< "geometry", "plan", "intervals", "curves", ...
  double seconds = 0.0;
};

struct EntityTiming {
  int dim = 3;
  int id = 0;
  std::string scheme;
  double seconds = 0.0;
};

/// Something a run gave up or found suspicious without failing (a scheme's
/// fallback, a volume deviating from the CAD's), about one entity.
struct Warning {
  EntityRef entity;
  std::string message;  ///< one sentence, no entity prefix
  /// "surface 12: pave fell back to quad-dominant ..."
  std::string text() const;
};

/// What became of one volume (3D) or surface (surface meshes).
struct Verdict {
  enum class State {
    Meshed,    ///< meshed and within the volume tolerance
    Refused,   ///< no scheme, a scheme failed, or inverted elements
    Deviates,  ///< meshed, but its volume (area) is off the CAD's beyond the tolerance
  };
  EntityRef entity;
  State state = State::Meshed;
  ErrorCode code = ErrorCode::NotApplicable;  ///< Refused: why, as an error code
  std::string reason;  ///< Refused / Deviates: one sentence, no entity prefix
  std::string hint;    ///< Refused: what to do, or ""
  /// Refused after its scheme accepted it (the scheme failed, or left
  /// inverted elements): a smaller size on it may mesh it (finer_retry.h).
  bool finer_may_help = false;
};

struct MeshResult {
  SchemePlan plan;
  intervals::IntervalSolution intervals;
  /// The mesh; with allow_partial, only the entities whose verdict is Meshed.
  mesh::MeshDB mesh;
  std::vector<EntityTiming> timings;   ///< surfaces then volumes, by id
  QualityReport quality;               ///< scaled Jacobian per block (no journal checks)
  std::vector<Warning> warnings;       ///< in stage order, then by entity id
  std::vector<StageTime> stages;       ///< plan, intervals, curves, surfaces, volumes, quality
  std::vector<Verdict> verdicts;       ///< every volume (3D) or surface (2D), by id
  std::vector<MeasureCheck> measures;  ///< meshed volume / area against the CAD's
  double volume_tolerance = 0.01;      ///< the tolerance the verdicts used
  /// allow_partial kept only some entities: `mesh` is not the mesh
  /// MeshOptions::beside_checks saw.
  bool mesh_replaced = false;

  /// True when some verdict is not Meshed (a partial or failed result).
  bool incomplete() const;
};

/// Thrown by mesh_model when some volumes of a model with several cannot be
/// meshed and allow_partial is off: the first refusal's entity, code and
/// reason, and every verdict, so a report can list them all.
class IncompleteMesh : public MeshingError {
 public:
  IncompleteMesh(const Verdict& first, std::vector<Verdict> verdicts, const std::string& hint);
  const std::vector<Verdict>& verdicts() const { return verdicts_; }
  /// Volume ids of the model before the automatic decomposition: entry
  /// k - 1 is the input volume that volume k is (part of); empty when
  /// nothing was cut (run_job fills it).
  const std::vector<int>& origin() const { return origin_; }
  void set_origin(std::vector<int> origin) { origin_ = std::move(origin); }

 private:
  std::vector<Verdict> verdicts_;
  std::vector<int> origin_;
};

/// The worker threads a run uses for MeshOptions::threads: the request, at
/// most the hardware's; 0 means every core.
int limit_threads_count(int requested);

/// Meshes a model. Every model is validated first (geom::validate) and its
/// size estimated against the element limit. Inverted elements are never
/// returned. A failure of a single-volume (single-surface) model throws
/// MeshingError naming the entity; in an assembly every volume gets a
/// verdict, and unless allow_partial, any refusal throws IncompleteMesh.
/// A volume deviating beyond the tolerance does not throw: its verdict is
/// Deviates (the caller fails the run, or drops it with allow_partial).
MeshResult mesh_model(const geom::Model& model, const io::MeshSettings& settings,
                      const scheme::Registry& registry, const MeshOptions& options = {});

struct RunResult {
  geom::Model model;                ///< after the automatic decomposition, if any
  decompose::Report decomposition;  ///< the cuts made (empty when none were needed)
  MeshResult mesh;
  QualityReport quality;
  std::vector<std::string> written;  ///< export files written
  bool exports_skipped = false;      ///< a failing check stopped them
  std::vector<StageTime> stages;     ///< geometry, the mesher's stages, checks, exports
  std::optional<double> size;        ///< the global size used, "D/N" resolved

  /// A quality check or the volume check failed, or (allow_partial) some
  /// volumes were left out: the command exits 1.
  bool failed() const;
};

/// A whole journal: geometry, meshing, quality checks, exports, then the HTML
/// reports of job.reports (framework/report/html_report.h; written also when
/// a check failed, to show why). Every export target is checked before the
/// geometry is built (an error names its <export> line); exports are written
/// only when no check fails (with allow_partial: for the volumes that
/// meshed), all of them or none (io::ExportBatch).
RunResult run_job(const io::Job& job, const scheme::Registry& registry,
                  const MeshOptions& options = {});

}  // namespace cooperage::pipeline
