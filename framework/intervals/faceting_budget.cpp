#include "framework/intervals/faceting_budget.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace cooperage::intervals {
namespace {

/// Curves turning less than this are straight for the budget.
constexpr double kMinTurning = M_PI / 180.0;
/// Relative difference below which two faces weigh the same.
constexpr double kSameWeight = 1e-6;

/// Segment area an arc of turning t and length l loses to n chords.
double arc_loss(double turning, double length, int n) {
  const double r = length / turning;
  const double phi = turning / n;
  return 0.5 * r * r * (turning - n * std::sin(phi));
}

/// Fraction by which n flat panels are shorter than the arc they span.
double panel_shortfall(double turning, int n) {
  const double half = 0.5 * turning / n;
  return 1.0 - std::sin(half) / half;
}

/// A non-planar face and its turning boundary curves.
struct RoundFace {
  int surface = 0;
  double area = 0.0;
  std::vector<int> curves;
  /// Per curve: +1 where the face is convex across it (its facets cut the
  /// volume short, a rod), -1 where concave (a hole's facets add volume).
  std::vector<double> signs;
  double length = 0.0;  ///< sum of the curves' lengths
};

struct Loss {
  double volume = 0.0;
  double area = 0.0;
};

Loss face_loss(const RoundFace& f, const geom::Model& model,
               const std::map<int, TurningCurve>& curves, const std::map<int, int>& counts) {
  Loss out;
  if (f.length <= 0) return out;
  for (std::size_t k = 0; k < f.curves.size(); ++k) {
    const int c = f.curves[k];
    const TurningCurve& t = curves.at(c);
    const double l = model.curve(c).length;
    const int n = counts.at(c);
    out.volume += f.signs[k] * arc_loss(t.turning, l, n);
    out.area += l * panel_shortfall(t.turning, n);
  }
  out.volume *= f.area / f.length;
  out.area *= f.area / f.length;
  return out;
}

/// +1 when surface s is convex across curve c as seen from volume v (the
/// curve's centre of curvature lies behind the outward normal), else -1.
double convexity(const geom::Model& model, int s, int v, int c) {
  const geom::CurveGeometry& curve = *model.curve(c).geometry;
  const auto [t0, t1] = curve.range();
  const double t = 0.5 * (t0 + t1), dt = 1e-3 * (t1 - t0);
  const geom::Vec3 p = curve.point(t);
  // Towards the centre of curvature: the chord's midpoint lies inside the arc.
  const geom::Vec3 inward = 0.5 * (curve.point(t - dt) + curve.point(t + dt)) - p;
  const geom::Vec3 normal = model.outward_normal(s, v, model.surface(s).geometry->project(p).uv);
  return normal.dot(inward) < 0 ? 1.0 : -1.0;
}

std::vector<RoundFace> round_faces(const geom::Model& model, int volume,
                                   const std::map<int, TurningCurve>& curves) {
  std::vector<RoundFace> out;
  for (int s : model.surfaces_of(volume)) {
    const geom::Surface& surface = model.surface(s);
    if (surface.geometry->type() == geom::SurfaceType::Plane) continue;
    RoundFace f;
    f.surface = s;
    f.area = surface.area;
    std::set<int> seen;
    for (const geom::Loop& loop : surface.loops) {
      for (const geom::CurveUse& use : loop.uses) {
        const auto it = curves.find(use.curve);
        if (it == curves.end() || !(it->second.turning >= kMinTurning)) continue;
        if (!seen.insert(use.curve).second) continue;
        f.curves.push_back(use.curve);
        f.signs.push_back(convexity(model, s, volume, use.curve));
        f.length += model.curve(use.curve).length;
      }
    }
    if (!f.curves.empty()) out.push_back(std::move(f));
  }
  return out;
}

double boundary_area(const geom::Model& model, int volume) {
  double a = 0.0;
  for (int s : model.surfaces_of(volume)) a += model.surface(s).area;
  return a;
}

std::map<int, int> start_counts(const std::map<int, TurningCurve>& curves) {
  std::map<int, int> counts;
  for (const auto& [id, t] : curves) counts[id] = std::max(1, t.intervals);
  return counts;
}

}  // namespace

