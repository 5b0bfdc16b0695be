// Options shared by the mesh exporters (write_mesh.h).
#pragma once

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
};

}  // namespace cooperage::io
