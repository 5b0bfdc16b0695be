#include "framework/io/read/read_mesh_file.h"
#include "framework/core/text.h"

#include "framework/core/error.h"
#include "framework/io/read/format_readers.h"

#include <cctype>
#include <filesystem>

namespace cooperage::io {

MeshFile read_mesh_file(const std::string& path) {
  const std::string ext = lower_extension(path);
  if (ext == ".exo" || ext == ".e" || ext == ".g") return detail::read_exodus(path);
  if (ext == ".msh") return detail::read_msh(path);
  if (ext == ".vtu") return detail::read_vtu(path);
  throw MeshingError(ErrorCode::InvalidInput, path + ": unknown mesh file extension \"" + ext +
                                                  "\" (allowed: .exo .e .g .msh .vtu)");
}

}  // namespace cooperage::io
