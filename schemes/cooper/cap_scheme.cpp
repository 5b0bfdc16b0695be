#include "schemes/cooper/cap_scheme.h"

namespace cooperage::cooper {
namespace {

// The cap schemes are asked of the registry by role (scheme::Role), never by
// name, so a plug-in scheme serving the role competes on its score.

std::string no_scheme(int surface, const char* what, const std::string& reasons) {
  return "no " + std::string(what) + " scheme meshes cap surface " + std::to_string(surface) +
         " (" + reasons + ")";
}

// Mixed mode: the best-scoring scheme serving mixed caps, where an all-quad
// one (it also serves quad caps: map, submap; its score is the scaled
// Jacobian it reaches) counts only at kMixedMinQuadQuality or more, so a
// face where it would squash a corner goes to quad_dominant (pave with its
// quads below that quality split into triangles). Plain pave does not serve
// mixed caps: it keeps a poor quad where mixed mode wants two triangles.
std::string mixed_cap_scheme(const geom::Model& model, const scheme::Registry& registry,
                             int surface, std::string& why, const scheme::Settings* settings) {
  const scheme::SurfaceView view{model, surface, nullptr, settings};
  const scheme::SurfaceScheme* best = nullptr;
  double best_score = -1.0;
  std::string reasons;
  const auto candidates = registry.surface_schemes(scheme::Role::MixedCap);
  for (const scheme::SurfaceScheme* s : candidates) {
    const scheme::Applicability a = s->applicable(view);
    const bool quads_only = scheme::serves(s->serves(), scheme::Role::QuadCap);
    if (!a.ok) {
      reasons += (reasons.empty() ? "" : "; ") + std::string(s->name()) + ": " + a.why;
    } else if (quads_only && a.score < kMixedMinQuadQuality) {
      continue;
    } else if (a.score > best_score) {
      best = s;
      best_score = a.score;
    }
  }
  if (best) return std::string(best->name());
  why = no_scheme(surface, "mixed-cap",
                  candidates.empty() ? "no registered surface scheme serves mixed caps" : reasons);
  return {};
}

// The journal's scheme for the cap, when it pins one that serves `role`:
// a cap is meshed beforehand and taken as it is, so any scheme of its role
// will do, and the user's word wins over the best score. A pin of another
// role (tri on a hex cap) is left to the selector, which names the conflict.
const scheme::SurfaceScheme* pinned_cap_scheme(const scheme::Registry& registry, int surface,
                                               scheme::Role role,
                                               const scheme::Settings* settings) {
  if (settings == nullptr || settings->job == nullptr) return nullptr;
  for (const io::SurfaceSetting& s : settings->job->surfaces) {
    if (s.id != surface || s.scheme == "auto") continue;
    const scheme::SurfaceScheme* pinned = registry.surface_scheme(s.scheme);
    if (pinned != nullptr && scheme::serves(pinned->serves(), role)) return pinned;
  }
  return nullptr;
}

}  // namespace

std::string cap_scheme(const geom::Model& model, const scheme::Registry& registry, int surface,
                       std::string& why, Elements elements, const scheme::Settings* settings) {
  const scheme::Role role = elements == Elements::Mixed   ? scheme::Role::MixedCap
                            : elements == Elements::Wedge ? scheme::Role::TriCap
                                                          : scheme::Role::QuadCap;
  if (const scheme::SurfaceScheme* pinned = pinned_cap_scheme(registry, surface, role, settings))
    return std::string(pinned->name());
  if (elements == Elements::Mixed) return mixed_cap_scheme(model, registry, surface, why, settings);
  // Hex mode: the best-scoring quad-cap scheme (scores are the scaled
  // Jacobian each can reach, so a corner map/submap would squash goes to
  // pave); ties keep the registration order map, submap, pave, plug-ins.
  // Wedge mode: the best triangle scheme (tri).
  const scheme::RoleChoice c = scheme::best_surface_scheme(
      registry, role, scheme::SurfaceView{model, surface, nullptr, settings});
  if (c.scheme) return std::string(c.scheme->name());
  why = no_scheme(surface, elements == Elements::Wedge ? "triangle" : "quad", c.reasons);
  return {};
}

}  // namespace cooperage::cooper
