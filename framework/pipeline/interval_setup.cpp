#include "framework/pipeline/interval_setup.h"

#include "framework/core/error.h"
#include "framework/intervals/curve_sizing.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace cooperage::pipeline {
namespace {

template <class Setting>
const Setting* find_setting(const std::vector<Setting>& settings, int id) {
  for (const auto& s : settings) {
    if (s.id == id) return &s;
  }
  return nullptr;
}

void keep_min(std::optional<double>& best, std::optional<double> candidate) {
  if (candidate && (!best || *candidate < *best)) best = candidate;
}

intervals::Firmness to_firmness(io::Firmness f) {
  switch (f) {
    case io::Firmness::Hard: return intervals::Firmness::Hard;
    case io::Firmness::Soft: return intervals::Firmness::Soft;
    case io::Firmness::Default: return intervals::Firmness::Default;
  }
  return intervals::Firmness::Default;
}

}  // namespace

double curve_target_size(const geom::Model& model, const io::MeshSettings& settings, int curve_id) {
  if (const auto* own = find_setting(settings.curves, curve_id); own && own->sizing.size) {
    return *own->sizing.size;
  }
  std::optional<double> size;
  for (int s : model.curve(curve_id).surfaces) {
    if (const auto* set = find_setting(settings.surfaces, s)) keep_min(size, set->sizing.size);
    for (int v : model.surface(s).volumes) {
      if (const auto* set = find_setting(settings.volumes, v)) keep_min(size, set->sizing.size);
    }
  }
  if (!size) size = settings.size;
  if (!size) {
    throw MeshingError(ErrorCode::InvalidInput, EntityRef::curve(curve_id),
                       "no element size: set <mesh size=...> or a size on the curve, one of its "
                       "surfaces or volumes");
  }
  return *size;
}

intervals::IntervalProblem build_interval_problem(const geom::Model& model,
                                                  const scheme::Registry& registry,
                                                  const SchemePlan& plan,
                                                  const io::MeshSettings& settings) {
  intervals::IntervalProblem problem;
  // Goals that keep features (circles >= 6 intervals, round faces' volume,
  // thin faces and small neighbours graded): framework/intervals/curve_sizing.h.
  // Faceting may take half the volume tolerance, so that a round part at a
  // coarse size passes the run's own check with room for the rest.
  intervals::SizingOptions sizing_options;
  sizing_options.faceting.fraction = 0.5 * settings.volume_tolerance.value_or(0.01);
  const std::map<int, intervals::CurveSizing> sizing = intervals::curve_sizing(
      model, [&](int id) { return curve_target_size(model, settings, id); }, sizing_options);
  for (const geom::Curve& curve : model.curves()) {
    const bool closed = curve.start_vertex == curve.end_vertex;
    const int min = closed ? 2 : 1;  // a closed curve with one interval has no extent
    const auto* own = find_setting(settings.curves, curve.id);
    if (own && own->sizing.intervals) {
      const int n = *own->sizing.intervals;
      const io::Firmness f =
          own->sizing.firmness == io::Firmness::Default ? io::Firmness::Hard : own->sizing.firmness;
      if (n < min) {
        throw MeshingError(ErrorCode::InvalidInput, EntityRef::curve(curve.id),
                           "is closed and needs at least " + std::to_string(min) + " intervals, " +
                               std::to_string(n) + " given");
      }
      problem.add_curve(curve.id, static_cast<double>(n), to_firmness(f), n, min);
      continue;
    }
    const intervals::CurveSizing& z = sizing.at(curve.id);
    // Whole goals: with fractional ones from graded sizes the integer
    // program's relaxation was weak and CBC took minutes on large
    // components (real-cad impeller: > 2 min, whole: 3 s).
    const double goal =
        std::max<double>({intervals::whole_goal(z.goal), 1.0, static_cast<double>(z.min)});
    const int least = std::max(min, z.min);
    if (z.graded) problem.set_size_function(curve.id, z.sizes);
    const io::Firmness f = own ? own->sizing.firmness : io::Firmness::Default;
    if (f == io::Firmness::Hard) {  // the count the size gives, fixed exactly
      const int n = std::max(least, static_cast<int>(std::lround(goal)));
      problem.add_curve(curve.id, goal, intervals::Firmness::Hard, n, least);
    } else {
      problem.add_curve(curve.id, goal, to_firmness(f), std::nullopt, least);
    }
  }
  // Each scheme gets back the plan its applicable() made (PlanEntry::data).
  const scheme::Settings job = scheme::Settings::of(settings);
  for (const auto& [id, entry] : plan.surfaces) {
    if (entry.scheme == scheme::kMeshedByVolume) continue;  // its volume scheme constrains it
    registry.surface_scheme(entry.scheme)
        ->constrain(scheme::SurfaceView{model, id, nullptr, &job, entry.data.get()}, problem);
  }
  for (const auto& [id, entry] : plan.volumes) {
    registry.volume_scheme(entry.scheme)
        ->constrain(scheme::VolumeView{model, id, nullptr, &job, entry.data.get()}, problem);
  }
  return problem;
}

}  // namespace cooperage::pipeline
