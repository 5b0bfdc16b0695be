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

#include "framework/io/job.h"
#include "framework/scheme/scheme.h"
#include "schemes/submap/classify.h"
#include "schemes/submap/smooth.h"

namespace cooperage::submap {

struct SubmapOptions {
  ClassifyOptions classify;
  SmoothOptions smooth;
};

class SurfaceSubmap final : public scheme::SurfaceScheme {
 public:
  explicit SurfaceSubmap(std::vector<io::VertexTypeSetting> pins = {}, SubmapOptions options = {})
      : pins_(std::move(pins)), options_(options) {}

  std::string_view name() const override { return "submap"; }
  /// Structured: cooper's sides, and caps of any sweep.
  scheme::Role serves() const override {
    return scheme::Role::SweepSide | scheme::Role::QuadCap | scheme::Role::MixedCap;
  }
  /// From angles and topology alone (plan_submap()); says why a face is rejected.
  scheme::Applicability applicable(const scheme::SurfaceView& view) const override;
  /// Per loop and axis: + sums = - sums; per hole: it fits inside the outer loop.
  void constrain(const scheme::SurfaceView& view,
                 intervals::IntervalProblem& problem) const override;
  /// Lattice fill + guarded smoothing. Throws MeshingError(MeshingFailed)
  /// when a curve is not meshed, a loop's intervals do not balance, or the
  /// lattice region is invalid (overlapping, a hole that does not fit).
  scheme::EntityMesh mesh(const scheme::SurfaceView& view,
                          const scheme::MeshParams& params) const override;

  /// Hard vertex types from the journal (those of other surfaces are ignored).
  void set_pins(std::vector<io::VertexTypeSetting> pins) { pins_ = std::move(pins); }
  const std::vector<io::VertexTypeSetting>& pins() const { return pins_; }

 private:
  std::vector<io::VertexTypeSetting> pins_;
  SubmapOptions options_;
};

/// The scheme, with the journal's vertex type pins.
std::unique_ptr<scheme::SurfaceScheme> make_submap(std::vector<io::VertexTypeSetting> pins = {});

}  // namespace cooperage::submap
