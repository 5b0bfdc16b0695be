// The selector: picks a scheme for every volume and surface a priori, from
// the schemes' applicable() verdicts and scores only (never by trial
// meshing), honours the journal's pins, and relaxes automatic surface choices
// when they make the interval assignment infeasible.
#pragma once

#include "framework/geometry/model.h"
#include "framework/io/job.h"
#include "framework/pipeline/mesher.h"
#include "framework/scheme/registry.h"
#include "selector/selection.h"

namespace cooperage::selector {

struct SelectOptions {
  int dim = 3;               ///< 3: volumes and surfaces; 2: surfaces only
  int max_relaxations = 64;  ///< bound on map -> submap -> pave steps
  bool check_intervals = true;
  /// A volume no scheme fits is recorded in Selection::refused (and left
  /// out of the plan) instead of failing the whole selection, so an
  /// assembly can report every volume (issue 16 item 5).
  bool refuse_per_volume = false;
  /// After a feasible solve: a graded curve (a thin face's, a small
  /// feature's) that map/submap constraints hold at half its goal or less
  /// has the automatic map/submap choices on it paved, when that frees it
  /// without starving another graded curve more (issue 16, item 1).
  bool pave_starved_curves = true;
};

/// Volumes first, in id order: the applicable scheme with the best score
/// (ties: registry order, i.e. volume map, then cooper), whose surface roles
/// agree with the volumes already chosen and with surface pins. Then every
/// surface without a role: its pin, or the best-scoring applicable surface
/// scheme. Finally the interval problem is solved; when it is infeasible the
/// automatic surface choice with the lowest score among the surfaces whose
/// curves are in conflict moves to its next candidate, and the problem is
/// solved again (bounded, deterministic). Then a curve held far below the
/// small intervals its sizing asks (SelectOptions::pave_starved_curves) has
/// the map/submap surfaces that hold it paved; both kinds of change are
/// listed in Selection::relaxations.
/// Throws MeshingError: InvalidInput for a pin naming no registered scheme
/// (pipeline::check_scheme_names); NotApplicable naming the entity and every scheme's
/// reason; InvalidInput for contradictory pins (naming both); Infeasible
/// when no automatic choice can be relaxed.
Selection select_schemes(const geom::Model& model, const scheme::Registry& registry,
                         const io::MeshSettings& settings, const SelectOptions& options = {});

/// The selector as the pipeline's planner (MeshOptions::planner), refusing
/// volumes one by one (SchemePlan::refused_volumes).
pipeline::Planner planner();

/// MeshOptions with the selector as planner.
pipeline::MeshOptions mesh_options(int dim = 3, int threads = 0);

}  // namespace cooperage::selector
