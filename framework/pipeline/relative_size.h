// "--size D/40": a size given as a fraction of the model's bounding-box
// diagonal becomes a length once the model is built (after imports,
// booleans and the imprint), before anything reads the size.
#pragma once

#include "framework/geometry/model.h"
#include "framework/io/job.h"

namespace cooperage::pipeline {

/// settings.size = the diagonal of the box of all of `model`'s entities
/// over settings.size_divisor, and the divisor cleared; nothing when no
/// divisor is set.
/// @throws MeshingError(InvalidInput) when the model has no extent.
void resolve_relative_size(io::MeshSettings& settings, const geom::Model& model);

}  // namespace cooperage::pipeline
