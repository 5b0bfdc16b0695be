#include "framework/openmesh/surface_mesh.h"

#include "framework/core/error.h"

#include <OpenMesh/Core/Utils/Property.hh>

#include <algorithm>
#include <map>

namespace cooperage::om {
namespace {

bool has_elements(const mesh::MeshDB& db, int volume) {
  return db.volume_meshed(volume) && db.volume(volume).size() > 0;
}

/// The surfaces to take, each with whether its faces are to be flipped.
std::vector<std::pair<int, bool>> selected(const mesh::MeshDB& db, const geom::Model& model,
                                           SurfaceSelection which) {
  std::vector<std::pair<int, bool>> out;
  for (const auto& [id, s] : db.surfaces()) {
    if (s.size() == 0) continue;
    if (which == SurfaceSelection::All) {
      out.emplace_back(id, false);
      continue;
    }
    const auto& vols = model.surface(id).volumes;
    int meshed = 0, first = -1;
    for (size_t k = 0; k < vols.size(); ++k) {
      if (!has_elements(db, vols[k])) continue;
      ++meshed;
      if (first < 0) first = static_cast<int>(k);
    }
    // Surface elements face out of the surface's first volume (mesh_db.h).
    if (meshed == 1) out.emplace_back(id, first != 0);
  }
  return out;
}

}  // namespace

SurfaceMesh to_openmesh(const mesh::MeshDB& db, const geom::Model& model, SurfaceSelection which) {
  SurfaceMesh m;
  OpenMesh::VPropHandleT<int> node_of;
  OpenMesh::FPropHandleT<int> surface_of;
  m.add_property(node_of, kNodeProperty);
  m.add_property(surface_of, kSurfaceProperty);
  // Not persistent: the writers would put them into .ply files, whose
  // readers (meshio) refuse the ':' in their names.

  const auto surfaces = selected(db, model, which);
  std::vector<int> used;
  for (const auto& [id, flip] : surfaces) {
    const auto& s = db.surface(id);
    for (const auto& q : s.quads) used.insert(used.end(), q.begin(), q.end());
    for (const auto& t : s.tris) used.insert(used.end(), t.begin(), t.end());
  }
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  std::map<int, SurfaceMesh::VertexHandle> vertex;
  for (int n : used) {
    const auto& x = db.node(n);
    const auto v = m.add_vertex(SurfaceMesh::Point(x.x(), x.y(), x.z()));
    m.property(node_of, v) = n;
    vertex.emplace(n, v);
  }
  std::vector<SurfaceMesh::VertexHandle> face;
  auto add = [&](const int* nodes, int count, bool flip, int surface) {
    face.clear();
    for (int k = 0; k < count; ++k) face.push_back(vertex.at(nodes[flip ? count - 1 - k : k]));
    auto f = m.add_face(face);
    if (!f.is_valid()) {
      // Not a manifold, consistently oriented addition: a face of its own.
      for (auto& v : face) {
        const int n = m.property(node_of, v);
        v = m.add_vertex(m.point(v));
        m.property(node_of, v) = n;
      }
      f = m.add_face(face);
    }
    m.property(surface_of, f) = surface;
  };
  for (const auto& [id, flip] : surfaces) {
    const auto& s = db.surface(id);
    for (const auto& q : s.quads) add(q.data(), 4, flip, id);
    for (const auto& t : s.tris) add(t.data(), 3, flip, id);
  }
  return m;
}

mesh::MeshDB from_openmesh(const SurfaceMesh& m, int surface_id) {
  OpenMesh::FPropHandleT<int> surface_of;
  const bool has_surface = m.get_property_handle(surface_of, kSurfaceProperty);
  mesh::MeshDB db;
  db.reserve_nodes(m.n_vertices());
  for (const auto v : m.vertices()) {
    const auto& p = m.point(v);
    db.add_node(mesh::Vec3(p[0], p[1], p[2]), mesh::NodeOwner{2, surface_id});
  }
  for (const auto f : m.faces()) {
    std::vector<int> nodes;
    for (const auto v : m.fv_range(f)) nodes.push_back(v.idx());
    const int sid = has_surface ? m.property(surface_of, f) : surface_id;
    auto& s = db.mutable_surface(sid);
    if (nodes.size() == 4) {
      s.quads.push_back({nodes[0], nodes[1], nodes[2], nodes[3]});
    } else if (nodes.size() == 3) {
      s.tris.push_back({nodes[0], nodes[1], nodes[2]});
    } else {
      throw MeshingError(ErrorCode::InvalidInput,
                         "OpenMesh face " + std::to_string(f.idx()) + " has " +
                             std::to_string(nodes.size()) +
                             " vertices; a Cooperage surface mesh has quads and triangles only");
    }
  }
  return db;
}

}  // namespace cooperage::om
