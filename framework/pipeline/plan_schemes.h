// The scheme plan before the selector exists: the journal's pins, else the
// roles a volume scheme imposes, else the first applicable registered scheme.
#pragma once

#include "framework/geometry/model.h"
#include "framework/io/job.h"
#include "framework/pipeline/scheme_plan.h"
#include "framework/scheme/registry.h"

namespace cooperage::pipeline {

/// Plans every volume (when dim == 3) and every surface. Throws
/// MeshingError(NotApplicable) naming the entity and every scheme's reason
/// when nothing applies, and MeshingError(InvalidInput) for a pinned scheme
/// that is unknown or contradicts a volume scheme's role.
SchemePlan plan_schemes(const geom::Model& model, const scheme::Registry& registry,
                        const io::MeshSettings& settings, int dim);

}  // namespace cooperage::pipeline
