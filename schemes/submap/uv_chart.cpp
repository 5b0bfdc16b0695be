#include "schemes/submap/uv_chart.h"

#include <algorithm>
#include <cmath>

namespace cooperage::submap {

UvChart::UvChart(const geom::SurfaceGeometry& geometry) : geometry_(geometry) {
  const auto [ub, vb] = geometry.uv_bounds();
  const double u0 = ub.x(), u1 = ub.y(), v0 = vb.x(), v1 = vb.y();
  const Vec2 centre(0.5 * (u0 + u1), 0.5 * (v0 + v1));
  const Vec3 pc = geometry.point(centre);
  double scale = 0.0;
  for (double a : {0.0, 0.5, 1.0}) {
    for (double b : {0.0, 0.5, 1.0}) {
      scale = std::max(scale,
                       (geometry.point(Vec2(u0 + a * (u1 - u0), v0 + b * (v1 - v0))) - pc).norm());
    }
  }
  const double tol = 1e-7 * std::max(scale, 1e-12);
  bool closed_u = u1 > u0, closed_v = v1 > v0;
  for (double a : {0.1, 0.5, 0.9}) {
    const double v = v0 + a * (v1 - v0), u = u0 + a * (u1 - u0);
    if ((geometry.point(Vec2(u0, v)) - geometry.point(Vec2(u1, v))).norm() > tol) closed_u = false;
    if ((geometry.point(Vec2(u, v0)) - geometry.point(Vec2(u, v1))).norm() > tol) closed_v = false;
  }
  if (closed_u) period_.x() = u1 - u0;
  if (closed_v) period_.y() = v1 - v0;
  const double hu = 1e-4 * std::max(u1 - u0, 1e-12), hv = 1e-4 * std::max(v1 - v0, 1e-12);
  const double mu = (geometry.point(centre + Vec2(hu, 0)) - pc).norm() / hu;
  const double mv = (geometry.point(centre + Vec2(0, hv)) - pc).norm() / hv;
  metric_ = Vec2(mu > 0 ? mu : 1.0, mv > 0 ? mv : 1.0);
}

Vec2 UvChart::shift_near(Vec2 uv, const Vec2& near) const {
  for (int k = 0; k < 2; ++k) {
    const double p = period_[k];
    if (p > 0) uv[k] += p * std::round((near[k] - uv[k]) / p);
  }
  return uv;
}

}  // namespace cooperage::submap
