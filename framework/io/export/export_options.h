// Options shared by the mesh exporters (write_mesh.h).
#pragma once

#include "framework/io/job.h"

#include <string>

namespace cooperage::io {

struct ExportOptions {
  /// VTK .vtu only: also write the surface elements (quads/tris) next to the
  /// volume elements. When false, a mesh with volume elements gets only
  /// those, and a surface-only mesh gets its surface elements.
  bool include_surfaces = false;
  /// Title / heading written where the format has one (Exodus title is cut
  /// to 80 characters by the format).
  std::string title = "Cooperage mesh";
  /// .vtu and .msh only: binary encoding (.vtu: raw little-endian arrays in
  /// one appended block; .msh: Gmsh 4.1 binary). Both are read by ParaView,
  /// Gmsh and meshio; ASCII (the default) is also read by `cooperage quality`.
  bool binary = false;
  /// Exodus only: netCDF-4 (HDF5) container instead of classic 64-bit-offset
  /// netCDF. Classic is the default: as fast once the header has room for
  /// every definition (bench/RESULTS.md, issue 20) and read by every tool.
  bool exodus_netcdf4 = false;
  /// The journal's <block>, <sideset>, <nodeset> (.exo, .msh, .inp; see
  /// mesh_groups.h). Each empty list keeps its default.
  GroupSettings groups;
  /// A named group none of whose entities has elements is an error, except
  /// with this (--allow-partial: its volumes were refused), when it is left out.
  bool skip_empty_groups = false;
};

}  // namespace cooperage::io
