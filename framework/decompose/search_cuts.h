// The bounded search for the cuts of one solid: evaluate every candidate cut
// (kernel split, pieces' a-priori verdicts, thickness), take the best cut
// whose pieces all plan together, else recurse on the best partial cuts.
#pragma once

#include "framework/decompose/cut_candidates.h"
#include "framework/decompose/decompose.h"
#include "framework/decompose/part_ids.h"

#include <functional>
#include <optional>

#include <tbb/task_arena.h>

namespace cooperage::decompose {

/// The cuts found for one solid and the solids they give.
struct SolidPlan {
  occ::SolidPieces pieces;
  std::vector<AppliedCut> cuts;
};

/// Searches the cuts of one solid (a SolidPieces of size 1).
class CutSearch {
 public:
  /// `part_ids`: the part's ids for what the search says of its pieces
  /// (cuts, refusals).
  CutSearch(const scheme::Registry& registry, const ModelCheck& check,
            const DecomposeOptions& options, const PartIds& part_ids)
      : registry_(registry),
        check_(check),
        options_(options),
        part_ids_(part_ids),
        arena_(options.threads > 0 ? options.threads : tbb::task_arena::automatic) {}

  /// The decomposition of `solid`, or nullopt (then failure() says why).
  /// A second pass, within what is left of the budget of cuts, adds the
  /// meridian planes (meridian_candidates) and takes plans with rings of
  /// sweeps: where the first pass finds cuts, their pieces sweep better.
  std::optional<SolidPlan> solve(const occ::SolidPieces& solid) {
    last_resort_ = false;
    if (auto plan = solve(solid, 0, {}, nullptr)) return plan;
    last_resort_ = true;
    if (auto plan = solve_turned(solid)) return plan;
    return solve(solid, 0, {}, nullptr);
  }

  int tried() const { return tried_; }
  /// Why the search failed, for a person.
  std::string failure() const;

  /// The solids a piece's own cuts must plan among: given the pieces of the
  /// solid being cut, all solids settled so far (the other pieces of the
  /// cuts above it, those still without a scheme left out). Null: the
  /// pieces alone (the volume itself).
  using Context = std::function<occ::SolidPieces(const occ::SolidPieces&)>;

 private:
  /// `inherited`: the candidates of the solids this one was cut from (the
  /// part's own faces extended, which a piece no longer has as faces).
  std::optional<SolidPlan> solve(const occ::SolidPieces& solid, int depth,
                                 const std::vector<CutCandidate>& inherited,
                                 const Context& context);
  /// A turned part solid at its axis (core_candidates): the core cylinder,
  /// then a meridian cut of the tube around it, when all three pieces have
  /// a scheme and plan together.
  std::optional<SolidPlan> solve_turned(const occ::SolidPieces& solid);
  /// "" when `pieces` plan among the solids of `context`, else the reason
  /// (in the part's ids).
  std::string check_in(const occ::SolidPieces& pieces, const geom::Model* alone,
                       const Context& context);

  const scheme::Registry& registry_;
  const ModelCheck& check_;
  DecomposeOptions options_;
  const PartIds& part_ids_;
  tbb::task_arena arena_;  ///< the cuts of one level are made in parallel
  int tried_ = 0;
  bool last_resort_ = false;  ///< the second pass: meridian cuts, rings of sweeps
  int crossing_ = 0;          ///< candidates crossing the volume by a layer on each side
  int candidates_ = 0;        ///< candidates of the volume itself (depth 0)
  double thickest_ = 0.0;     ///< thinnest side of the volume across its thickest candidate
  std::string face_kinds_;  ///< "28 bspline": its faces' geometry, for a refusal without candidates
  std::string best_partial_;  ///< what the best cut at depth 0 left unmeshable
  std::string conflict_;      ///< why the first complete cut did not plan
  int conflicts_ = 0;         ///< sets of sweepable pieces that did not plan
};

}  // namespace cooperage::decompose
