// The pave surface scheme: unstructured all-quad meshing of any face with
// any number of loops (docs/design.md; the seed brief "The schemes"; the 2D algorithm and its
// deviations from classic paving are described in pave_2d.h).
//
// * applicable(): every face with at least one boundary loop. A priori the
//   interval counts are unknown, so the parity cannot be checked there;
//   constrain() makes an odd count impossible and mesh() rejects one with
//   MeshingError(InvalidInput) naming the surface.
// * constrain(): the interval sum over all curves of all loops is even (a
//   curve used twice in a loop, e.g. a seam, counts twice), and every loop
//   has at least 4 intervals (6 for an outer loop around holes).
// * mesh(): the face goes to the plane (surface_to_2d.h), pave_2d meshes it,
//   interior nodes go back to the surface, and every quad is checked against
//   the natural normal; an inverted quad is never returned
//   (MeshingError(MeshingFailed) instead). Element sizes come from the
//   boundary spacing (graded between loops); Settings::size is not used.
#pragma once

#include "framework/scheme/scheme.h"
#include "schemes/pave/pave_2d.h"

#include <memory>

namespace cooperage::pave {

class PaveScheme : public scheme::SurfaceScheme {
 public:
  explicit PaveScheme(PaveOptions options = {}) : options_(std::move(options)) {}
  std::string_view name() const override { return "pave"; }
  scheme::Role serves() const override { return scheme::Role::QuadCap; }
  scheme::Applicability applicable(const scheme::SurfaceView& view) const override;
  void constrain(const scheme::SurfaceView& view,
                 intervals::IntervalProblem& problem) const override;
  scheme::EntityMesh mesh(const scheme::SurfaceView& view,
                          const scheme::Settings& params) const override;

 private:
  PaveOptions options_;
};

/// The pave scheme with default options.
std::unique_ptr<scheme::SurfaceScheme> make_pave();

}  // namespace cooperage::pave
