// The a-priori analysis of a submap face, from angles and topology alone:
// vertex types per loop (with repair and the journal's pins), a direction
// per curve use (holes rotated to match the outer loop's lattice), and the
// interval constraints they imply. Shared by applicable(), constrain() and
// mesh(); it never meshes.
#pragma once

#include <string>
#include <vector>

#include "framework/geometry/model.h"
#include "framework/intervals/interval_problem.h"
#include "framework/io/job.h"
#include "framework/scheme/vertex_angles.h"
#include "schemes/submap/classify.h"

namespace cooperage::submap {

struct LoopPlan {
  std::vector<geom::CurveUse> uses;
  std::vector<scheme::LoopCorner> corners;  ///< corner k before uses[k]
  LoopTypes types;
  std::vector<int> directions;  ///< per use (directions.h), in the face's lattice
};

struct SubmapPlan {
  bool ok = false;
  double score = 0.0;
  std::string why;              ///< "surface 7: vertex 17 at 35 degrees cannot be ..."
  std::vector<LoopPlan> loops;  ///< outer loop first
};

/// Analyses a surface for submapping. Not ok when a vertex has no type, a
/// loop sum cannot be repaired, or a vertex ends up REVERSAL (a slit).
/// \param[in] pins  hard vertex types; those of other surfaces are ignored
SubmapPlan plan_submap(const geom::Model& model, int surface_id,
                       const std::vector<io::VertexTypeSetting>& pins,
                       const ClassifyOptions& options = {});

/// The interval constraints of a planned surface (Whiteley et al. 1996;
/// MeshKit EdgeDiscretization): per loop and axis, sum over the + curves =
/// sum over the - curves; per hole and axis, the outer loop's + sum exceeds
/// the hole's + sum by at least 2, so the hole fits strictly inside the
/// outer lattice with a row of cells around it.
void add_submap_constraints(int surface_id, const SubmapPlan& plan,
                            intervals::IntervalProblem& problem);

}  // namespace cooperage::submap
