#include "framework/mesh/mesh_db.h"

#include <algorithm>
#include <stdexcept>

namespace cooperage::mesh {
namespace {
const std::vector<int> kNoChain;
const SurfaceMeshData kNoSurface;
const VolumeMeshData kNoVolume;
}  // namespace

void MeshDB::append_nodes(std::vector<Vec3>&& coords, std::vector<NodeOwner>&& owners) {
  if (coords.size() != owners.size()) {
    throw std::invalid_argument("MeshDB::append_nodes: coords and owners differ in size");
  }
  const size_t n0 = coords_.size(), m = coords.size();
  if (coords.capacity() >= n0 + m && coords_.capacity() < n0 + m) {
    // Slide the new nodes up (within capacity: no reallocation), put the
    // existing ones in front, and keep that array.
    coords.resize(n0 + m);
    std::move_backward(coords.begin(), coords.begin() + static_cast<std::ptrdiff_t>(m),
                       coords.end());
    std::copy(coords_.begin(), coords_.end(), coords.begin());
    coords_.swap(coords);
  } else {
    coords_.insert(coords_.end(), coords.begin(), coords.end());
  }
  owners_.insert(owners_.end(), owners.begin(), owners.end());
  coords = {};
  owners = {};
}

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
