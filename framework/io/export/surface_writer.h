// Surface mesh formats (.obj .off .stl .ply) written through OpenMesh's IO.
#pragma once

#include "framework/geometry/model.h"
#include "framework/io/export/export_options.h"
#include "framework/mesh/mesh_db.h"

#include <string>

namespace cooperage::io {

/// True for the extensions write_surface_mesh() writes (.obj .off .stl .ply,
/// any case).
bool is_surface_format(const std::string& extension_without_dot);

/// Writes the surface elements of `db` as a polygon mesh through OpenMesh's
/// writers (om::to_openmesh): a surface-only mesh (--dim 2) gives every
/// meshed surface; a volume mesh its boundary, the surfaces bounding one
/// meshed volume, oriented outward (the surfaces between the volumes of an
/// assembly are left out: the formats have no volumes to separate). Quads
/// stay quads in .obj, .off and .ply; .stl holds triangles, so each quad is
/// split along its shorter diagonal. Coordinates are written in single
/// precision (OpenMesh's writers; binary STL is single precision by
/// definition). options.binary: binary .stl and .ply (.obj and .off are
/// text). Blocks and side sets are not kept (the formats have no groups).
/// Written atomically (see write_mesh()).
/// @throws MeshingError(InvalidInput) when the mesh has no surface elements
///         to write (a volume mesh without its surfaces), or as write_mesh.
void write_surface_mesh(const std::string& path, const mesh::MeshDB& db, const geom::Model& model,
                        const ExportOptions& options = {});

}  // namespace cooperage::io
