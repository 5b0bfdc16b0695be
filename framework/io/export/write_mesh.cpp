#include "framework/io/export/write_mesh.h"

#include "framework/core/error.h"
#include "framework/io/export/exodus_writer.h"
#include "framework/io/export/inp_writer.h"
#include "framework/io/export/msh_writer.h"
#include "framework/io/export/vtu_writer.h"

#include <algorithm>
#include <cctype>

namespace cooperage::io {

void write_mesh(const std::string& path, const mesh::MeshDB& db, const geom::Model& model,
                const ExportOptions& options) {
  const size_t slash = path.find_last_of("/\\");
  const size_t dot = path.find_last_of('.');
  std::string ext;
  if (dot != std::string::npos && (slash == std::string::npos || dot > slash)) {
    ext = path.substr(dot + 1);
  }
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == "exo" || ext == "e" || ext == "g") return write_exodus(path, db, model, options);
  if (ext == "msh") return write_msh(path, db, model, options);
  if (ext == "vtu") return write_vtu(path, db, model, options);
  if (ext == "inp") return write_inp(path, db, model, options);
  throw MeshingError(ErrorCode::InvalidInput,
                     "cannot export '" + path + "': unknown extension '" +
                         (ext.empty() ? std::string() : "." + ext) +
                         "' (allowed: .exo, .e, .g (Exodus II), .msh (Gmsh 4.1), "
                         ".vtu (VTK), .inp (Abaqus))");
}

}  // namespace cooperage::io
