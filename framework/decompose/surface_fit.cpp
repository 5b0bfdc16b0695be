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

namespace {

// The circle through one parameter line of g at the middle of the other
// (three points at 0.1, 0.5 and 0.9 of its range), if a fourth point (at
// 0.3) lies on it.
std::optional<Cylinder> circle_along(const geom::SurfaceGeometry& g, bool vary_u) {
  const auto [u, v] = g.uv_bounds();
  const geom::Vec2 lo(u.x(), v.x()), hi(u.y(), v.y());
  const geom::Vec2 mid = 0.5 * (lo + hi);
  const auto at = [&](double t) {
    geom::Vec2 p = mid;
    if (vary_u)
      p.x() = lo.x() + t * (hi.x() - lo.x());
    else
      p.y() = lo.y() + t * (hi.y() - lo.y());
    return g.point(p);
  };
  auto circle = circle_through(at(0.1), at(0.5), at(0.9));
  if (!circle) return std::nullopt;
  const Vec3 r = at(0.3) - circle->point;
  const double off_plane = std::abs(r.dot(circle->axis));
  const double off_circle =
      std::abs((r - r.dot(circle->axis) * circle->axis).norm() - circle->radius);
  if (off_plane + off_circle > 1e-6 * std::max(1.0, circle->radius)) return std::nullopt;
  return circle;
}

}  // namespace

std::optional<Cylinder> cylinder_of(const geom::Surface& surface) {
  if (!surface.geometry || surface.geometry->type() != geom::SurfaceType::Cylinder)
    return std::nullopt;
  // Whichever of u and v runs round the axis.
  if (auto c = circle_along(*surface.geometry, true)) return c;
  return circle_along(*surface.geometry, false);
}

std::optional<Cylinder> torus_axis_of(const geom::Surface& surface) {
  if (!surface.geometry || surface.geometry->type() != geom::SurfaceType::Torus)
    return std::nullopt;
  // The kernel's u runs round the torus's axis (v round the tube).
  return circle_along(*surface.geometry, true);
}

double signed_distance(const Plane& plane, const Vec3& p) {
  return plane.normal.dot(p - plane.point);
}

double signed_distance(const Cylinder& cylinder, const Vec3& p) {
  const Vec3 r = p - cylinder.point;
  return (r - r.dot(cylinder.axis) * cylinder.axis).norm() - cylinder.radius;
}

}  // namespace cooperage::decompose
