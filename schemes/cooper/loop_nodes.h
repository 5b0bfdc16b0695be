// Boundary node loops of a surface from its meshed curves (the cap loops
// whose nodes start the ribs, Blacker 1996, sec. 4).
#pragma once

#include "framework/geometry/model.h"
#include "framework/mesh/mesh_db.h"

#include <array>
#include <vector>

namespace cooperage::cooper {

/// Node loops of `surface_id`, in loop order (face on the left seen against
/// its natural normal), first node not repeated. Throws MeshingError naming
/// `volume_id` when a curve is not meshed or a loop is not closed.
std::vector<std::vector<int>> loop_nodes(const geom::Model& model, const mesh::MeshDB& db,
                                         int volume_id, int surface_id);

/// The seams of a loop: curves it uses twice (a periodic face), ascending.
std::vector<int> seam_curves(const geom::Loop& loop);

/// The seam of a surface when its loops hold exactly one, else 0.
int single_seam(const geom::Surface& surface);

/// Boundary loops of a consistently oriented quad set (an upper cap made of
/// a real cap and the virtual caps beside it, sec. 4 Fig. 8d): the edges used
/// by one quad, chained in quad order, each loop starting at its smallest
/// node. Empty when the boundary is not a set of simple loops.
std::vector<std::vector<int>> quad_boundary_loops(const std::vector<std::array<int, 4>>& quads);

/// Boundary loops of the union of regions bounded by node loops that share
/// edges (a real cap's loops and the rims of the flush virtual caps beside
/// it, sec. 4 Fig. 8d, when the real cap has no mesh yet): the edges of one
/// loop only, chained, each merged loop oriented like the `reference` loop it
/// shares an edge with. Empty when the boundary is not a set of simple loops.
std::vector<std::vector<int>> merge_loops(const std::vector<std::vector<int>>& reference,
                                          const std::vector<std::vector<int>>& others);

}  // namespace cooperage::cooper
