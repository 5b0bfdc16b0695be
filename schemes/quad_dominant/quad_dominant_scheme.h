// The surface scheme "quad_dominant": quads where quads are good, triangles
// where they are not, for cooper's mixed caps (journal elements="mixed").
// It meshes the face with an all-quad scheme (the registration code passes
// pave; schemes never include each other) and splits every quad whose
// scaled Jacobian is below the threshold into two triangles
// (framework/mesh/split_poor_quads.h); halves of two poor quads that make a
// good quad are merged back, and the triangles' free nodes then move to
// lift them (framework/mesh/improve_split_nodes.h), never taking a quad
// below the threshold. Triangles sit where pave had to put a poor quad,
// e.g. at a sharp corner; no boundary node or edge changes.
#pragma once

#include "framework/scheme/scheme.h"

#include <memory>

namespace cooperage::quad_dominant {

class QuadDominantScheme final : public scheme::SurfaceScheme {
 public:
  /// \param[in] quads        the all-quad scheme whose poor quads are split
  /// \param[in] min_quality  the smallest scaled Jacobian of a kept quad
  QuadDominantScheme(std::unique_ptr<scheme::SurfaceScheme> quads, double min_quality)
      : quads_(std::move(quads)), min_quality_(min_quality) {}
  std::string_view name() const override { return "quad_dominant"; }
  scheme::Role serves() const override { return scheme::Role::MixedCap; }
  /// Where the quad scheme applies, at a low score (0.1): chosen only when
  /// pinned or imposed by a mixed sweep, never by the selector over quads.
  scheme::Applicability applicable(const scheme::SurfaceView& view) const override;
  /// The quad scheme's constraints (pave: an even interval sum).
  void constrain(const scheme::SurfaceView& view,
                 intervals::IntervalProblem& problem) const override;
  /// The quad scheme's mesh with the quads below min_quality split and the
  /// triangles' free (interior) nodes moved on the surface; curve and
  /// vertex nodes unchanged. Throws what the quad scheme throws.
  scheme::EntityMesh mesh(const scheme::SurfaceView& view,
                          const scheme::Settings& params) const override;

 private:
  std::unique_ptr<scheme::SurfaceScheme> quads_;
  double min_quality_;
};

}  // namespace cooperage::quad_dominant
