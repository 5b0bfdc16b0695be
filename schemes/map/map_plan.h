// What map's applicable() computed, handed back by the selector to
// constrain() and mesh() (scheme::PlanData), so the logical sides of a face
// are found once per run.
#pragma once

#include "framework/scheme/scheme.h"
#include "schemes/map/map_sides.h"

#include <map>
#include <memory>
#include <type_traits>

namespace cooperage::map {

/// The logical rectangle of one surface.
struct SurfaceMapPlan final : scheme::PlanData {
  int surface_id = 0;
  MapSides sides;
};

/// The logical rectangles of the six faces of a block, by surface id.
struct VolumeMapPlan final : scheme::PlanData {
  int volume_id = 0;
  std::map<int, MapSides> faces;
};

/// The plan `view` carries for its own entity, else one computed now; a
/// carried plan is not owned (the selector keeps it).
template <class Plan, class View, class Compute>
std::shared_ptr<const Plan> carried_or(const View& view, int id, Compute compute) {
  if (const Plan* carried = scheme::carried_plan<Plan>(view)) {
    if constexpr (std::is_same_v<Plan, SurfaceMapPlan>) {
      if (carried->surface_id == id) return {std::shared_ptr<const Plan>(), carried};
    } else {
      if (carried->volume_id == id) return {std::shared_ptr<const Plan>(), carried};
    }
  }
  return compute();
}

}  // namespace cooperage::map
