#include "schemes/cooper/cap_scheme.h"

namespace cooperage::cooper {
namespace {

// Wedge and mixed mode: `name` ("tri", "quad_dominant") when it meshes the
// cap, or why not.
std::string named_cap_scheme(const geom::Model& model, const scheme::Registry& registry, int surface,
                             const char* name, const char* purpose, std::string& why) {
  const scheme::SurfaceScheme* s = registry.surface_scheme(name);
  if (!s) {
    why = "cap surface " + std::to_string(surface) + " needs the " + name + " scheme for " + purpose +
          ", which is not available";
    return {};
  }
  const scheme::Applicability a = s->applicable(scheme::SurfaceView{model, surface, nullptr});
  if (a.ok) return name;
  why = std::string(name) + " does not mesh cap surface " + std::to_string(surface) + " (" + a.why + ")";
  return {};
}

// Mixed mode: map or submap where they reach the mixed quad quality (their
// score is the scaled Jacobian they reach), else quad_dominant (pave with
// its quads below that quality split into triangles). Plain pave is left
// out: it keeps a poor quad where mixed mode wants two triangles.
std::string mixed_cap_scheme(const geom::Model& model, const scheme::Registry& registry, int surface,
                             std::string& why) {
  std::string best;
  double best_score = -1.0;
  for (const char* name : {"map", "submap"}) {
    const scheme::SurfaceScheme* s = registry.surface_scheme(name);
    if (!s) continue;
    const scheme::Applicability a = s->applicable(scheme::SurfaceView{model, surface, nullptr});
    if (a.ok && a.score >= kMixedMinQuadQuality && a.score > best_score) {
      best = name;
      best_score = a.score;
    }
  }
  if (!best.empty()) return best;
  return named_cap_scheme(model, registry, surface, "quad_dominant", "a wedge/hex mix", why);
}

}  // namespace

std::string cap_scheme(const geom::Model& model, const scheme::Registry& registry, int surface,
                       std::string& why, Elements elements) {
  if (elements == Elements::Wedge) return named_cap_scheme(model, registry, surface, "tri", "wedges", why);
  if (elements == Elements::Mixed) return mixed_cap_scheme(model, registry, surface, why);
  // The best-scoring quad scheme (scores are the scaled Jacobian each can
  // reach, so a corner map/submap would squash goes to pave); ties keep the
  // order map, submap, pave.
  std::string reasons;
  std::string best;
  double best_score = -1.0;
  for (const char* name : {"map", "submap", "pave"}) {
    const scheme::SurfaceScheme* s = registry.surface_scheme(name);
    if (!s) continue;
    const scheme::Applicability a = s->applicable(scheme::SurfaceView{model, surface, nullptr});
    if (a.ok && a.score > best_score) {
      best = name;
      best_score = a.score;
    }
    if (!a.ok) reasons += std::string(reasons.empty() ? "" : "; ") + name + ": " + a.why;
  }
  if (!best.empty()) return best;
  why = registry.surface_scheme("pave")
            ? "no surface scheme meshes cap surface " + std::to_string(surface) + " (" + reasons + ")"
            : "cap surface " + std::to_string(surface) + " needs pave, which is not available (" + reasons + ")";
  return {};
}

}  // namespace cooperage::cooper
