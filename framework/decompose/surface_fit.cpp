#include "framework/decompose/surface_fit.h"

#include <Eigen/Geometry>

#include <cmath>

namespace cooperage::decompose {

std::optional<Plane> plane_of(const geom::Surface& surface) {
  if (!surface.geometry || surface.geometry->type() != geom::SurfaceType::Plane)
    return std::nullopt;
  const auto [u, v] = surface.geometry->uv_bounds();
  const geom::Vec2 mid(0.5 * (u.x() + u.y()), 0.5 * (v.x() + v.y()));
  const Vec3 n = surface.geometry->normal(mid);
  if (!(n.norm() > 0.5)) return std::nullopt;
  return Plane{surface.geometry->point(mid), n.normalized()};
}

std::optional<Cylinder> circle_through(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a;
  const Vec3 n = ab.cross(ac);
  const double n2 = n.squaredNorm();
  const double scale = std::max(ab.squaredNorm(), ac.squaredNorm());
  if (!(n2 > 1e-12 * scale * scale)) return std::nullopt;
  // Circumcentre of the triangle (a, b, c).
  const Vec3 centre =
      a + (ac.squaredNorm() * n.cross(ab) + ab.squaredNorm() * ac.cross(n)) / (2.0 * n2);
  return Cylinder{centre, n.normalized(), (a - centre).norm()};
}

std::optional<Cylinder> cylinder_of(const geom::Surface& surface) {
  if (!surface.geometry || surface.geometry->type() != geom::SurfaceType::Cylinder)
    return std::nullopt;
  const auto& g = *surface.geometry;
  const auto [u, v] = g.uv_bounds();
  // Three points along one parameter line at the middle of the other.
  const auto along = [&](bool vary_u) -> std::optional<Cylinder> {
    const geom::Vec2 lo(u.x(), v.x()), hi(u.y(), v.y());
    const geom::Vec2 mid = 0.5 * (lo + hi);
    geom::Vec2 p[3];
    for (int k = 0; k < 3; ++k) {
      const double t = 0.1 + 0.4 * k;  // 0.1, 0.5, 0.9 of the range
      p[k] = mid;
      if (vary_u)
        p[k].x() = lo.x() + t * (hi.x() - lo.x());
      else
        p[k].y() = lo.y() + t * (hi.y() - lo.y());
    }
    auto circle = circle_through(g.point(p[0]), g.point(p[1]), g.point(p[2]));
    if (!circle) return std::nullopt;
    // The line must lie on the circle: a fourth point checks it.
    geom::Vec2 q = mid;
    if (vary_u)
      q.x() = lo.x() + 0.3 * (hi.x() - lo.x());
    else
      q.y() = lo.y() + 0.3 * (hi.y() - lo.y());
    const Vec3 x = g.point(q);
    const Vec3 r = x - circle->point;
    const double off_plane = std::abs(r.dot(circle->axis));
    const double off_circle =
        std::abs((r - r.dot(circle->axis) * circle->axis).norm() - circle->radius);
    if (off_plane + off_circle > 1e-6 * std::max(1.0, circle->radius)) return std::nullopt;
    return circle;
  };
  if (auto c = along(true)) return c;
  return along(false);
}

double signed_distance(const Plane& plane, const Vec3& p) {
  return plane.normal.dot(p - plane.point);
}

double signed_distance(const Cylinder& cylinder, const Vec3& p) {
  const Vec3 r = p - cylinder.point;
  return (r - r.dot(cylinder.axis) * cylinder.axis).norm() - cylinder.radius;
}

}  // namespace cooperage::decompose
