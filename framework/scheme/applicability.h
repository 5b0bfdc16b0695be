// The answer of a scheme's a-priori test: can it mesh this entity, how well
// (score, higher is better), why, in a sentence for a person, and the plan
// the scheme computed to decide (docs/design.md, "Plans and settings").
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>

namespace cooperage::scheme {

/// A scheme's own a-priori analysis of one entity (cooper's barrel tree,
/// submap's vertex types), made by its applicable() for one model, entity
/// and Settings. The selector keeps it with its choice (the pipeline's
/// SchemePlan) and hands it back through the views (SurfaceView::plan,
/// VolumeView::plan) to constrain(), roles(), takes_existing_mesh() and
/// mesh(), so a scheme analyses an entity once per run and keeps nothing
/// itself. Immutable once returned: volumes are meshed in parallel, and
/// every call of a run reads the same object. A scheme derives its own
/// type from it and finds it again with carried_plan<T>() (scheme.h).
class PlanData {
 public:
  virtual ~PlanData() = default;
  /// The direction (x, y, z) of the straight sweep this plan makes, if it
  /// is one: the pipeline tries a volume that failed sweeping one way the
  /// other way (pipeline/finer_retry.h) without knowing the scheme.
  virtual std::optional<std::array<double, 3>> straight_sweep() const { return std::nullopt; }
};

struct Applicability {
  bool ok = false;
  double score = 0.0;  ///< in [0, 1]; compares schemes on one entity
  std::string why;     ///< "surface 12: 6 END vertices, map needs 4"
  /// The scheme's plan (ok or not), or null when it keeps none.
  std::shared_ptr<const PlanData> plan;

  static Applicability yes(double score, std::string why = {},
                           std::shared_ptr<const PlanData> plan = nullptr) {
    return {true, score, std::move(why), std::move(plan)};
  }
  static Applicability no(std::string why, std::shared_ptr<const PlanData> plan = nullptr) {
    return {false, 0.0, std::move(why), std::move(plan)};
  }
};

}  // namespace cooperage::scheme
