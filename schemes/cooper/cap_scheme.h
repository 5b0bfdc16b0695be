// The surface scheme that meshes a cap beforehand (Blacker 1996, sec. 6.1:
// "the paving algorithm is currently used"; map and submap where they
// reach better elements), per element kind (elements.h). Asks the
// registry's applicable(), never meshes.
#pragma once

#include "framework/geometry/model.h"
#include "framework/scheme/registry.h"
#include "schemes/cooper/elements.h"

#include <string>

namespace cooperage::cooper {

/// Hex mode: the best-scoring of map, submap, pave (ties in that order);
/// wedge mode "tri"; mixed mode map / submap where they reach
/// kMixedMinQuadQuality, else "quad_dominant". "" with `why` when none applies.
std::string cap_scheme(const geom::Model& model, const scheme::Registry& registry, int surface,
                       std::string& why, Elements elements = Elements::Hex);

}  // namespace cooperage::cooper
