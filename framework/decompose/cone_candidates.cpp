#include "framework/decompose/cone_candidates.h"

#include "framework/decompose/surface_fit.h"
#include "framework/decompose/volume_samples.h"

#include <algorithm>
#include <cmath>

namespace cooperage::decompose {
namespace {

constexpr double kCircleTolerance = 1e-3;  ///< of the radius
constexpr double kMinSkinAngleDeg = 30.0;

// Whether the two faces of the volume at curve c meet within `deg` of flat.
bool tangent_at(const geom::Model& model, int volume, int c, double deg) {
  const std::vector<Vec3> normals = outward_normals_at(model, volume, c);
  return normals.size() == 2 && normals[0].dot(normals[1]) > std::cos(deg * M_PI / 180.0);
}

// Unit normal of the faces at p on tangent curve c (either face: they agree).
Vec3 skin_normal(const geom::Model& model, int c, const Vec3& p) {
  return model.surface(model.curve(c).surfaces.front()).geometry->project(p).normal.normalized();
}

}  // namespace

std::optional<CircleFit> circle_of(const geom::Model& model, int c) {
  const geom::Curve& curve = model.curve(c);
  if (!curve.geometry || curve.start_vertex != curve.end_vertex) return std::nullopt;
  const auto [t0, t1] = curve.geometry->range();
  const auto at = [&](double f) { return curve.geometry->point(t0 + f * (t1 - t0)); };
  const auto circle = circle_through(at(0.1), at(0.43), at(0.77));
  if (!circle) return std::nullopt;
  CircleFit fit{circle->point, circle->axis, circle->radius, 0.0};
  for (int k = 0; k < 24; ++k) {
    const Vec3 r = at(k / 24.0) - fit.centre;
    const double along = r.dot(fit.normal);
    const double off = std::hypot(along, (r - along * fit.normal).norm() - fit.radius);
    fit.error = std::max(fit.error, off);
  }
  if (!(fit.error <= kCircleTolerance * fit.radius)) return std::nullopt;
  return fit;
}

std::vector<CutCandidate> cone_candidates(const geom::Model& model, int volume, double tangent_deg,
                                          int max_cones) {
  std::vector<std::pair<int, CircleFit>> circles;
  for (int c : curves_of(model, volume)) {
    if (!tangent_at(model, volume, c, tangent_deg)) continue;
    if (auto fit = circle_of(model, c)) circles.emplace_back(c, *fit);
  }
  std::vector<CutCandidate> out;
  for (size_t i = 0; i < circles.size(); ++i) {
    for (size_t j = i + 1; j < circles.size(); ++j) {
      if (static_cast<int>(out.size()) >= max_cones) return out;
      const auto& [ca, a] = circles[i];
      const auto& [cb, b] = circles[j];
      const double tol = kCircleTolerance * std::max(a.radius, b.radius);
      if (std::abs(a.normal.dot(b.normal)) < 1.0 - 1e-6) continue;
      const Vec3 axis = a.normal;
      const Vec3 d = b.centre - a.centre;
      const double height = d.dot(axis);
      if ((d - height * axis).norm() > tol) continue;  // not coaxial
      if (std::abs(height) <= tol || std::abs(b.radius - a.radius) <= tol) continue;
      const auto& sa = model.curve(ca).surfaces;
      const auto& sb = model.curve(cb).surfaces;
      if (std::find_first_of(sa.begin(), sa.end(), sb.begin(), sb.end()) != sa.end()) continue;
      // The cone widens along its direction: from the smaller circle.
      const bool a_small = a.radius < b.radius;
      const CircleFit& small = a_small ? a : b;
      const Vec3 dir = (a_small ? 1.0 : -1.0) * (height > 0 ? axis : Vec3(-axis));
      const double half_angle = std::atan2(std::abs(b.radius - a.radius), std::abs(height));
      const Vec3 to_vertex = model.vertex(model.curve(ca).start_vertex).point - a.centre;
      // The cut leaves both skins at kMinSkinAngle or more (a shallower cut
      // makes a sliver edge no hex along it can be good at).
      const Vec3 radial = (to_vertex - axis * axis.dot(to_vertex)).normalized();
      const Vec3 pa = a.centre + a.radius * radial, pb = b.centre + b.radius * radial;
      const Vec3 g = (pb - pa).normalized();
      const double min_sine = std::sin(kMinSkinAngleDeg * M_PI / 180.0);
      if (std::abs(g.dot(skin_normal(model, ca, pa))) < min_sine ||
          std::abs(g.dot(skin_normal(model, cb, pb))) < min_sine)
        continue;
      CutSurface cone;
      cone.kind = CutSurface::Kind::Cone;
      cone.origin = small.centre;
      cone.direction = dir;
      cone.radius = small.radius;
      cone.half_angle = half_angle;
      cone.seam = to_vertex - axis * axis.dot(to_vertex);
      cone.fuzzy = std::max(1e-7 * std::max(a.radius, b.radius), 4.0 * std::max(a.error, b.error));
      out.push_back(
          {cone, "cone through curves " + std::to_string(ca) + " and " + std::to_string(cb)});
    }
  }
  return out;
}

}  // namespace cooperage::decompose
