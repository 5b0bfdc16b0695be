#include "framework/pipeline/mesh_size.h"

#include "framework/pipeline/interval_setup.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

namespace cooperage::pipeline {
namespace {

// Peak memory per element, meshing and exporting: a 100^3 brick at size 1
// (1,000,000 hexes, 60,000 quads, written to .exo) peaks at 196 MB resident,
// at size 2 (125,000 hexes, not written) at 70 MB: 144 bytes per extra hex,
// rounded up to 200 (/usr/bin/time -v cooperage run, docs/reliability.md).
constexpr double kBytesPerVolumeElement = 200;
constexpr double kBytesPerSurfaceElement = 200;

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2g", v);
  return buf;
}

double count_of(const std::map<int, double>& intervals, int curve) {
  const auto it = intervals.find(curve);
  return it == intervals.end() ? 1.0 : std::max(it->second, 1.0);
}

}  // namespace

std::map<int, double> interval_goals(const geom::Model& model, const io::MeshSettings& settings) {
  std::map<int, double> goals;
  for (const geom::Curve& c : model.curves()) {
    double goal = 0;
    for (const io::CurveSetting& s : settings.curves)
      if (s.id == c.id && s.sizing.intervals) goal = *s.sizing.intervals;
    if (goal == 0) goal = c.length / curve_target_size(model, settings, c.id);
    goals[c.id] = std::isfinite(goal) ? std::max(goal, 1.0) : 1e300;
  }
  return goals;
}

MeshSizeEstimate estimate_mesh_size(const geom::Model& model,
                                    const std::map<int, double>& intervals, int dim) {
  MeshSizeEstimate e;
  auto consider = [&](EntityRef who, double n) {
    if (n > e.largest_elements) {
      e.largest_elements = n;
      e.largest = who;
    }
  };
  for (const geom::Curve& c : model.curves()) e.nodes += count_of(intervals, c.id);
  double surface_elements = 0;
  for (const geom::Surface& s : model.surfaces()) {
    double length = 0, count = 0;
    for (const geom::Loop& loop : s.loops)
      for (const geom::CurveUse& u : loop.uses) {
        length += model.curve(u.curve).length;
        count += count_of(intervals, u.curve);
      }
    if (!(length > 0) || !(count > 0)) continue;
    const double h = length / count;
    const double quads = std::max(1.0, s.area / (h * h));
    surface_elements += quads;
    consider(EntityRef::surface(s.id), quads);
  }
  double volume_elements = 0;
  if (dim == 3) {
    for (const geom::Volume& v : model.volumes()) {
      std::set<int> curves;
      for (const auto& shell : v.shells)
        for (const geom::SurfaceUse& su : shell)
          for (const geom::Loop& loop : model.surface(su.surface).loops)
            for (const geom::CurveUse& u : loop.uses) curves.insert(u.curve);
      double length = 0, count = 0;
      for (int c : curves) {
        length += model.curve(c).length;
        count += count_of(intervals, c);
      }
      if (!(length > 0) || !(count > 0)) continue;
      const double h = length / count;
      const double hexes = std::max(1.0, v.volume / (h * h * h));
      volume_elements += hexes;
      consider(EntityRef::volume(v.id), hexes);
    }
  }
  e.elements = volume_elements + surface_elements;
  e.nodes += volume_elements + surface_elements;
  e.bytes = kBytesPerVolumeElement * volume_elements + kBytesPerSurfaceElement * surface_elements;
  return e;
}

void check_mesh_size(const MeshSizeEstimate& estimate, double limit) {
  // A curve alone can ask for more nodes than elements are allowed.
  const double worst = std::max(estimate.elements, estimate.nodes);
  if (!(worst > limit)) return;
  std::string where;
  if (estimate.largest.dim >= 0)
    where = " (" + estimate.largest.name() + " about " + number(estimate.largest_elements) + ")";
  throw MeshingError(ErrorCode::InvalidInput,
                     "the mesh would have about " + number(worst) + " elements" + where +
                         " and need about " + number(estimate.bytes / 1e9) + " GB; the limit is " +
                         number(limit) +
                         " (--max-elements, <mesh max_elements>): use a larger element size or "
                         "fewer intervals");
}

double element_limit(const io::MeshSettings& settings, std::optional<double> override) {
  return std::min(override.value_or(settings.max_elements.value_or(kDefaultMaxElements)),
                  kMaxElementsCeiling);
}

void check_planned_size(const geom::Model& model, const io::MeshSettings& settings, int dim) {
  if (!settings.size) return;
  check_mesh_size(estimate_mesh_size(model, interval_goals(model, settings), dim),
                  element_limit(settings));
}

}  // namespace cooperage::pipeline
