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

/// Asks the registry for the schemes serving the cap role of the element
/// kind (scheme::Role), so plug-in schemes compete: hex mode the best-scoring
/// quad-cap scheme (map, submap, pave; ties in registration order); wedge
/// mode the best tri-cap scheme ("tri"); mixed mode the best mixed-cap one,
/// an all-quad scheme (map, submap) only where it reaches
/// kMixedMinQuadQuality, else "quad_dominant". A scheme the journal pins on
/// the cap (<surface id scheme>) wins when it serves the role. "" with
/// `why` when none applies.
/// `settings` reach the candidates' applicable(); null: defaults.
std::string cap_scheme(const geom::Model& model, const scheme::Registry& registry, int surface,
                       std::string& why, Elements elements = Elements::Hex,
                       const scheme::Settings* settings = nullptr);

}  // namespace cooperage::cooper
