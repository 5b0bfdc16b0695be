// The planning stage as a function, so the pipeline never depends on the
// selector (which provides it: selector::planner()).
#pragma once

#include "framework/geometry/model.h"
#include "framework/io/job.h"
#include "framework/pipeline/scheme_plan.h"
#include "framework/scheme/registry.h"

#include <functional>

namespace cooperage::pipeline {

/// A scheme for every volume (dim 3) and surface; throws MeshingError when
/// an entity has none, or the choices conflict, or intervals are infeasible.
using Planner = std::function<SchemePlan(const geom::Model&, const scheme::Registry&,
                                         const io::MeshSettings&, int dim)>;

}  // namespace cooperage::pipeline
