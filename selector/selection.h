// The selector's answer (the paper's "tool manager"): for every volume and
// surface, every scheme's a-priori verdict, the choice and the reason.
#pragma once

#include "framework/pipeline/scheme_plan.h"
#include "framework/scheme/applicability.h"

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace cooperage::selector {

struct Candidate {
  std::string scheme;
  scheme::Applicability applicability;
};

/// A scheme's verdict in one line, as `cooperage plan` prints it:
/// "+ map score 1.00: <why>" or "- map: <why>".
std::string describe(const Candidate& candidate);

struct Choice {
  int dim = 3;  ///< 3: volume, 2: surface
  int id = 0;
  /// Every registered scheme of the entity's dimension, in registry order
  /// (empty for surfaces a volume scheme meshes itself).
  std::vector<Candidate> candidates;
  std::string scheme;  ///< the choice (scheme::kMeshedByVolume: meshed by its volume)
  std::string reason;  ///< "best score 1.00", "pinned at job.xml:7", "role from volume 2 (map)"
  bool pinned = false;
  bool fixed_by_volume = false;
  /// Surfaces: every volume it bounds takes any all-quad mesh of it
  /// (PlanEntry::any_quad_mesh).
  bool any_quad_mesh = false;
};

struct Selection {
  std::vector<Choice> volumes;   ///< ascending id
  std::vector<Choice> surfaces;  ///< ascending id
  /// Choices changed because the interval assignment was infeasible, in order.
  std::vector<std::string> relaxations;
  /// With SelectOptions::refuse_per_volume: volumes without a scheme, and why.
  std::map<int, pipeline::Refusal> refused;
  /// Volume -> the volumes meshed before it, whose mesh of a shared surface
  /// it takes (SchemePlan::waits_for).
  std::map<int, std::vector<int>> waits_for;
  /// Volumes closing a ring of sweeps (SchemePlan::ring_closers).
  std::set<int> ring_closers;
  /// The feasible interval assignment found for the final choices (with
  /// SelectOptions::check_intervals), carried into SchemePlan::intervals.
  std::optional<intervals::IntervalSolution> intervals;

  /// The plan the pipeline runs; each entry's details are its candidates'
  /// verdicts (describe()).
  pipeline::SchemePlan plan() const;
};

}  // namespace cooperage::selector
