// From sizes and the scheme plan to the global interval problem (docs/design.md
// "Interval assignment"): one goal per curve, every planned scheme's
// constraints.
#pragma once

#include "framework/geometry/model.h"
#include "framework/intervals/interval_problem.h"
#include "framework/io/job.h"
#include "framework/pipeline/scheme_plan.h"
#include "framework/scheme/registry.h"

namespace cooperage::pipeline {

/// Target element size of a curve: its own size, else the smallest size set
/// on a surface or volume it bounds, else the global size. Throws
/// MeshingError(InvalidInput) naming the curve when no size applies.
double curve_target_size(const geom::Model& model, const io::MeshSettings& settings, int curve_id);

/// Goals for every curve (a user's interval count is hard unless marked
/// soft) and the constraints of every planned surface and volume scheme.
intervals::IntervalProblem build_interval_problem(const geom::Model& model,
                                                  const scheme::Registry& registry,
                                                  const SchemePlan& plan,
                                                  const io::MeshSettings& settings);

}  // namespace cooperage::pipeline
