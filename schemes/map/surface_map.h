// The surface map scheme "map": a logical rectangle (4 END corners, SIDE
// junctions elsewhere, one loop) meshed by transfinite interpolation in 3D
// with projection onto the surface (ALGORITHMS.md sec. 1).
#pragma once

#include "framework/scheme/scheme.h"

#include <memory>

namespace cooperage::map {

class SurfaceMap final : public scheme::SurfaceScheme {
 public:
  std::string_view name() const override { return "map"; }
  /// One grid: the volume map's faces, and caps of any sweep.
  scheme::Role serves() const override {
    return scheme::Role::MappedFace | scheme::Role::QuadCap | scheme::Role::MixedCap;
  }
  /// One loop, 4 END and otherwise SIDE junctions; see analyse_map_surface().
  scheme::Applicability applicable(const scheme::SurfaceView& view) const override;
  /// Opposite logical sides get equal interval sums.
  void constrain(const scheme::SurfaceView& view,
                 intervals::IntervalProblem& problem) const override;
  /// An (n+1) x (m+1) lattice: boundary nodes are the curve nodes, interior
  /// nodes by TFI projected onto the surface; quads follow the natural normal.
  /// Throws MeshingError(MeshingFailed) when opposite sides differ in count,
  /// a curve is not meshed, or the surface is not mappable.
  scheme::EntityMesh mesh(const scheme::SurfaceView& view,
                          const scheme::Settings& params) const override;
};

std::unique_ptr<scheme::SurfaceScheme> make_surface_map();

}  // namespace cooperage::map
