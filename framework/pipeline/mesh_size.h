// How big will the mesh be? An estimate from interval counts, made before
// any node exists, so that a tiny size or a huge interval count is refused
// with a number instead of running until the machine gives out (issue 21
// item 2: a size of 1e-3 on a 40 mm part ran until killed).
#pragma once

#include "framework/core/error.h"
#include "framework/geometry/model.h"
#include "framework/io/job.h"

#include <map>
#include <optional>
#include <string>

namespace cooperage::pipeline {

/// The default of MeshOptions::max_elements / <mesh max_elements>.
inline constexpr double kDefaultMaxElements = 200e6;
/// The largest limit accepted: node and element indices are 32-bit.
inline constexpr double kMaxElementsCeiling = 1e9;

struct MeshSizeEstimate {
  double elements = 0;  ///< volume elements (dim 3) plus surface elements
  double nodes = 0;
  double bytes = 0;   ///< memory the mesh and its working copies take, about
  EntityRef largest;  ///< the entity expected to have the most elements
  double largest_elements = 0;
};

/// Interval goals per curve from the settings alone (length / target size,
/// or the user's count), before the interval assignment. Throws
/// MeshingError(InvalidInput) when a curve has no size (as the assignment would).
std::map<int, double> interval_goals(const geom::Model& model, const io::MeshSettings& settings);

/// Estimates the mesh from an interval count per curve: a surface gets its
/// area over the square of its boundary's mean edge length in quads; a volume
/// (dim 3) its volume over the cube of its curves' mean edge length in hexes.
/// Exact for a mapped rectangle or brick with uniform edges; an estimate
/// (within a small factor) otherwise.
MeshSizeEstimate estimate_mesh_size(const geom::Model& model,
                                    const std::map<int, double>& intervals, int dim);

/// Throws MeshingError(InvalidInput) when the estimate exceeds `limit`
/// elements: "the mesh would have about 6.4e+13 elements (volume 1 about
/// 6.4e+13), about 1.6e+04 GB; the limit is 2e+08 (--max-elements or <mesh
/// max_elements>): use a larger element size or fewer intervals".
void check_mesh_size(const MeshSizeEstimate& estimate, double limit);

/// The element limit a run applies: `override` (--max-elements), else
/// <mesh max_elements>, else the default; at most the ceiling.
double element_limit(const io::MeshSettings& settings, std::optional<double> override = {});

/// The same check from the settings alone, for a plan (`cooperage plan`,
/// cooperage.plan()): the limit is <mesh max_elements> or the default, and
/// settings without a size are not checked. A size in the wrong unit made
/// a plan run for seconds and show what `mesh` refuses at once.
void check_planned_size(const geom::Model& model, const io::MeshSettings& settings, int dim);

}  // namespace cooperage::pipeline
