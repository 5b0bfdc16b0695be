// Exodus II export through the Exodus C library (libexodusII).
#pragma once

#include "framework/geometry/model.h"
#include "framework/io/export/export_options.h"
#include "framework/mesh/mesh_db.h"

#include <string>

namespace cooperage::io {

/// Writes an Exodus II file (num_dim 3, double coordinates, 1-based node and
/// element numbers).
///
/// Blocks, side sets and node sets are those of detail::mesh_groups()
/// (mesh_groups.h): the journal's <block>, <sideset>, <nodeset>, with
/// their ids and names, or the defaults below.
///
/// Volume meshes (any hex or wedge): by default one element block per
/// volume and element type. A group's HEX8 elements form a block with the
/// group's id; its WEDGE elements (element type "WEDGE", which meshio and
/// SEACAS read) one with the same id when the group has no hexes, otherwise
/// id + W, where W is the smallest power of ten >= 1000 that exceeds every
/// block id (so 1001 for block 1 of a small model), named "<name>_wedge".
/// Default block ids are the volume ids, names the volume names
/// (volume_label(): sanitised, or "V<id>"). Elements are numbered block
/// after block, hex block before wedge block, each block's volumes in
/// ascending id.
/// Side sets: by default one per meshed surface that bounds a meshed volume,
/// id = surface id, name "surface_<id>": for each surface quad/tri, the
/// element of the surface's first volume with that face and its Exodus side
/// number (HEX8: 1 = 1,2,6,5; 2 = 2,3,7,6; 3 = 3,4,8,7; 4 = 1,5,8,4;
/// 5 = 1,4,3,2; 6 = 5,6,7,8; WEDGE: 1 = 1,2,5,4; 2 = 2,3,6,5; 3 = 1,4,6,3;
/// 4 = 1,3,2; 5 = 4,5,6). A surface element that is no element face throws
/// MeshingError(InvalidInput).
///
/// Surface-only meshes (no hex/wedge): QUAD4 / TRI3 blocks (by default per
/// surface, ids = surface ids, names "surface_<id>", a second TRI3 block
/// "<name>_tri"), and no side sets.
///
/// Both: node sets, by default one per meshed surface, id = surface id, its
/// nodes ascending. Names longer than 32 characters raise the file's
/// maximum name length. Written atomically (see write_mesh()).
void write_exodus(const std::string& path, const mesh::MeshDB& db, const geom::Model& model,
                  const ExportOptions& options = {});

/// Loads the Exodus II library now (it is loaded on first use,
/// exodus_lazy.h). Throws MeshingError(Internal) when it cannot be loaded.
void load_exodus_library();

}  // namespace cooperage::io
