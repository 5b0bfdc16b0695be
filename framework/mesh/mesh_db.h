// MeshDB: the mesh of a whole model, as plain arrays (docs/design.md; the seed brief "Core types").
// A node on a shared vertex, curve or surface exists once; surface elements
// are oriented with their surface's natural normal (outward for the
// surface's first volume); volume elements use Exodus/VTK node order:
//   hex:   P0..P3 bottom counter-clockwise seen from P4..P7's side, P4..P7 above them
//   wedge: P0..P2 bottom triangle counter-clockwise seen from P3..P5, P3..P5 above
// Node indices are 0-based here; exporters write them 1-based where a format asks.
#pragma once

#include "framework/geometry/types.h"

#include <array>
#include <cstdint>
#include <map>
#include <set>
#include <vector>

namespace cooperage::mesh {

using geom::Vec3;

/// The geometric entity a node lies in: dim 0 vertex, 1 curve, 2 surface,
/// 3 volume interior, with its 1-based model id.
struct NodeOwner {
  std::int8_t dim = -1;
  int id = 0;
  bool operator==(const NodeOwner& o) const { return dim == o.dim && id == o.id; }
};

using Tri = std::array<int, 3>;
using Quad = std::array<int, 4>;
using Wedge = std::array<int, 6>;
using Hex = std::array<int, 8>;

struct SurfaceMeshData {
  std::vector<Quad> quads;
  std::vector<Tri> tris;
  size_t size() const { return quads.size() + tris.size(); }
};

struct VolumeMeshData {
  std::vector<Hex> hexes;
  std::vector<Wedge> wedges;
  size_t size() const { return hexes.size() + wedges.size(); }
};

class MeshDB {
 public:
  /// Adds a node; returns its 0-based index.
  int add_node(const Vec3& x, NodeOwner owner) {
    coords_.push_back(x);
    owners_.push_back(owner);
    return static_cast<int>(coords_.size()) - 1;
  }
  void reserve_nodes(size_t n) {
    coords_.reserve(n);
    owners_.reserve(n);
  }
  /// Appends nodes (coords[k] owned by owners[k]; the sizes must match),
  /// taking `coords`' storage when it has room for the existing nodes in
  /// front: the node array is then never held twice (at 10 M hexes each
  /// copy is 240 MB). Both arguments are left empty.
  void append_nodes(std::vector<Vec3>&& coords, std::vector<NodeOwner>&& owners);
  size_t node_count() const { return coords_.size(); }
  const Vec3& node(int i) const { return coords_[static_cast<size_t>(i)]; }
  Vec3& mutable_node(int i) { return coords_[static_cast<size_t>(i)]; }
  const NodeOwner& owner(int i) const { return owners_[static_cast<size_t>(i)]; }
  const std::vector<Vec3>& coords() const { return coords_; }

  /// The node of a model vertex (-1 when not meshed).
  int vertex_node(int vertex_id) const {
    auto it = vertex_nodes_.find(vertex_id);
    return it == vertex_nodes_.end() ? -1 : it->second;
  }
  void set_vertex_node(int vertex_id, int node) { vertex_nodes_[vertex_id] = node; }

  /// Node chain of a curve from its start vertex to its end vertex, both
  /// included (first == last for a closed curve); empty when not meshed.
  const std::vector<int>& curve_nodes(int curve_id) const;
  void set_curve_nodes(int curve_id, std::vector<int> chain) {
    curves_[curve_id] = std::move(chain);
  }
  bool curve_meshed(int curve_id) const { return curves_.count(curve_id) > 0; }
  /// A volume scheme set where the curve's nodes go (VolumeScheme::
  /// space_curves): its grading is on purpose, and a surface scheme keeps it.
  void set_curve_placed_by_volume(int curve_id) { placed_by_volume_.insert(curve_id); }
  bool curve_placed_by_volume(int curve_id) const { return placed_by_volume_.count(curve_id) > 0; }

  const SurfaceMeshData& surface(int surface_id) const;
  SurfaceMeshData& mutable_surface(int surface_id) { return surfaces_[surface_id]; }
  bool surface_meshed(int surface_id) const { return surfaces_.count(surface_id) > 0; }

  const VolumeMeshData& volume(int volume_id) const;
  VolumeMeshData& mutable_volume(int volume_id) { return volumes_[volume_id]; }
  bool volume_meshed(int volume_id) const { return volumes_.count(volume_id) > 0; }

  /// Meshed entities in ascending id order.
  const std::map<int, std::vector<int>>& curves() const { return curves_; }
  const std::map<int, SurfaceMeshData>& surfaces() const { return surfaces_; }
  const std::map<int, VolumeMeshData>& volumes() const { return volumes_; }

  size_t hex_count() const;
  size_t wedge_count() const;
  size_t quad_count() const;
  size_t tri_count() const;

 private:
  std::vector<Vec3> coords_;
  std::vector<NodeOwner> owners_;
  std::map<int, int> vertex_nodes_;
  std::map<int, std::vector<int>> curves_;
  std::set<int> placed_by_volume_;
  std::map<int, SurfaceMeshData> surfaces_;
  std::map<int, VolumeMeshData> volumes_;
};

}  // namespace cooperage::mesh
