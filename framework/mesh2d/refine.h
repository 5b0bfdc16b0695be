// Delaunay refinement of a constrained triangulation without splitting its
// constraints (see triangulate.h). Internal to framework/mesh2d.
#pragma once

#include <cstddef>

#include "framework/mesh2d/cdt.h"
#include "framework/mesh2d/triangulate.h"

namespace cooperage::mesh2d::detail {

struct RefineStats {
  std::size_t rejected = 0;
  bool capped = false;
};

/// Inserts circumcentres (or segment apices) of skinny and oversized inside
/// triangles until none is left that can be improved, or the point count
/// reaches max_points.
RefineStats refine(Cdt& cdt, const RefineOptions& options, std::size_t max_points);

}  // namespace cooperage::mesh2d::detail
