// The part of a mesh that a partial run writes (issue 16 item 5:
// --allow-partial writes the volumes that meshed, conformal among themselves).
#pragma once

#include "framework/geometry/model.h"
#include "framework/mesh/mesh_db.h"

#include <set>

namespace cooperage::pipeline {

/// A copy of `db` with only the elements of `volumes` (dim 3) and of the
/// surfaces that bound them, or, when `volumes` is empty, of `surfaces`
/// (surface meshes); nodes no kept element or curve uses are dropped and the
/// rest renumbered in their old order, so the copy is as deterministic as
/// the original. Curve chains are kept for the curves of kept surfaces.
mesh::MeshDB keep_entities(const mesh::MeshDB& db, const geom::Model& model,
                           const std::set<int>& volumes, const std::set<int>& surfaces);

}  // namespace cooperage::pipeline
