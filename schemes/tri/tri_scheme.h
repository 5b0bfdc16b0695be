// The surface scheme "tri": a quality triangulation of any face with any
// number of loops, planar or curved, on the given curve meshes (no new
// boundary nodes): constrained Delaunay triangulation with Delaunay
// refinement (framework/mesh2d) in the face's chart (the flattener shared
// by the 2D schemes, framework/mesh2d/surface_chart.h: a plane frame,
// scaled (u, v), or a conformal map), interior nodes mapped back onto the
// surface. For the
// wedge/hexahedral mix of Blacker 1996 (abstract: "or a wedge/hexahedral
// element mix if desired"): triangle caps swept into wedges.
#pragma once

#include <memory>

#include "framework/mesh2d/triangulate.h"
#include "framework/scheme/scheme.h"

namespace cooperage::tri {

class TriScheme final : public scheme::SurfaceScheme {
 public:
  explicit TriScheme(mesh2d::RefineOptions options = {}) : options_(options) {}
  std::string_view name() const override { return "tri"; }
  scheme::Role serves() const override { return scheme::Role::TriCap; }
  /// Any face with at least one loop (a closed face such as a full sphere
  /// has no boundary to triangulate). Low score: triangles, not quads.
  scheme::Applicability applicable(const scheme::SurfaceView& view) const override;
  /// At least 3 intervals around every loop.
  void constrain(const scheme::SurfaceView& view,
                 intervals::IntervalProblem& problem) const override;
  /// Triangles oriented with the natural normal; boundary nodes are exactly
  /// the curve nodes, interior nodes new. Sizes grade between the loops'
  /// spacings. Throws MeshingError(MeshingFailed, surface) when a curve is
  /// not meshed, the loops are invalid in the face's 2D space, or a
  /// triangle would come out inverted against the surface normal.
  scheme::EntityMesh mesh(const scheme::SurfaceView& view,
                          const scheme::Settings& params) const override;

 private:
  mesh2d::RefineOptions options_;
};

std::unique_ptr<scheme::SurfaceScheme> make_tri();

}  // namespace cooperage::tri
