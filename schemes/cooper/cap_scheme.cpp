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

}  // namespace

std::string cap_scheme(const geom::Model& model, const scheme::Registry& registry, int surface,
                       std::string& why, Elements elements, const scheme::Settings* settings) {
  if (elements == Elements::Mixed) return mixed_cap_scheme(model, registry, surface, why, settings);
  // Hex mode: the best-scoring quad-cap scheme (scores are the scaled
  // Jacobian each can reach, so a corner map/submap would squash goes to
  // pave); ties keep the registration order map, submap, pave, plug-ins.
  // Wedge mode: the best triangle scheme (tri).
  const bool wedge = elements == Elements::Wedge;
  const scheme::RoleChoice c =
      scheme::best_surface_scheme(registry, wedge ? scheme::Role::TriCap : scheme::Role::QuadCap,
                                  scheme::SurfaceView{model, surface, nullptr, settings});
  if (c.scheme) return std::string(c.scheme->name());
  why = no_scheme(surface, wedge ? "triangle" : "quad", c.reasons);
  return {};
}

}  // namespace cooperage::cooper
