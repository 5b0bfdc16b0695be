// Surface parameters for the lattice fill, made continuous along a walk:
// on a surface closed in u or v (a full cylinder side) the parameter jumps
// by the period across the seam; uv_near() picks the copy nearest to the
// previous value, so a boundary loop gets continuous (unwrapped) parameters.
#pragma once

#include "framework/geometry/evaluators.h"

namespace cooperage::submap {

using geom::Vec2;
using geom::Vec3;

class UvChart {
 public:
  /// Detects periodicity by comparing the points at the ends of the face's
  /// parameter box.
  explicit UvChart(const geom::SurfaceGeometry& geometry);

  /// Parameters of the closest surface point to p.
  Vec2 uv(const Vec3& p) const { return geometry_.project(p).uv; }
  /// Parameters of p, shifted by whole periods to lie nearest to `near`.
  Vec2 uv_near(const Vec3& p, const Vec2& near) const { return shift_near(uv(p), near); }
  /// uv shifted by whole periods to lie nearest to `near`.
  Vec2 shift_near(Vec2 uv, const Vec2& near) const;
  /// Periods in u and v (0 when not periodic).
  const Vec2& period() const { return period_; }
  /// Model-space length per unit of u and v at the centre of the box.
  const Vec2& metric() const { return metric_; }
  const geom::SurfaceGeometry& geometry() const { return geometry_; }

 private:
  const geom::SurfaceGeometry& geometry_;
  Vec2 period_ = Vec2::Zero();
  Vec2 metric_ = Vec2::Ones();
};

}  // namespace cooperage::submap
