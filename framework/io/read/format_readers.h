// The per-format readers behind read_mesh_file() (read_mesh_file.h documents
// what each accepts). They assume the extension was checked by the caller.
#pragma once

#include "framework/io/read/read_mesh_file.h"

#include <string>

namespace cooperage::io::detail {

/// Exodus II (.exo .e .g) through libexodus.
MeshFile read_exodus(const std::string& path);
/// Gmsh .msh, 4.1 or 2.2 ASCII.
MeshFile read_msh(const std::string& path);
/// VTK XML .vtu, inline ascii or uncompressed base64 DataArrays.
MeshFile read_vtu(const std::string& path);

}  // namespace cooperage::io::detail
