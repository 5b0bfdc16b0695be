#include "framework/pipeline/plan_schemes.h"

#include "framework/core/error.h"

namespace cooperage::pipeline {
namespace {

template <class Setting>
const Setting* find_setting(const std::vector<Setting>& settings, int id) {
  for (const auto& s : settings) {
    if (s.id == id) return &s;
  }
  return nullptr;
}

std::string pin_place(const io::SourceLocation& where) {
  return where.file.empty() ? std::string("the job")
                            : where.file + ":" + std::to_string(where.line);
}

// The best applicable scheme of a list, or an error listing every reason.
template <class Scheme, class View>
PlanEntry first_applicable(const std::vector<const Scheme*>& schemes, const View& view,
                           EntityRef entity) {
  std::string reasons;
  const Scheme* best = nullptr;
  double best_score = -1;
  for (const Scheme* s : schemes) {
    const scheme::Applicability a = s->applicable(view);
    if (a.ok && a.score > best_score) {
      best = s;
      best_score = a.score;
    }
    if (!a.ok) reasons += std::string(reasons.empty() ? "" : "; ") + std::string(s->name()) + ": " + a.why;
  }
  if (!best) {
    throw MeshingError(ErrorCode::NotApplicable, entity,
                       "no scheme applies" + (reasons.empty() ? std::string(" (none registered)")
                                                              : " (" + reasons + ")"));
  }
  return {std::string(best->name()), "first applicable scheme"};
}

}  // namespace

SchemePlan plan_schemes(const geom::Model& model, const scheme::Registry& registry,
                        const io::MeshSettings& settings, int dim) {
  SchemePlan plan;
  if (dim == 3) {
    for (const geom::Volume& volume : model.volumes()) {
      const scheme::VolumeView view{model, volume.id, nullptr};
      const io::VolumeSetting* pin = find_setting(settings.volumes, volume.id);
      PlanEntry entry;
      if (pin && pin->scheme != "auto") {
        const scheme::VolumeScheme* s = registry.volume_scheme(pin->scheme);
        if (!s) {
          throw MeshingError(ErrorCode::NotSupported, EntityRef::volume(volume.id),
                             "volume scheme \"" + pin->scheme + "\" (" + pin_place(pin->where) +
                                 ") is not available in this release");
        }
        const scheme::Applicability a = s->applicable(view);
        if (!a.ok) throw MeshingError(ErrorCode::NotApplicable, EntityRef::volume(volume.id), a.why);
        entry = {pin->scheme, "pinned at " + pin_place(pin->where)};
      } else {
        entry = first_applicable(registry.volume_schemes(), view, EntityRef::volume(volume.id));
      }
      for (const auto& [surface, role] : registry.volume_scheme(entry.scheme)->roles(view)) {
        auto it = plan.surfaces.find(surface);
        if (it != plan.surfaces.end() && it->second.scheme != role) {
          throw MeshingError(ErrorCode::InvalidInput, EntityRef::surface(surface),
                             "volume " + std::to_string(volume.id) + " (" + entry.scheme +
                                 ") needs " + role + " but " + it->second.reason + " needs " +
                                 it->second.scheme);
        }
        plan.surfaces[surface] = {role, "role from volume " + std::to_string(volume.id) + " (" +
                                            entry.scheme + ")"};
      }
      plan.volumes[volume.id] = entry;
    }
  }
  for (const geom::Surface& surface : model.surfaces()) {
    const scheme::SurfaceView view{model, surface.id, nullptr};
    const io::SurfaceSetting* pin = find_setting(settings.surfaces, surface.id);
    auto planned = plan.surfaces.find(surface.id);
    if (planned != plan.surfaces.end() && planned->second.scheme == scheme::kMeshedByVolume) {
      if (pin && pin->scheme != "auto") {
        throw MeshingError(ErrorCode::InvalidInput, EntityRef::surface(surface.id),
                           "pinned to " + pin->scheme + " at " + pin_place(pin->where) +
                               " but it is meshed by its volume (" + planned->second.reason + ")");
      }
      continue;
    }
    if (pin && pin->scheme != "auto") {
      const scheme::SurfaceScheme* s = registry.surface_scheme(pin->scheme);
      if (!s) {
        throw MeshingError(ErrorCode::NotSupported, EntityRef::surface(surface.id),
                           "surface scheme \"" + pin->scheme + "\" (" + pin_place(pin->where) +
                               ") is not available in this release");
      }
      if (planned != plan.surfaces.end() && planned->second.scheme != pin->scheme) {
        throw MeshingError(ErrorCode::InvalidInput, EntityRef::surface(surface.id),
                           "pinned to " + pin->scheme + " at " + pin_place(pin->where) + " but " +
                               planned->second.reason + " needs " + planned->second.scheme);
      }
      plan.surfaces[surface.id] = {pin->scheme, "pinned at " + pin_place(pin->where)};
    } else if (planned == plan.surfaces.end()) {
      plan.surfaces[surface.id] =
          first_applicable(registry.surface_schemes(), view, EntityRef::surface(surface.id));
    }
    // A surface scheme fixed by a role or pin must still apply.
    const scheme::SurfaceScheme* s = registry.surface_scheme(plan.surfaces[surface.id].scheme);
    if (!s) {
      throw MeshingError(ErrorCode::NotSupported, EntityRef::surface(surface.id),
                         "surface scheme \"" + plan.surfaces[surface.id].scheme +
                             "\" is not available in this release");
    }
    const scheme::Applicability a = s->applicable(view);
    if (!a.ok) throw MeshingError(ErrorCode::NotApplicable, EntityRef::surface(surface.id), a.why);
  }
  return plan;
}

}  // namespace cooperage::pipeline
