// The geometry stage with the automatic decomposition (issue 17): a job's
// geometry operations, then, when <mesh decompose="auto"> (the default), the
// volumes no volume scheme applies to are cut into pieces one does
// (framework/decompose/decompose.h), and everything is imprinted and merged.
#pragma once

#include "framework/decompose/decompose.h"
#include "framework/geometry/model.h"
#include "framework/io/job.h"
#include "framework/pipeline/planner.h"
#include "framework/scheme/registry.h"

namespace cooperage::pipeline {

struct DecomposedGeometry {
  geom::Model model;
  decompose::Report decomposition;  ///< empty when nothing was cut
  double geometry_seconds = 0.0;    ///< the journal's operations and the first model
  /// The job's global size with "D/N" resolved against the model built
  /// (before any cut); the job's own size otherwise.
  std::optional<double> size;
};

/// build_geometry(job), the global size resolved (resolve_relative_size),
/// then the decomposition when `dim` is 3 and
/// job.mesh->decompose is Auto. A cut piece is checked with `planner` (its
/// shared faces' schemes agree, its intervals are feasible).
/// Entity ids in the journal's settings (and its blocks, side sets and node
/// sets) refer to the model before any cut,
/// so a job that sets entities by id is not decomposed: a volume no scheme
/// applies to is then refused naming the setting (unless the volume's own
/// scheme is pinned, when the planner's refusal of the pin stands).
/// The search judges its cuts on `threads` threads (0: the job's <mesh
/// threads>); the result is the same for any number.
/// @throws MeshingError as build_geometry() and decompose::decompose() do.
DecomposedGeometry build_decomposed_geometry(const io::Job& job, const scheme::Registry& registry,
                                             const Planner& planner, int dim = 3, int threads = 0);

/// The element size the decomposition measures thickness against: the
/// settings' global size, else 1/40 of the model's bounding-box diagonal.
double decomposition_size(const io::MeshSettings& settings, const geom::Model& model);

}  // namespace cooperage::pipeline
