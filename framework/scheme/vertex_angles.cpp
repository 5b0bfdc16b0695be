#include "framework/scheme/vertex_angles.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

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

// Unit chord from a use's vertex (its end when at_end, else its start) to
// the point `fraction` of the parameter range away along the curve.
Vec3 chord_from_vertex(const geom::Curve& curve, geom::Sense sense, bool at_end, double fraction) {
  const auto [t0, t1] = curve.geometry->range();
  const bool at_t1 = (sense == geom::Sense::Forward) == at_end;
  const double t = at_t1 ? t1 : t0;
  const double inner = at_t1 ? t1 - fraction * (t1 - t0) : t0 + fraction * (t1 - t0);
  const Vec3 d = curve.geometry->point(inner) - curve.geometry->point(t);
  const double n = d.norm();
  return n > 0 ? Vec3(d / n) : Vec3::Zero();
}

// Angle, counter-clockwise about `normal`, from direction a to direction b,
// in [0, 360) degrees.
double ccw_degrees(const Vec3& a, const Vec3& b, const Vec3& normal) {
  double angle = std::atan2(normal.dot(a.cross(b)), a.dot(b)) * 180.0 / kPi;
  if (angle < 0.0) angle += 360.0;
  return angle;
}

// Where two curves leave a vertex along one line (a tangent cusp, angle 0,
// or a slit, 360) the sign of the tangents' vanishing cross product is
// noise; the chords a little way along the curves tell which (circle
// tangent to a line: the chord leans into the face by s / 2R).
constexpr double kTangentJunctionDegrees = 1.0;
constexpr double kChordFraction = 0.01;

// The interior angle at the junction in -> out: from the outgoing direction
// counter-clockwise (face on the left) to the direction back along `in`.
double interior_angle(const geom::Curve& cin, geom::Sense in_sense, const geom::Curve& cout,
                      geom::Sense out_sense, const Vec3& normal) {
  const Vec3 t_in = travel_direction(cin, in_sense, true);
  const Vec3 t_out = travel_direction(cout, out_sense, false);
  const double angle = ccw_degrees(t_out, -t_in, normal);
  if (angle > kTangentJunctionDegrees && angle < 360.0 - kTangentJunctionDegrees) return angle;
  const Vec3 back = chord_from_vertex(cin, in_sense, true, kChordFraction);
  const Vec3 ahead = chord_from_vertex(cout, out_sense, false, kChordFraction);
  const double chordal = ccw_degrees(ahead, back, normal);
  // The chords pick the side; the tangents, exact at the vertex, the size.
  return chordal < 180.0 ? std::min(angle, 360.0 - angle) : std::max(angle, 360.0 - angle);
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
  if (degrees < kMinEndAngle) return std::nullopt;
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
    const Vec3 normal = surface.geometry->project(model.vertex(c.vertex).point).normal;
    c.angle = interior_angle(cin, in.sense, cout, out.sense, normal);
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

namespace {

// The narrowest opening of a face at a vertex that several of its loops pass
// through (a hole touching the outer loop or another hole). Each loop leaves
// the union of its corners' sectors there on its left; the face is what all
// loops leave, the intersection, which can be far thinner than any one
// corner: a circle touching a line pinches the face into two cusps of angle
// 0 although both loops pass straight through. Sampled at 0.05 degrees;
// nothing left means 0.
double pinched_opening(const geom::Model& model, int surface_id,
                       const std::vector<std::vector<LoopCorner>>& corners, int vertex) {
  const geom::Surface& surface = model.surface(surface_id);
  const Vec3 normal = surface.geometry->project(model.vertex(vertex).point).normal;
  const Vec3 e1 = normal.unitOrthogonal();
  const Vec3 e2 = normal.cross(e1);
  constexpr int kSamples = 7200;
  std::vector<int> inside(kSamples, 0);  // loops leaving each direction on their left
  int loops_here = 0;
  for (size_t l = 0; l < corners.size(); ++l) {
    std::vector<char> mine(kSamples, 0);
    bool here = false;
    for (const LoopCorner& c : corners[l]) {
      if (c.vertex != vertex) continue;
      here = true;
      const geom::CurveUse& out = surface.loops[l].uses[static_cast<size_t>(c.use_index)];
      const Vec3 d = travel_direction(model.curve(out.curve), out.sense, false);
      double start = std::atan2(d.dot(e2), d.dot(e1)) * 180.0 / kPi;
      if (start < 0.0) start += 360.0;
      for (int k = 0; k < kSamples; ++k) {
        double a = (k + 0.5) * 360.0 / kSamples - start;
        if (a < 0.0) a += 360.0;
        if (a < c.angle) mine[static_cast<size_t>(k)] = 1;
      }
    }
    if (!here) continue;
    ++loops_here;
    for (int k = 0; k < kSamples; ++k) inside[static_cast<size_t>(k)] += mine[static_cast<size_t>(k)];
  }
  // The narrowest run of directions every loop leaves open (runs may wrap).
  int first_closed = -1;
  for (int k = 0; k < kSamples && first_closed < 0; ++k)
    if (inside[static_cast<size_t>(k)] < loops_here) first_closed = k;
  if (first_closed < 0) return 360.0;
  double narrowest = 360.0;
  bool any = false;
  int run = 0;
  for (int i = 1; i <= kSamples; ++i) {
    const int k = (first_closed + i) % kSamples;
    if (inside[static_cast<size_t>(k)] == loops_here) {
      ++run;
    } else if (run > 0) {
      narrowest = std::min(narrowest, run * 360.0 / kSamples);
      any = true;
      run = 0;
    }
  }
  return any ? narrowest : 0.0;
}

}  // namespace

std::optional<LoopCorner> sharpest_corner(const geom::Model& model, int surface_id) {
  std::optional<LoopCorner> out;
  const auto& loops = model.surface(surface_id).loops;
  std::vector<std::vector<LoopCorner>> corners;
  std::map<int, std::set<size_t>> loops_at;  // vertex -> the loops through it
  for (size_t l = 0; l < loops.size(); ++l) {
    corners.push_back(loop_corners(model, surface_id, static_cast<int>(l)));
    for (const LoopCorner& c : corners.back()) {
      loops_at[c.vertex].insert(l);
      if (!out || c.angle < out->angle) out = c;
    }
  }
  for (const auto& [vertex, through] : loops_at) {
    if (through.size() < 2) continue;
    const double opening = pinched_opening(model, surface_id, corners, vertex);
    if (out && opening < out->angle) {
      for (const LoopCorner& c : corners[*through.begin()]) {
        if (c.vertex != vertex) continue;
        out = c;
        out->angle = opening;
        out->type = classify_angle(opening);
        break;
      }
    }
  }
  return out;
}

}  // namespace cooperage::scheme
