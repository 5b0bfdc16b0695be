// The meshing pipeline (DESIGN.md "Data flow"): plan schemes -> assign
// intervals -> mesh curves -> surfaces -> volumes -> quality -> exports.
// Every stage is a function of the previous stage's value.
#pragma once

#include "framework/core/error.h"
#include "framework/geometry/model.h"
#include "framework/intervals/solve.h"
#include "framework/io/job.h"
#include "framework/mesh/mesh_db.h"
#include "framework/pipeline/decomposed_geometry.h"
#include "framework/pipeline/planner.h"
#include "framework/pipeline/quality_report.h"
#include "framework/pipeline/scheme_plan.h"
#include "framework/scheme/registry.h"

#include <functional>
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
  int threads = 0;  ///< 0: all cores; the result does not depend on it
  /// Called as work advances: stage name, items done, items in the stage.
  std::function<void(const std::string& stage, std::size_t done, std::size_t total)> progress;
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

struct MeshResult {
  SchemePlan plan;
  intervals::IntervalSolution intervals;
  mesh::MeshDB mesh;
  std::vector<EntityTiming> timings;  ///< surfaces then volumes, by id
  QualityReport quality;              ///< scaled Jacobian per block (no journal checks)
  std::vector<Warning> warnings;      ///< in stage order, then by entity id
  std::vector<StageTime> stages;      ///< plan, intervals, curves, surfaces, volumes, quality
};

/// Meshes a model. Throws MeshingError naming the entity on any failure,
/// including inverted volume elements (never returned silently).
MeshResult mesh_model(const geom::Model& model, const io::MeshSettings& settings,
                      const scheme::Registry& registry, const MeshOptions& options = {});

struct RunResult {
  geom::Model model;               ///< after the automatic decomposition, if any
  decompose::Report decomposition; ///< the cuts made (empty when none were needed)
  MeshResult mesh;
  QualityReport quality;
  std::vector<std::string> written;  ///< export files written
  bool exports_skipped = false;      ///< a failing quality check stopped them
  std::vector<StageTime> stages;     ///< geometry, the mesher's stages, checks, exports
};

/// A whole journal: geometry, meshing, quality checks, exports (written only
/// when no check with action="fail" fails; each file is written atomically),
/// then the HTML reports of job.reports (written also when a check failed,
/// to show why; framework/report/html_report.h).
RunResult run_job(const io::Job& job, const scheme::Registry& registry,
                  const MeshOptions& options = {});

}  // namespace cooperage::pipeline
