// Projections of a run of nearby points onto one surface: the elements of a
// surface mesh visited in order, each close to the one before. Each
// projection starts a local search (project_near) from the previous answer,
// a fraction of an element away, instead of the global search a point
// without history needs (on a B-spline face the global search is most of
// the cost of a quality or measure check, issue 20). A local answer farther
// than `reach` from its point (the walk jumped across the face, or the
// search found another sheet) is dropped for the global one.
//
// The answers depend on the order of the queries, so a walk belongs to one
// sequential loop over a fixed order (one per chunk of a parallel loop
// whose chunks do not depend on the thread count).
#pragma once

#include "framework/geometry/evaluators.h"

#include <optional>

namespace cooperage::geom {

class ProjectionWalk {
 public:
  explicit ProjectionWalk(const SurfaceGeometry& surface) : surface_(surface) {}

  /// Closest point of the surface to p, trusted from the previous answer's
  /// parameters when it lies within `reach` of p.
  SurfaceProjection project(const Vec3& p, double reach) {
    SurfaceProjection out;
    bool done = false;
    if (last_uv_) {
      out = surface_.project_near(p, *last_uv_);
      done = out.distance <= reach;
    }
    if (!done) out = surface_.project(p);
    if (out.uv.allFinite()) last_uv_ = out.uv;
    return out;
  }

 private:
  const SurfaceGeometry& surface_;
  std::optional<Vec2> last_uv_;
};

}  // namespace cooperage::geom
