#include "framework/scheme/vertex_angles.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace cooperage::scheme {
namespace {

using geom::Vec3;

constexpr double kPi = 3.14159265358979323846;

// Unit direction of travel along a curve use, at its start (at_end false) or
// end (at_end true). Falls back to a short chord where the derivative vanishes.
Vec3 travel_direction(const geom::Curve& curve, geom::Sense sense, bool at_end) {
  const auto [t0, t1] = curve.geometry->range();
  // Walking Forward, the use starts at t0 and ends at t1.
  const bool at_t1 = (sense == geom::Sense::Forward) == at_end;
  const double t = at_t1 ? t1 : t0;
  Vec3 d = curve.geometry->tangent(t);
  if (d.norm() < 1e-12 * std::max(1.0, curve.length)) {
    const double inner = at_t1 ? t1 - 0.01 * (t1 - t0) : t0 + 0.01 * (t1 - t0);
    d = at_t1 ? Vec3(curve.geometry->point(t) - curve.geometry->point(inner))
              : Vec3(curve.geometry->point(inner) - curve.geometry->point(t));
  }
  if (sense == geom::Sense::Reversed) d = -d;
  const double n = d.norm();
  return n > 0 ? Vec3(d / n) : Vec3::Zero();
}

}  // namespace

const char* to_string(VertexType type) {
  switch (type) {
    case VertexType::End: return "END";
    case VertexType::Side: return "SIDE";
    case VertexType::Corner: return "CORNER";
    case VertexType::Reversal: return "REVERSAL";
  }
  return "?";
}

double ideal_angle_degrees(VertexType type) { return 90.0 * (2 - static_cast<int>(type)); }

double predicted_corner_quality(double degrees, VertexType type) {
  const int k = 2 - static_cast<int>(type);  // quad corners sharing the angle
  const double q = std::sin(degrees / k * kPi / 180.0);
  return std::clamp(q, 0.0, 1.0);
}

std::optional<VertexType> classify_angle(double degrees) {
  if (degrees < 45.0) return std::nullopt;
  if (degrees < 130.0) return VertexType::End;
  if (degrees < 225.0) return VertexType::Side;
  if (degrees < 315.0) return VertexType::Corner;
  return VertexType::Reversal;
}

std::vector<LoopCorner> loop_corners(const geom::Model& model, int surface_id, int loop_index) {
  const geom::Surface& surface = model.surface(surface_id);
  const geom::Loop& loop = surface.loops.at(static_cast<size_t>(loop_index));
  const size_t n = loop.uses.size();
  std::vector<LoopCorner> corners;
  corners.reserve(n);
  for (size_t k = 0; k < n; ++k) {
    const geom::CurveUse& in = loop.uses[(k + n - 1) % n];
    const geom::CurveUse& out = loop.uses[k];
    const geom::Curve& cin = model.curve(in.curve);
    const geom::Curve& cout = model.curve(out.curve);
    LoopCorner c;
    c.use_index = static_cast<int>(k);
    c.vertex = out.sense == geom::Sense::Forward ? cout.start_vertex : cout.end_vertex;
    const Vec3 t_in = travel_direction(cin, in.sense, true);
    const Vec3 t_out = travel_direction(cout, out.sense, false);
    const Vec3 normal = surface.geometry->project(model.vertex(c.vertex).point).normal;
    // Interior angle = pi - signed turning angle about the normal (face on the left).
    const double turn = std::atan2(normal.dot(t_in.cross(t_out)), t_in.dot(t_out));
    c.angle = (kPi - turn) * 180.0 / kPi;
    c.type = classify_angle(c.angle);
    corners.push_back(c);
  }
  return corners;
}

std::vector<std::vector<int>> sides_between_ends(const std::vector<LoopCorner>& corners,
                                                 size_t use_count) {
  std::vector<int> ends;
  for (const auto& c : corners) {
    if (c.type == VertexType::End) ends.push_back(c.use_index);
  }
  std::vector<std::vector<int>> sides;
  for (size_t s = 0; s < ends.size(); ++s) {
    const int first = ends[s];
    const int stop = ends[(s + 1) % ends.size()];
    std::vector<int> uses;
    int k = first;
    do {
      uses.push_back(k);
      k = static_cast<int>((static_cast<size_t>(k) + 1) % use_count);
    } while (k != stop);
    sides.push_back(std::move(uses));
  }
  return sides;
}

std::optional<LoopCorner> sharpest_corner(const geom::Model& model, int surface_id) {
  std::optional<LoopCorner> out;
  const auto& loops = model.surface(surface_id).loops;
  for (size_t l = 0; l < loops.size(); ++l) {
    for (const LoopCorner& c : loop_corners(model, surface_id, static_cast<int>(l))) {
      if (!out || c.angle < out->angle) out = c;
    }
  }
  return out;
}

}  // namespace cooperage::scheme
