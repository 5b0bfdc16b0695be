// The many-to-one builder shared by the barrel kinds (detail of
// sweep_many_to_one.h): barrels whose lower cap has no subcaps
// (sweep_many_to_one.cpp) and barrels with subcaps on both ends, whose
// real caps are imprinted and meshed here (sweep_two_sided.cpp).
#pragma once

#include "framework/core/error.h"
#include "schemes/cooper/form_barrels.h"
#include "schemes/cooper/sweep_many_to_one.h"

#include <algorithm>
#include <array>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

namespace cooperage::cooper::detail {

[[noreturn]] inline void fail(int volume_id, const std::string& message) {
  throw MeshingError(ErrorCode::MeshingFailed, EntityRef::volume(volume_id), message);
}

// A virtual lower cap, in EntityMesh-local nodes, oriented counter-clockwise
// about the sweep direction of the barrel that made it.
struct VirtualCap {
  std::vector<mesh::Quad> quads;
  std::vector<mesh::Tri> tris;
  std::vector<int> rib_nodes;  // MeshDB side nodes of its barrel's ribs above it (flush sides)
  // MeshDB nodes of its boundary, loop by loop: its barrel's rib ends in rib
  // order (a flush subcap's outline before any mesh is made in it).
  std::vector<std::vector<int>> rim;
};

// The elements of a barrel's upper end of one kind (quads N = 4, triangles
// N = 3), each with where its image on the lower end goes.
template <size_t N>
struct CapFaces {
  std::vector<std::array<int, N>> faces;
  std::vector<char> arriving;     ///< over a subcap arriving on the lower end
  std::vector<int> lower_region;  ///< from-middle barrel below it, or -1
  void add(const std::array<int, N>& f, bool arrives, int region) {
    faces.push_back(f);
    arriving.push_back(arrives ? 1 : 0);
    lower_region.push_back(region);
  }
};

// The same face seen from the other side: first node kept, order reversed.
template <size_t N>
std::array<int, N> reversed(std::array<int, N> f) {
  std::reverse(f.begin() + 1, f.end());
  return f;
}

// An element with its nodes renumbered through `node`.
template <size_t N>
std::array<int, N> renumbered(const std::array<int, N>& e, const std::vector<int>& node) {
  std::array<int, N> out;
  for (size_t k = 0; k < N; ++k) out[k] = node[static_cast<size_t>(e[k])];
  return out;
}

class Builder {
 public:
  Builder(const scheme::VolumeView& view, const ManyToOne& plan, const scheme::PolygonMesher* mesher)
      : vid_(view.volume_id), model_(view.model), db_(*view.mesh), plan_(plan), mesher_(mesher) {}

  scheme::EntityMesh run(std::vector<BarrelReport>* reports);

 private:
  int existing(int g);
  const mesh::SurfaceMeshData& meshed(int surface, const std::string& what) const;
  const SideFace& side(int surface) const;
  std::set<int> lower_curves(const BarrelPlan& p) const;
  /// Side quads, rib loops of the upper cap, stop nodes and the expected rib
  /// ends of barrel b; the ribs.
  Barrel ribs(size_t b, BarrelInput& bin, std::vector<int>& lower_loop_nodes) const;
  /// Rib loops of an upper cap with flush virtual caps beside it: the
  /// boundary of the real cap's mesh and every inflowing virtual cap.
  std::vector<std::vector<int>> flush_upper_loops(const BarrelPlan& p) const;
  /// Records rib_nodes and rim of barrel b's virtual cap from its ribs.
  void record_ribs(size_t b, const BarrelInput& bin, const Barrel& barrel);
  BarrelReport barrel(size_t b);
  BarrelReport two_sided(size_t b);
  /// A barrel meshed from the middle: swept from its virtual cap (made by
  /// the two-sided barrel it flows into) out to its real cap; `flip` when the
  /// virtual cap's elements face the other way.
  BarrelReport sweep_out(size_t b, bool flip);

  int vid_;
  const geom::Model& model_;
  const mesh::MeshDB& db_;
  const ManyToOne& plan_;
  const scheme::PolygonMesher* mesher_;
  scheme::EntityMesh out_;
  std::unordered_map<int, int> local_;
  std::vector<VirtualCap> virtual_;
};

}  // namespace cooperage::cooper::detail
