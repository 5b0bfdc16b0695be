#include "framework/decompose/cut_surface.h"

#include "framework/core/text.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

namespace cooperage::decompose {
namespace {

std::string num(double x) { return number_text(std::abs(x) < 5e-13 ? 0.0 : x); }

std::string vec(const geom::Vec3& v) {
  return "(" + num(v.x()) + " " + num(v.y()) + " " + num(v.z()) + ")";
}

// "x", "y", "z" (or "-x" ...) when d is a coordinate axis, else "".
std::string axis_name(const geom::Vec3& d) {
  static const char* names[] = {"x", "y", "z"};
  for (int k = 0; k < 3; ++k) {
    if (std::abs(std::abs(d[k]) - 1.0) < 1e-9) return std::string(d[k] < 0 ? "-" : "") + names[k];
  }
  return {};
}

}  // namespace

double signed_distance(const CutSurface& cut, const geom::Vec3& p) {
  const geom::Vec3 d = cut.direction.normalized();
  const geom::Vec3 r = p - cut.origin;
  if (cut.kind == CutSurface::Kind::Plane) return d.dot(r);
  const double radial = (r - r.dot(d) * d).norm();
  if (cut.kind == CutSurface::Kind::Cylinder) return radial - cut.radius;
  // Cone: the radial gap to the cone at p's height, measured normal to it.
  return (radial - cut.radius - r.dot(d) * std::tan(cut.half_angle)) * std::cos(cut.half_angle);
}

Span span(const CutSurface& cut, const std::vector<geom::Vec3>& points) {
  Span s{std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  for (const auto& p : points) {
    const double d = signed_distance(cut, p);
    s.below = std::min(s.below, d);
    s.above = std::max(s.above, d);
  }
  return s;
}

bool same_surface(const CutSurface& a, const CutSurface& b, double tol) {
  if (a.kind != b.kind) return false;
  const geom::Vec3 da = a.direction.normalized(), db = b.direction.normalized();
  if (std::abs(da.dot(db)) < 1.0 - 1e-9) return false;
  if (a.kind == CutSurface::Kind::Plane) return std::abs(da.dot(b.origin - a.origin)) <= tol;
  const geom::Vec3 r = b.origin - a.origin;
  if (a.kind == CutSurface::Kind::Cylinder)
    return (r - r.dot(da) * da).norm() <= tol && std::abs(a.radius - b.radius) <= tol;
  // Cones: the same axis, opening the same way at the same angle, and b's
  // origin circle on a.
  return (r - r.dot(da) * da).norm() <= tol && da.dot(db) > 0 &&
         std::abs(a.half_angle - b.half_angle) <= 1e-9 &&
         std::abs(b.radius - a.radius - r.dot(da) * std::tan(a.half_angle)) <= tol;
}

std::string describe(const CutSurface& cut) {
  const geom::Vec3 d = cut.direction.normalized();
  const std::string axis = axis_name(d);
  if (cut.kind == CutSurface::Kind::Plane) {
    if (!axis.empty()) {
      const int k = axis.back() - 'x';
      return "plane " + axis.substr(axis.size() - 1) + " = " + num(cut.origin[k]);
    }
    return "plane through " + vec(cut.origin) + " normal " + vec(d);
  }
  if (cut.kind == CutSurface::Kind::Cone) {
    return "cone of half angle " + num(cut.half_angle * 180.0 / M_PI) +
           " degrees, r = " + num(cut.radius) + " at " + vec(cut.origin) + ", widening along " +
           (axis.empty() ? vec(d) : axis);
  }
  return "cylinder r = " + num(cut.radius) + " about the axis through " + vec(cut.origin) +
         " along " + (axis.empty() ? vec(d) : axis);
}

}  // namespace cooperage::decompose
