// The one loop walker: a surface's boundary loops as rings of mesh nodes,
// from its meshed curves (each use's chain, reversed for a Reversed use,
// junction nodes once, the closing node not repeated; a seam curve used
// twice contributes its nodes twice).
#pragma once

#include "framework/geometry/model.h"
#include "framework/mesh/mesh_db.h"

#include <vector>

namespace cooperage::mesh {

/// The node rings of `surface_id`'s loops, in loop order (the face on the
/// left seen against its natural normal), outer loop first.
/// Throws MeshingError(MeshingFailed, surface) when a curve is not meshed,
/// has no interval, or does not continue its loop, or a loop does not close.
std::vector<std::vector<int>> surface_loop_nodes(const geom::Model& model, int surface_id,
                                                 const MeshDB& db);

/// The curve ids of a loop as "3+7+12" (for messages).
std::string loop_curve_list(const geom::Loop& loop);

}  // namespace cooperage::mesh
