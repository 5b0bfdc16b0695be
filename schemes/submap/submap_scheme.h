// The surface scheme "submap" (ALGORITHMS.md sec. 1; White et al. 1995,
// Whiteley et al. 1996): faces whose boundary vertices classify as END /
// SIDE / CORNER with valid loop sums (L, T, U, comb shapes, rectilinear
// holes, their curved counterparts; REVERSAL vertices are classified but
// rejected, as the lattice fill cannot mesh the slit they make) are meshed
// by a lattice fill: every boundary node gets integer (i, j), interior lattice points are
// blended from their rows and columns, projected onto the surface, one quad
// per unit cell, then guarded smoothing.
#pragma once

#include <memory>
#include <vector>

#include "framework/scheme/scheme.h"
#include "schemes/submap/classify.h"
#include "schemes/submap/smooth.h"
#include "schemes/submap/submap_plan.h"

namespace cooperage::submap {

struct SubmapOptions {
  ClassifyOptions classify;
  SmoothOptions smooth;
};

/// The plan applicable() returns and constrain() and mesh() take back
/// (scheme::PlanData): the vertex types and curve directions of one surface,
/// with the journal's pins (Settings::vertex_types) applied.
struct SubmapPlanData final : scheme::PlanData {
  int surface_id = 0;
  SubmapPlan plan;
};

class SurfaceSubmap final : public scheme::SurfaceScheme {
 public:
  explicit SurfaceSubmap(SubmapOptions options = {}) : options_(options) {}

  std::string_view name() const override { return "submap"; }
  /// Structured: cooper's sides, and caps of any sweep.
  scheme::Role serves() const override {
    return scheme::Role::SweepSide | scheme::Role::QuadCap | scheme::Role::MixedCap;
  }
  /// From angles and topology alone (plan_submap(), with the vertex types
  /// of view.settings()); says why a face is rejected. Returns the plan.
  scheme::Applicability applicable(const scheme::SurfaceView& view) const override;
  /// Per loop and axis: + sums = - sums; per hole: it fits inside the outer loop.
  void constrain(const scheme::SurfaceView& view,
                 intervals::IntervalProblem& problem) const override;
  /// Lattice fill + guarded smoothing. Throws MeshingError(MeshingFailed)
  /// when a curve is not meshed, a loop's intervals do not balance, or the
  /// lattice region is invalid (overlapping, a hole that does not fit).
  scheme::EntityMesh mesh(const scheme::SurfaceView& view,
                          const scheme::Settings& params) const override;

  /// The plan view.plan carries (this scheme's applicable() for the same
  /// surface), else one computed now.
  std::shared_ptr<const SubmapPlanData> plan(const scheme::SurfaceView& view) const;

 private:
  SubmapOptions options_;
};

/// The scheme (the journal's vertex types reach it through scheme::Settings).
std::unique_ptr<scheme::SurfaceScheme> make_submap(SubmapOptions options = {});

}  // namespace cooperage::submap
