// Which scheme meshes each volume and surface, and why (the selector's output).
#pragma once

#include "framework/core/error.h"
#include "framework/intervals/solve.h"
#include "framework/scheme/applicability.h"

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace cooperage::pipeline {

struct PlanEntry {
  std::string scheme;  ///< registered scheme name
  std::string reason;  ///< "pinned in the journal", "role from volume 2 (map)", ...
  /// The planner's further notes for a person, one line each: every
  /// scheme's verdict, a volume scheme's structure (shown by reports).
  std::vector<std::string> details;
  /// What the chosen scheme's applicable() returned as its plan (or null):
  /// the pipeline hands it back to constrain(), roles() and mesh() through
  /// the views, so the scheme analyses the entity once per run. Shared and
  /// immutable: copies of the plan share it.
  std::shared_ptr<const scheme::PlanData> data;
  /// Surfaces: every volume it bounds takes any valid all-quad mesh of it
  /// with the agreed intervals (VolumeScheme::takes_existing_mesh), so the
  /// mesher may let a failing structured scheme fall back to pave
  /// (Settings::allow_quad_fallback).
  bool any_quad_mesh = false;
};

/// Why the planner found no scheme for an entity.
struct Refusal {
  ErrorCode code = ErrorCode::NotApplicable;
  std::string message;  ///< without the entity prefix
  std::string hint;     ///< what to do, or ""
};

struct SchemePlan {
  std::map<int, PlanEntry> volumes;   ///< volume id -> volume scheme
  std::map<int, PlanEntry> surfaces;  ///< surface id -> surface scheme
  /// Volumes no scheme can mesh (a planner may refuse volumes one by one
  /// instead of failing the whole plan; the pipeline reports each).
  std::map<int, Refusal> refused_volumes;
  /// Volume -> the volumes it waits for: they mesh a surface it shares and
  /// takes as it finds it (VolumeScheme::takes_existing_mesh). Acyclic.
  std::map<int, std::vector<int>> waits_for;
  /// Volumes whose sweep ends on a mesh a ring of neighbouring sweeps made
  /// from its own source (scheme::NeighbourMeshes::closing): a cut that
  /// needs one is the decomposition's last resort.
  std::set<int> ring_closers;
  /// The interval assignment the planner found feasible for this plan and
  /// its settings, when it solved one; the mesher uses it instead of solving
  /// the same problem again (on a 137-face part, 70 s each).
  std::optional<intervals::IntervalSolution> intervals;
};

}  // namespace cooperage::pipeline
