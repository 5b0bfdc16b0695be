#include "framework/mesh/mesh_db.h"

namespace cooperage::mesh {
namespace {
const std::vector<int> kNoChain;
const SurfaceMeshData kNoSurface;
const VolumeMeshData kNoVolume;
}  // namespace

const std::vector<int>& MeshDB::curve_nodes(int curve_id) const {
  auto it = curves_.find(curve_id);
  return it == curves_.end() ? kNoChain : it->second;
}

const SurfaceMeshData& MeshDB::surface(int surface_id) const {
  auto it = surfaces_.find(surface_id);
  return it == surfaces_.end() ? kNoSurface : it->second;
}

const VolumeMeshData& MeshDB::volume(int volume_id) const {
  auto it = volumes_.find(volume_id);
  return it == volumes_.end() ? kNoVolume : it->second;
}

size_t MeshDB::hex_count() const {
  size_t n = 0;
  for (const auto& [id, v] : volumes_) n += v.hexes.size();
  return n;
}
size_t MeshDB::wedge_count() const {
  size_t n = 0;
  for (const auto& [id, v] : volumes_) n += v.wedges.size();
  return n;
}
size_t MeshDB::quad_count() const {
  size_t n = 0;
  for (const auto& [id, s] : surfaces_) n += s.quads.size();
  return n;
}
size_t MeshDB::tri_count() const {
  size_t n = 0;
  for (const auto& [id, s] : surfaces_) n += s.tris.size();
  return n;
}

}  // namespace cooperage::mesh
