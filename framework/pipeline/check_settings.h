// Journal meshing settings checked against the model they apply to: ids
// that exist, and combinations that cannot work (wedge/mixed elements from a
// volume map).
#pragma once

#include "framework/geometry/model.h"
#include "framework/io/job.h"

namespace cooperage::pipeline {

/// Throws MeshingError naming the journal line: InvalidInput for an id the
/// model does not have, or for elements="wedge" / "mixed" with scheme="map".
void check_settings(const geom::Model& model, const io::MeshSettings& settings);

}  // namespace cooperage::pipeline
