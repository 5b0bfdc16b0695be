// write_mesh: export a MeshDB to the format named by the file extension.
#pragma once

#include "framework/geometry/model.h"
#include "framework/io/export/export_options.h"
#include "framework/mesh/mesh_db.h"

#include <string>

namespace cooperage::io {

/// Writes `db` to `path`, choosing the format by the (case-insensitive)
/// extension: .exo/.e/.g Exodus II (exodus_writer.h), .msh Gmsh 4.1 ASCII
/// (msh_writer.h), .vtu VTK XML unstructured grid (vtu_writer.h), .inp Abaqus
/// (inp_writer.h).
///
/// Every writer validates the mesh first (node indices in range, meshed ids
/// in the model; MeshingError(InvalidInput) otherwise), writes
/// "<path>.tmp-<pid>" in the same directory and renames it to `path` on
/// success. On failure the temporary file is removed and MeshingError is
/// thrown (FileNotFound for an unwritable path), so an existing file at
/// `path` is never replaced by a partial one.
/// @param[in] path    output file
/// @param[in] db      the mesh (0-based node indices)
/// @param[in] model   the model the mesh belongs to (ids, names, topology)
/// @param[in] options see ExportOptions
/// @throws MeshingError(InvalidInput) for an unknown extension (the message
///         lists the allowed ones) or an invalid mesh.
void write_mesh(const std::string& path, const mesh::MeshDB& db, const geom::Model& model,
                const ExportOptions& options = {});

}  // namespace cooperage::io
