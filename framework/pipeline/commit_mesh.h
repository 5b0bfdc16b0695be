// Moves a scheme's EntityMesh into the MeshDB: new nodes get the entity as
// owner, local indices become global ones. The element arrays are handed
// over and renumbered in place (no whole-mesh copy: at 10 M hexes a copy
// took as long as the sweep, issue 20) and the node arrays are reserved
// once per entity.
#pragma once

#include "framework/mesh/mesh_db.h"
#include "framework/scheme/scheme.h"

namespace cooperage::pipeline {

/// Commits the quads/tris of surface `surface_id`, taking `local`'s node and
/// element arrays ([in,out]: they are left empty; pass a copy to keep them).
/// Throws MeshingError(Internal) for mismatched node arrays or out-of-range
/// local indices, found before any node or element is added.
void commit_surface(scheme::EntityMesh& local, int surface_id, mesh::MeshDB& db);

/// Commits the hexes/wedges of volume `volume_id` (and the surfaces the
/// volume scheme meshed itself), taking `local`'s arrays as commit_surface.
void commit_volume(scheme::EntityMesh& local, int volume_id, mesh::MeshDB& db);

}  // namespace cooperage::pipeline
