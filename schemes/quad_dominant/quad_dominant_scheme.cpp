#include "schemes/quad_dominant/quad_dominant_scheme.h"

#include "framework/geometry/evaluators.h"
#include "framework/mesh/improve_split_nodes.h"

#include <cstdio>
#include <string>

namespace cooperage::quad_dominant {

scheme::Applicability QuadDominantScheme::applicable(const scheme::SurfaceView& view) const {
  scheme::Applicability a = quads_->applicable(view);
  if (!a.ok) return a;
  char threshold[32];
  std::snprintf(threshold, sizeof threshold, "%g", min_quality_);
  return scheme::Applicability::yes(
      0.1, a.why + "; quad_dominant splits its quads of scaled Jacobian below " + threshold +
               " into triangles");
}

void QuadDominantScheme::constrain(const scheme::SurfaceView& view,
                                   intervals::IntervalProblem& problem) const {
  quads_->constrain(view, problem);
}

scheme::EntityMesh QuadDominantScheme::mesh(const scheme::SurfaceView& view,
                                            const scheme::Settings& params) const {
  scheme::EntityMesh out = quads_->mesh(view, params);
  // Nodes the scheme made (global -1) may move on the surface; curve and
  // vertex nodes stay.
  std::vector<bool> movable(out.coords.size());
  for (size_t i = 0; i < movable.size(); ++i) movable[i] = out.global[i] < 0;
  const geom::SurfaceGeometry* surface = view.surface().geometry.get();
  mesh::QuadDominant split = mesh::make_quad_dominant(
      out.coords, out.quads, movable,
      [&](const geom::Vec3& x) { return surface ? surface->project(x).point : x; }, min_quality_);
  out.quads = std::move(split.quads);
  out.tris.insert(out.tris.end(), split.tris.begin(), split.tris.end());
  return out;
}

}  // namespace cooperage::quad_dominant
