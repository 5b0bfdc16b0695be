#include "framework/pipeline/commit_mesh.h"

#include "framework/core/error.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <utility>

namespace cooperage::pipeline {
namespace {

// Global index of every local node, replacing local.global (so no second
// index array), the new nodes moved into db in local order: local.coords is
// compacted in place and handed to MeshDB::append_nodes, which keeps its
// storage when it can (the node array is then never held twice).
const std::vector<int>& globalise(scheme::EntityMesh& local, mesh::NodeOwner owner,
                                  mesh::MeshDB& db) {
  if (local.global.size() != local.coords.size()) {
    throw MeshingError(ErrorCode::Internal, EntityRef{owner.dim, owner.id},
                       "scheme returned mismatched node arrays");
  }
  const int known = static_cast<int>(db.node_count());
  for (const int g : local.global) {
    if (g >= known) {
      throw MeshingError(ErrorCode::Internal, EntityRef{owner.dim, owner.id},
                         "scheme referenced an unknown node");
    }
  }
  std::vector<mesh::NodeOwner> owners;
  owners.reserve(static_cast<size_t>(
      std::count_if(local.global.begin(), local.global.end(), [](int g) { return g < 0; })));
  size_t fresh = 0;
  for (size_t k = 0; k < local.global.size(); ++k) {
    if (local.global[k] >= 0) continue;
    const mesh::NodeOwner own =
        k < local.owners.size() && local.owners[k].dim >= 0 ? local.owners[k] : owner;
    owners.push_back(own);
    local.coords[fresh] = local.coords[k];  // fresh <= k: compaction in place
    local.global[k] = known + static_cast<int>(fresh);
    ++fresh;
  }
  local.coords.resize(fresh);
  local.owners = {};
  db.append_nodes(std::move(local.coords), std::move(owners));
  return local.global;
}

// Renumbers elements in place from local to global indices (checked
// before: every index is in range), in parallel over fixed blocks.
template <size_t N>
void remap(std::vector<std::array<int, N>>& elements, const std::vector<int>& map) {
  tbb::parallel_for(tbb::blocked_range<size_t>(0, elements.size(), 8192),
                    [&](const tbb::blocked_range<size_t>& r) {
                      for (size_t e = r.begin(); e != r.end(); ++e) {
                        for (int& v : elements[e]) v = map[static_cast<size_t>(v)];
                      }
                    });
}

// Checks every local index before anything is handed over, so a bad mesh
// leaves db's element arrays untouched. Parallel; whether it throws does
// not depend on the thread count (the message names no element).
template <size_t N>
void check(const std::vector<std::array<int, N>>& elements, size_t nodes, EntityRef entity) {
  const bool bad = tbb::parallel_reduce(
      tbb::blocked_range<size_t>(0, elements.size(), 8192), false,
      [&](const tbb::blocked_range<size_t>& r, bool found) {
        for (size_t e = r.begin(); e != r.end() && !found; ++e) {
          for (int v : elements[e]) found = found || v < 0 || static_cast<size_t>(v) >= nodes;
        }
        return found;
      },
      [](bool a, bool b) { return a || b; });
  if (bad) throw MeshingError(ErrorCode::Internal, entity, "element with a bad local node index");
}

}  // namespace

void commit_surface(scheme::EntityMesh& local, int surface_id, mesh::MeshDB& db) {
  const EntityRef entity = EntityRef::surface(surface_id);
  check(local.quads, local.coords.size(), entity);
  check(local.tris, local.coords.size(), entity);
  const auto& map = globalise(local, {2, surface_id}, db);
  remap(local.quads, map);
  remap(local.tris, map);
  mesh::SurfaceMeshData& s = db.mutable_surface(surface_id);
  s.quads = std::move(local.quads);
  s.tris = std::move(local.tris);
}

void commit_volume(scheme::EntityMesh& local, int volume_id, mesh::MeshDB& db) {
  const size_t nodes = local.coords.size();
  check(local.hexes, nodes, EntityRef::volume(volume_id));
  check(local.wedges, nodes, EntityRef::volume(volume_id));
  for (const auto& [sid, quads] : local.surface_quads) check(quads, nodes, EntityRef::surface(sid));
  for (const auto& [sid, tris] : local.surface_tris) check(tris, nodes, EntityRef::surface(sid));
  const auto& map = globalise(local, {3, volume_id}, db);
  remap(local.hexes, map);
  remap(local.wedges, map);
  mesh::VolumeMeshData& v = db.mutable_volume(volume_id);
  v.hexes = std::move(local.hexes);
  v.wedges = std::move(local.wedges);
  for (auto& [sid, quads] : local.surface_quads) {
    remap(quads, map);
    db.mutable_surface(sid).quads = std::move(quads);
  }
  for (auto& [sid, tris] : local.surface_tris) {
    remap(tris, map);
    db.mutable_surface(sid).tris = std::move(tris);
  }
}

}  // namespace cooperage::pipeline
