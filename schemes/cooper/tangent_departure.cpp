#include "schemes/cooper/tangent_departure.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace cooperage::cooper {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kSteps = 64;  // chords sampled along a departing curve

bool uses_curve(const geom::Surface& s, int curve) {
  for (const auto& loop : s.loops) {
    for (const auto& use : loop.uses) {
      if (use.curve == curve) return true;
    }
  }
  return false;
}

// Walks `along` away from `vertex` and measures each chord's rise off the
// plane through p0 with normal n (unit).
TangentDeparture walk(const geom::Curve& along, int vertex, const geom::Vec3& p0,
                      const geom::Vec3& n, const geom::Vec3& outward) {
  TangentDeparture d;
  d.along = along.id;
  d.vertex = vertex;
  d.length = along.length;
  const bool from_start = along.start_vertex == vertex;
  const double target = std::sin(kTangentLiftDeg * kPi / 180.0);
  double prev_s = 0, prev_lift = 0;
  for (int i = 1; i <= kSteps; ++i) {
    const double s = along.length * i / kSteps;
    const double t = along.geometry->parameter_at_length(from_start ? s : along.length - s);
    const geom::Vec3 chord = along.geometry->point(t) - p0;
    const double len = chord.norm();
    if (len == 0) continue;
    const double lift = std::abs(chord.dot(n)) / len;
    if (lift > d.max_lift) {
      d.max_lift = lift;
      d.into_volume = chord.dot(outward) < 0;
    }
    if (lift >= target) {
      const double f = lift > prev_lift ? (target - prev_lift) / (lift - prev_lift) : 1.0;
      d.first_size = prev_s + std::clamp(f, 0.0, 1.0) * (s - prev_s);
      d.into_volume = chord.dot(outward) < 0;
      break;
    }
    prev_s = s;
    prev_lift = lift;
  }
  d.max_lift = std::asin(std::min(1.0, d.max_lift)) * 180.0 / kPi;
  return d;
}

}  // namespace

std::vector<TangentDeparture> tangent_departures(const geom::Model& model, int volume_id, int curve,
                                                 int face, int other) {
  const geom::Curve& c = model.curve(curve);
  const geom::Surface& sf = model.surface(face);
  const geom::Surface& so = model.surface(other);
  const double out_sign = geom::sign(model.sense_in(other, volume_id));
  std::vector<TangentDeparture> out;
  std::set<std::pair<int, int>> seen;  // (along, vertex): a seam is used twice
  for (int v : {c.start_vertex, c.end_vertex}) {
    const geom::Vec3 p0 = model.vertex(v).point;
    const auto at = so.geometry->project(p0);
    const geom::Vec3 n = at.normal.normalized();
    for (const auto& loop : sf.loops) {
      for (const auto& use : loop.uses) {
        const geom::Curve& k = model.curve(use.curve);
        if (k.id == curve || (k.start_vertex != v && k.end_vertex != v)) continue;
        if (uses_curve(so, k.id) || !seen.insert({k.id, v}).second) continue;
        TangentDeparture d = walk(k, v, p0, n, out_sign * n);
        d.curve = curve;
        d.face = face;
        d.other = other;
        out.push_back(d);
      }
    }
  }
  return out;
}

}  // namespace cooperage::cooper
