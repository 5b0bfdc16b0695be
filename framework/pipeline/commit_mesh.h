// Copies a scheme's EntityMesh into the MeshDB: new nodes get the entity as
// owner, local indices become global ones.
#pragma once

#include "framework/mesh/mesh_db.h"
#include "framework/scheme/scheme.h"

namespace cooperage::pipeline {

/// Commits the quads/tris of surface `surface_id`. Throws
/// MeshingError(Internal) for out-of-range local indices.
void commit_surface(const scheme::EntityMesh& local, int surface_id, mesh::MeshDB& db);

/// Commits the hexes/wedges of volume `volume_id`.
void commit_volume(const scheme::EntityMesh& local, int volume_id, mesh::MeshDB& db);

}  // namespace cooperage::pipeline
