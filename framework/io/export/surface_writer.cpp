#include "framework/io/export/surface_writer.h"

#include "framework/core/error.h"
#include "framework/core/text.h"
#include "framework/io/export/export_common.h"
#include "framework/openmesh/surface_mesh.h"

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/System/omstream.hh>

#include <algorithm>
#include <cctype>
#include <limits>
#include <ostream>
#include <sstream>

namespace cooperage::io {
namespace {

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string extension_of(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  const size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return {};
  return lower(path.substr(dot + 1));
}

/// Splits every quad along its shorter diagonal (STL holds triangles only).
void split_quads(om::SurfaceMesh& m) {
  std::vector<om::SurfaceMesh::FaceHandle> quads;
  for (const auto f : m.faces())
    if (m.valence(f) == 4) quads.push_back(f);
  for (const auto f : quads) {
    // h0: v0->v1, h1: v1->v2, h2: v2->v3, h3: v3->v0.
    const auto h0 = m.halfedge_handle(f);
    const auto h1 = m.next_halfedge_handle(h0);
    const auto h2 = m.next_halfedge_handle(h1);
    const auto h3 = m.next_halfedge_handle(h2);
    const auto v0 = m.from_vertex_handle(h0), v1 = m.from_vertex_handle(h1);
    const auto v2 = m.from_vertex_handle(h2), v3 = m.from_vertex_handle(h3);
    // insert_edge(a, b) joins a's target to b's source, splitting the face.
    if ((m.point(v0) - m.point(v2)).sqrnorm() <= (m.point(v1) - m.point(v3)).sqrnorm())
      m.insert_edge(h3, h2);  // v0 -- v2
    else
      m.insert_edge(h0, h3);  // v1 -- v3
  }
}

/// OpenMesh's log lines ("[OBJWriter] : write file") off while writing.
class QuietOpenMesh {
 public:
  QuietOpenMesh() : log_(omlog().is_enabled()), out_(omout().is_enabled()) {
    omlog().disable();
    omout().disable();
  }
  ~QuietOpenMesh() {
    if (log_) omlog().enable();
    if (out_) omout().enable();
  }
  QuietOpenMesh(const QuietOpenMesh&) = delete;
  QuietOpenMesh& operator=(const QuietOpenMesh&) = delete;

 private:
  bool log_, out_;
};

}  // namespace

bool is_surface_format(const std::string& extension_without_dot) {
  const std::string e = lower(extension_without_dot);
  return e == "obj" || e == "off" || e == "stl" || e == "ply";
}

void write_surface_mesh(const std::string& path, const mesh::MeshDB& db, const geom::Model& model,
                        const ExportOptions& options) {
  detail::validate_mesh(db, model);
  const std::string ext = extension_of(path);
  const bool volume_mesh = detail::has_volume_elements(db);
  om::SurfaceMesh m = om::to_openmesh(
      db, model, volume_mesh ? om::SurfaceSelection::Boundary : om::SurfaceSelection::All);
  if (m.n_faces() == 0)
    throw MeshingError(ErrorCode::InvalidInput,
                       "cannot export '" + clip_path(path) + "': the mesh has no " +
                           (volume_mesh ? "boundary surface elements" : "surface elements") +
                           " for a surface format");
  if (ext == "stl") split_quads(m);
  OpenMesh::IO::Options opt = OpenMesh::IO::Options::Default;
  if (options.binary && (ext == "stl" || ext == "ply")) opt += OpenMesh::IO::Options::Binary;
  if (options.binary && ext == "ply") opt += OpenMesh::IO::Options::LSB;
  const auto failed = [&] {
    return MeshingError(ErrorCode::FileNotFound, "cannot write '" + clip_path(path) +
                                                     "' (OpenMesh's ." + ext + " writer failed)");
  };
  const int digits = std::numeric_limits<float>::max_digits10;
  const QuietOpenMesh quiet;
  if (ext == "stl" && !options.binary) {
    // OpenMesh ends every facet's vertices with a blank line, which meshio's
    // STL reader (5.0) cannot parse; the blank lines carry nothing.
    std::ostringstream text;
    if (!OpenMesh::IO::write_mesh(m, text, "." + ext, opt, digits)) throw failed();
    std::string body = text.str();
    std::string::size_type at = 0;
    while ((at = body.find("\n\n", at)) != std::string::npos) body.erase(at, 1);
    detail::write_text_atomically(path, [&](std::ostream& os) { os << body; });
    return;
  }
  detail::write_text_atomically(path, [&](std::ostream& os) {
    if (!OpenMesh::IO::write_mesh(m, os, "." + ext, opt, digits)) throw failed();
  });
}

}  // namespace cooperage::io