FacetingLoss faceting_loss(const geom::Model& model, int volume,
                           const std::map<int, TurningCurve>& curves) {
  const std::map<int, int> counts = start_counts(curves);
  FacetingLoss out;
  for (const RoundFace& f : round_faces(model, volume, curves)) {
    const Loss l = face_loss(f, model, curves, counts);
    out.volume += l.volume;
    out.area += l.area;
  }
  return out;
}

std::map<int, int> faceting_minima(const geom::Model& model,
                                   const std::map<int, TurningCurve>& curves,
                                   const FacetingOptions& options) {
  std::map<int, int> counts = start_counts(curves);
  std::map<int, int> raised;
  if (!(options.fraction > 0)) return raised;
  const double finest = std::max(options.min_turn_deg, 0.1) * M_PI / 180.0;
  for (const geom::Volume& v : model.volumes()) {
    const std::vector<RoundFace> faces = round_faces(model, v.id, curves);
    if (faces.empty()) continue;
    const double volume_budget = options.fraction * std::abs(v.volume);
    const double area_budget = options.fraction * boundary_area(model, v.id);
    if (!(volume_budget > 0) || !(area_budget > 0)) continue;
    const auto can_raise = [&](const RoundFace& f) {
      for (int c : f.curves) {
        if (counts[c] < std::ceil(curves.at(c).turning / finest)) return true;
      }
      return false;
    };
    // Each pass raises at least one curve by >= 1 towards a finite cap.
    for (;;) {
      Loss total;
      std::vector<Loss> loss(faces.size());
      for (std::size_t i = 0; i < faces.size(); ++i) {
        loss[i] = face_loss(faces[i], model, curves, counts);
        total.volume += loss[i].volume;
        total.area += loss[i].area;
      }
      // Losses and gains cancel in the volume (a tube's bore against its
      // outside), as in the run's check; areas only shrink.
      const bool volume_over = std::abs(total.volume) > volume_budget;
      const bool area_over = total.area > area_budget;
      if (!volume_over && !area_over) break;
      // The faces that weigh most against the budget(s) exceeded; for the
      // volume, only faces erring in the same direction as the total.
      const double direction = total.volume > 0 ? 1.0 : -1.0;
      const auto weight = [&](const Loss& l) {
        return (volume_over ? std::max(0.0, direction * l.volume) / volume_budget : 0.0) +
               (area_over ? l.area / area_budget : 0.0);
      };
      // Faces that weigh the same up to rounding (the halves of a split
      // cylinder, a pattern of holes) are raised together, so that a moved
      // model, whose areas differ in the last bits, is sized the same.
      double heaviest = 0.0;
      for (std::size_t i = 0; i < faces.size(); ++i) {
        if (can_raise(faces[i])) heaviest = std::max(heaviest, weight(loss[i]));
      }
      if (!(heaviest > 0))
        break;  // every round face at its finest: the run's check reports the rest
      std::set<int> raise;
      for (std::size_t i = 0; i < faces.size(); ++i) {
        if (can_raise(faces[i]) && weight(loss[i]) >= heaviest * (1.0 - kSameWeight))
          raise.insert(faces[i].curves.begin(), faces[i].curves.end());
      }
      for (int c : raise) {
        const int cap = static_cast<int>(std::ceil(curves.at(c).turning / finest));
        int& n = counts[c];
        if (n >= cap) continue;
        n = std::min(cap, std::max(n + 1, static_cast<int>(std::ceil(1.25 * n))));
        raised[c] = n;
      }
    }
  }
  return raised;
}

}  // namespace cooperage::intervals
