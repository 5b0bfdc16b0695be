// Cooper plans in tests: from a registry's cooper scheme (as its
// applicable() returns them) or directly from plan_volume().
#pragma once

#include "schemes/cooper/cooper_scheme.h"
#include "schemes/cooper/plan_volume.h"

#include <memory>

namespace cooperage::cooper::plan_test {

/// The plan the registry's cooper scheme makes for a volume, for the job's
/// `settings` (null: none), as its applicable() returns it.
inline std::shared_ptr<const VolumePlan> scheme_plan(const scheme::Registry& registry,
                                                     const geom::Model& model, int volume_id,
                                                     const io::MeshSettings* settings = nullptr) {
  const auto* cooper = dynamic_cast<const CooperScheme*>(registry.volume_scheme("cooper"));
  if (!cooper) return nullptr;
  const scheme::Settings job = settings ? scheme::Settings::of(*settings) : scheme::Settings{};
  const std::shared_ptr<const CooperPlan> p =
      cooper->plan(scheme::VolumeView{model, volume_id, nullptr, &job});
  return {p, &p->plan};
}

/// A fresh plan (hex elements unless given).
inline VolumePlan plan_with(const geom::Model& model, int volume_id,
                            const scheme::Registry& registry, SweepHints hints = {},
                            bool polygon_mesher = true, Elements elements = Elements::Hex) {
  PlanInputs in;
  in.hints = std::move(hints);
  in.polygon_mesher = polygon_mesher;
  in.elements = elements;
  return plan_volume(model, volume_id, registry, in);
}

/// Real caps of a barrel end.
inline std::vector<int> end_caps(const std::vector<EndPiece>& end) {
  std::vector<int> out;
  for (const EndPiece& e : end) {
    if (e.cap) out.push_back(e.cap);
  }
  return out;
}

/// Virtual caps of a barrel end, as the barrels on their other side.
inline std::vector<int> end_barrels(const VolumePlan& p, const std::vector<EndPiece>& end,
                                    bool upper_end) {
  std::vector<int> out;
  for (const EndPiece& e : end) {
    if (e.interface < 0) continue;
    const BarrelInterface& v = p.tree.interfaces[static_cast<size_t>(e.interface)];
    out.push_back(upper_end ? v.above : v.below);
  }
  return out;
}

}  // namespace cooperage::cooper::plan_test
