#include "framework/pipeline/commit_mesh.h"

#include "framework/core/error.h"

namespace cooperage::pipeline {
namespace {

// Global index of every local node, adding the new ones to db.
std::vector<int> globalise(const scheme::EntityMesh& local, mesh::NodeOwner owner,
                           mesh::MeshDB& db) {
  if (local.global.size() != local.coords.size()) {
    throw MeshingError(ErrorCode::Internal, EntityRef{owner.dim, owner.id},
                       "scheme returned mismatched node arrays");
  }
  std::vector<int> map(local.global.size());
  for (size_t k = 0; k < local.global.size(); ++k) {
    const int g = local.global[k];
    if (g >= static_cast<int>(db.node_count())) {
      throw MeshingError(ErrorCode::Internal, EntityRef{owner.dim, owner.id},
                         "scheme referenced an unknown node");
    }
    const mesh::NodeOwner own =
        k < local.owners.size() && local.owners[k].dim >= 0 ? local.owners[k] : owner;
    map[k] = g >= 0 ? g : db.add_node(local.coords[k], own);
  }
  return map;
}

template <size_t N>
std::vector<std::array<int, N>> remap(const std::vector<std::array<int, N>>& elements,
                                      const std::vector<int>& map, EntityRef entity) {
  std::vector<std::array<int, N>> out;
  out.reserve(elements.size());
  for (const auto& e : elements) {
    std::array<int, N> g{};
    for (size_t i = 0; i < N; ++i) {
      if (e[i] < 0 || e[i] >= static_cast<int>(map.size())) {
        throw MeshingError(ErrorCode::Internal, entity, "element with a bad local node index");
      }
      g[i] = map[static_cast<size_t>(e[i])];
    }
    out.push_back(g);
  }
  return out;
}

}  // namespace

void commit_surface(const scheme::EntityMesh& local, int surface_id, mesh::MeshDB& db) {
  const auto map = globalise(local, {2, surface_id}, db);
  mesh::SurfaceMeshData& s = db.mutable_surface(surface_id);
  s.quads = remap(local.quads, map, EntityRef::surface(surface_id));
  s.tris = remap(local.tris, map, EntityRef::surface(surface_id));
}

void commit_volume(const scheme::EntityMesh& local, int volume_id, mesh::MeshDB& db) {
  const auto map = globalise(local, {3, volume_id}, db);
  mesh::VolumeMeshData& v = db.mutable_volume(volume_id);
  v.hexes = remap(local.hexes, map, EntityRef::volume(volume_id));
  v.wedges = remap(local.wedges, map, EntityRef::volume(volume_id));
  for (const auto& [sid, quads] : local.surface_quads) {
    db.mutable_surface(sid).quads = remap(quads, map, EntityRef::surface(sid));
  }
  for (const auto& [sid, tris] : local.surface_tris) {
    db.mutable_surface(sid).tris = remap(tris, map, EntityRef::surface(sid));
  }
}

}  // namespace cooperage::pipeline
