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
/// Volume meshes (any hex or wedge): one element block per element type per
/// volume. Block id scheme: the HEX8 block of volume v has id v; the WEDGE6
/// block has id v when the volume has no hexes, otherwise v + W, where W is
/// the smallest power of ten >= 1000 that exceeds every volume id of the
/// model (so 1001 for volume 1 of a small model). Block names are the volume
/// names (volume_label(): sanitised, or "V<id>"); a second (wedge) block is
/// named "<name>_wedge". Elements are numbered block after block, in
/// ascending volume id, hex block before wedge block.
/// One side set per meshed surface that bounds a meshed volume, id = surface
/// id, name "surface_<id>": for each surface quad/tri, the element of the
/// surface's first volume with that face and its Exodus side number (HEX8:
/// 1 = 1,2,6,5; 2 = 2,3,7,6; 3 = 3,4,8,7; 4 = 1,5,8,4; 5 = 1,4,3,2;
/// 6 = 5,6,7,8; WEDGE6: 1 = 1,2,5,4; 2 = 2,3,6,5; 3 = 1,4,6,3; 4 = 1,3,2;
/// 5 = 4,5,6). A surface element that is no element face throws
/// MeshingError(InvalidInput).
///
/// Surface-only meshes (no hex/wedge): QUAD4 / TRI3 blocks per surface with
/// the same id scheme (surface ids), names "surface_<id>", and no side sets.
///
/// Both: one node set per meshed surface, id = surface id, its nodes
/// ascending. Names longer than 32 characters raise the file's maximum name
/// length. Written atomically (see write_mesh()).
void write_exodus(const std::string& path, const mesh::MeshDB& db, const geom::Model& model,
                  const ExportOptions& options = {});

}  // namespace cooperage::io
