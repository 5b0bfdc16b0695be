#include "schemes/pave/surface_to_2d.h"

#include <Eigen/Geometry>

#include <cmath>

namespace cooperage::pave {
namespace {

/// True when the surface closes on itself across its parameter box in
/// direction dir (0: u, 1: v).
/// The parameter box as corners (uv_bounds() gives (umin, umax), (vmin, vmax)).
std::pair<geom::Vec2, geom::Vec2> box_of(const geom::SurfaceGeometry& s) {
  const auto [u, v] = s.uv_bounds();
  return {geom::Vec2(u.x(), v.x()), geom::Vec2(u.y(), v.y())};
}

bool periodic(const geom::SurfaceGeometry& s, int dir) {
  const auto [lo, hi] = box_of(s);
  const double span = hi[dir] - lo[dir];
  if (!(span > 0)) return false;
  const int other = 1 - dir;
  double scale = 0.0, gap = 0.0;
  for (int k = 0; k < 3; ++k) {
    geom::Vec2 a = lo, b = lo;
    a[other] = b[other] = lo[other] + (hi[other] - lo[other]) * (0.2 + 0.3 * k);
    b[dir] = hi[dir];
    geom::Vec2 m = a;
    m[dir] = 0.5 * (lo[dir] + hi[dir]);
    const geom::Vec3 pa = s.point(a), pb = s.point(b);
    gap = std::max(gap, (pa - pb).norm());
    scale = std::max(scale, (pa - s.point(m)).norm());
  }
  return gap <= 1e-7 * std::max(scale, 1e-300);
}

}  // namespace

SurfaceTo2D::SurfaceTo2D(const geom::SurfaceGeometry& surface,
                         const std::vector<std::vector<geom::Vec3>>& loops)
    : surface_(surface) {
  planar_ = surface.type() == geom::SurfaceType::Plane;
  if (planar_) {
    origin_ = loops[0][0];
    const geom::Vec3 n = surface.project(origin_).normal.normalized();
    geom::Vec3 e = loops[0][1] - origin_;
    e -= e.dot(n) * n;
    ex_ = e.normalized();
    ey_ = n.cross(ex_);
    normal_ = n;
    for (const auto& loop : loops) {
      std::vector<Eigen::Vector2d> l;
      for (const auto& p : loop) l.emplace_back((p - origin_).dot(ex_), (p - origin_).dot(ey_));
      loops_2d_.push_back(std::move(l));
    }
    mirror_if_clockwise();
    return;
  }
  const auto [lo, hi] = box_of(surface);
  const geom::Vec2 period = hi - lo;
  const bool wrap[2] = {periodic(surface, 0), periodic(surface, 1)};
  std::vector<std::vector<geom::Vec2>> uv;
  for (const auto& loop : loops) {
    std::vector<geom::Vec2> l;
    for (const auto& p : loop) {
      geom::Vec2 x = surface.project(p).uv;
      if (!l.empty()) {
        for (int d = 0; d < 2; ++d) {
          if (!wrap[d]) continue;
          while (x[d] - l.back()[d] > 0.5 * period[d]) x[d] -= period[d];
          while (x[d] - l.back()[d] < -0.5 * period[d]) x[d] += period[d];
        }
      }
      l.push_back(x);
    }
    uv.push_back(std::move(l));
  }
  // Mean metric scale per direction, and the orientation of (u, v).
  double su = 0.0, sv = 0.0, orient = 0.0;
  int count = 0;
  const double hu = 1e-5 * std::max(period[0], 1e-12), hv = 1e-5 * std::max(period[1], 1e-12);
  for (const auto& l : uv) {
    for (const auto& x : l) {
      const geom::Vec3 du =
          (surface.point(x + geom::Vec2(hu, 0)) - surface.point(x - geom::Vec2(hu, 0))) / (2 * hu);
      const geom::Vec3 dv =
          (surface.point(x + geom::Vec2(0, hv)) - surface.point(x - geom::Vec2(0, hv))) / (2 * hv);
      su += du.norm();
      sv += dv.norm();
      orient += du.cross(dv).dot(surface.normal(x));
      ++count;
    }
  }
  su_ = count > 0 && su > 0 ? su / count : 1.0;
  sv_ = count > 0 && sv > 0 ? sv / count : 1.0;
  if (orient < 0) sv_ = -sv_;
  for (const auto& l : uv) {
    std::vector<Eigen::Vector2d> out;
    for (const auto& x : l) out.emplace_back(x[0] * su_, x[1] * sv_);
    loops_2d_.push_back(std::move(out));
  }
  mirror_if_clockwise();
}

void SurfaceTo2D::mirror_if_clockwise() {
  double area = 0.0;
  const auto& outer = loops_2d_.front();
  for (size_t k = 0; k < outer.size(); ++k) {
    const Eigen::Vector2d& a = outer[k];
    const Eigen::Vector2d& b = outer[(k + 1) % outer.size()];
    area += a.x() * b.y() - a.y() * b.x();
  }
  if (area >= 0) return;
  mirrored_ = true;
  for (auto& l : loops_2d_) {
    for (auto& p : l) p.y() = -p.y();
  }
}

geom::Vec3 SurfaceTo2D::to_3d(const Eigen::Vector2d& xm) const {
  const Eigen::Vector2d x(xm.x(), mirrored_ ? -xm.y() : xm.y());
  if (planar_) return origin_ + x.x() * ex_ + x.y() * ey_;
  return surface_.point(geom::Vec2(x.x() / su_, x.y() / sv_));
}

geom::Vec3 SurfaceTo2D::normal_at(const Eigen::Vector2d& xm) const {
  const Eigen::Vector2d x(xm.x(), mirrored_ ? -xm.y() : xm.y());
  if (planar_) return normal_;
  return surface_.normal(geom::Vec2(x.x() / su_, x.y() / sv_));
}

}  // namespace cooperage::pave
