// Journal meshing settings checked against the model they apply to: ids
// that exist, and settings whose behaviour is not in this release.
#pragma once

#include "framework/geometry/model.h"
#include "framework/io/job.h"

namespace cooperage::pipeline {

/// Throws MeshingError naming the journal line: InvalidInput for an id the
/// model does not have, NotSupported for settings a later release carries out
/// (wedge/mixed elements).
void check_settings(const geom::Model& model, const io::MeshSettings& settings);

}  // namespace cooperage::pipeline
