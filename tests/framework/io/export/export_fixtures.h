// Hand-built MeshDB + Model fixtures for the exporter tests: axis-aligned
// boxes of hexes and wedges. Surfaces are derived from the boundary faces
// (one surface per volume and box side, one per pair of volumes sharing
// faces), oriented outward of their first (lowest-id) volume.
#pragma once

#include "framework/geometry/model.h"
#include "framework/mesh/mesh_db.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <vector>

namespace cooperage::test {

using geom::Vec3;

// Outward faces (right-hand normal out of the element), 0-based, written
// here from the Exodus manual independently of the exporter's tables.
inline const std::vector<std::vector<int>>& hex_outward_faces() {
  static const std::vector<std::vector<int>> t{{0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6},
                                               {0, 4, 7, 3}, {0, 3, 2, 1}, {4, 5, 6, 7}};
  return t;
}
inline const std::vector<std::vector<int>>& wedge_outward_faces() {
  static const std::vector<std::vector<int>> t{
      {0, 1, 4, 3}, {1, 2, 5, 4}, {0, 3, 5, 2}, {0, 2, 1}, {3, 4, 5}};
  return t;
}

struct TestMesh {
  geom::Model model;
  mesh::MeshDB db;
};

class MeshBuilder {
 public:
  int node(const Vec3& x) {
    for (size_t i = 0; i < pts_.size(); ++i) {
      if ((pts_[i] - x).norm() < 1e-12) return static_cast<int>(i);
    }
    pts_.push_back(x);
    return static_cast<int>(pts_.size()) - 1;
  }
  void hex(int vol, const mesh::Hex& h) { hexes_[vol].push_back(h); }
  void wedge(int vol, const mesh::Wedge& w) { wedges_[vol].push_back(w); }
  /// Structured nx*ny*nz hexes filling [lo, hi] in volume `vol`.
  void block(int vol, const Vec3& lo, const Vec3& hi, int nx, int ny, int nz) {
    auto p = [&](int i, int j, int k) {
      return node(Vec3(lo.x() + (hi.x() - lo.x()) * i / nx, lo.y() + (hi.y() - lo.y()) * j / ny,
                       lo.z() + (hi.z() - lo.z()) * k / nz));
    };
    for (int k = 0; k < nz; ++k)
      for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i)
          hex(vol, {p(i, j, k), p(i + 1, j, k), p(i + 1, j + 1, k), p(i, j + 1, k), p(i, j, k + 1),
                    p(i + 1, j, k + 1), p(i + 1, j + 1, k + 1), p(i, j + 1, k + 1)});
  }
  /// Two wedges filling [lo, hi] (split along the diagonal of the z = lo face).
  void prism_pair(int vol, const Vec3& lo, const Vec3& hi) {
    auto p = [&](int i, int j, int k) {
      return node(Vec3(i ? hi.x() : lo.x(), j ? hi.y() : lo.y(), k ? hi.z() : lo.z()));
    };
    wedge(vol, {p(0, 0, 0), p(1, 0, 0), p(1, 1, 0), p(0, 0, 1), p(1, 0, 1), p(1, 1, 1)});
    wedge(vol, {p(0, 0, 0), p(1, 1, 0), p(0, 1, 0), p(0, 0, 1), p(1, 1, 1), p(0, 1, 1)});
  }

  /// Builds the model (surfaces from boundary faces) and the MeshDB.
  TestMesh build(const std::vector<std::string>& volume_names, bool surfaces_only = false) {
    TestMesh t;
    geom::BoundingBox box;
    for (const auto& x : pts_) box.add(x);
    // Collect faces: key = sorted nodes -> (volume, oriented nodes) uses.
    struct Use {
      int vol;
      std::vector<int> nodes;
    };
    std::map<std::vector<int>, std::vector<Use>> faces;
    auto add_faces = [&](int vol, const int* e, const std::vector<std::vector<int>>& table) {
      for (const auto& f : table) {
        std::vector<int> nodes;
        for (int k : f) nodes.push_back(e[k]);
        std::vector<int> key = nodes;
        std::sort(key.begin(), key.end());
        faces[key].push_back({vol, nodes});
      }
    };
    for (auto& [v, hs] : hexes_)
      for (auto& h : hs) add_faces(v, h.data(), hex_outward_faces());
    for (auto& [v, ws] : wedges_)
      for (auto& w : ws) add_faces(v, w.data(), wedge_outward_faces());
    // Surface key: (first volume, second volume or 0, box side 0..5 or 6 = shared).
    std::map<std::tuple<int, int, int>, std::vector<std::vector<int>>> surf;
    for (auto& [key, uses] : faces) {
      if (uses.size() == 2 && uses[0].vol == uses[1].vol) continue;  // interior
      if (uses.size() == 2) {
        const Use& a = uses[0].vol < uses[1].vol ? uses[0] : uses[1];
        const Use& b = uses[0].vol < uses[1].vol ? uses[1] : uses[0];
        surf[{a.vol, b.vol, 6}].push_back(a.nodes);
        continue;
      }
      int side = -1;
      for (int a = 0; a < 3 && side < 0; ++a) {
        bool at_min = true, at_max = true;
        for (int n : key) {
          at_min = at_min && std::abs(pts_[n][a] - box.min[a]) < 1e-12;
          at_max = at_max && std::abs(pts_[n][a] - box.max[a]) < 1e-12;
        }
        if (at_min) side = 2 * a;
        if (at_max) side = 2 * a + 1;
      }
      surf[{uses[0].vol, 0, side}].push_back(uses[0].nodes);
    }
    // Model: volumes first (ids 1..), then surfaces in key order.
    int n_vol = 0;
    for (auto& [v, hs] : hexes_) n_vol = std::max(n_vol, v);
    for (auto& [v, ws] : wedges_) n_vol = std::max(n_vol, v);
    for (int v = 1; v <= n_vol; ++v) {
      geom::Volume vol;
      if (static_cast<size_t>(v - 1) < volume_names.size()) vol.name = volume_names[v - 1];
      vol.shells.emplace_back();
      t.model.add_volume(vol);
    }
    for (int c = 0; c < 8; ++c) {
      geom::Vertex vx;
      vx.point = Vec3(c & 1 ? box.max.x() : box.min.x(), c & 2 ? box.max.y() : box.min.y(),
                      c & 4 ? box.max.z() : box.min.z());
      t.model.add_vertex(vx);
    }
    std::vector<int> node_surface(pts_.size(), 0);
    for (auto& [key, elems] : surf) {
      geom::Surface s;
      s.volumes.push_back(std::get<0>(key));
      if (std::get<1>(key) > 0) s.volumes.push_back(std::get<1>(key));
      const int sid = t.model.add_surface(s);
      t.model.mutable_volume(std::get<0>(key)).shells[0].push_back({sid, geom::Sense::Forward});
      if (std::get<1>(key) > 0) {
        t.model.mutable_volume(std::get<1>(key)).shells[0].push_back({sid, geom::Sense::Reversed});
      }
      surface_elems_[sid] = elems;
      for (auto& e : elems)
        for (int n : e)
          if (!node_surface[n]) node_surface[n] = sid;
    }
    // Nodes with owners: box corners -> vertices, surface nodes -> lowest
    // surface, the rest -> the first volume using them.
    std::vector<int> node_volume(pts_.size(), 0);
    for (auto& [v, hs] : hexes_)
      for (auto& h : hs)
        for (int n : h)
          if (!node_volume[n]) node_volume[n] = v;
    for (auto& [v, ws] : wedges_)
      for (auto& w : ws)
        for (int n : w)
          if (!node_volume[n]) node_volume[n] = v;
    for (size_t i = 0; i < pts_.size(); ++i) {
      mesh::NodeOwner o{3, node_volume[i]};
      if (node_surface[i]) o = {2, node_surface[i]};
      for (const auto& vx : t.model.vertices()) {
        if ((vx.point - pts_[i]).norm() < 1e-12) o = {0, vx.id};
      }
      const int n = t.db.add_node(pts_[i], o);
      if (o.dim == 0) t.db.set_vertex_node(o.id, n);
    }
    for (auto& [sid, elems] : surface_elems_) {
      auto& s = t.db.mutable_surface(sid);
      for (auto& e : elems) {
        if (e.size() == 4)
          s.quads.push_back({e[0], e[1], e[2], e[3]});
        else
          s.tris.push_back({e[0], e[1], e[2]});
      }
    }
    if (!surfaces_only) {
      for (auto& [v, hs] : hexes_) t.db.mutable_volume(v).hexes = hs;
      for (auto& [v, ws] : wedges_) t.db.mutable_volume(v).wedges = ws;
    }
    return t;
  }

 private:
  std::vector<Vec3> pts_;
  std::map<int, std::vector<mesh::Hex>> hexes_;
  std::map<int, std::vector<mesh::Wedge>> wedges_;
  std::map<int, std::vector<std::vector<int>>> surface_elems_;
};

/// Volume 1: unit cube of 2x2x2 hexes.
inline TestMesh one_block() {
  MeshBuilder b;
  b.block(1, Vec3(0, 0, 0), Vec3(1, 1, 1), 2, 2, 2);
  return b.build({"block one"});
}

/// Volumes 1 and 2: two unit cubes of 2x2x2 hexes sharing the face x = 1.
inline TestMesh two_blocks() {
  MeshBuilder b;
  b.block(1, Vec3(0, 0, 0), Vec3(1, 1, 1), 2, 2, 2);
  b.block(2, Vec3(1, 0, 0), Vec3(2, 1, 1), 2, 2, 2);
  return b.build({"left", "right"});
}

/// Volume 1: a unit cube as two wedges (z = 0, 1 faces are two triangles each).
inline TestMesh two_wedges() {
  MeshBuilder b;
  b.prism_pair(1, Vec3(0, 0, 0), Vec3(1, 1, 1));
  return b.build({"prisms"});
}

/// Volume 1: one hex [0,1]^3 plus two wedges filling [1,2]x[0,1]^2.
inline TestMesh mixed() {
  MeshBuilder b;
  b.block(1, Vec3(0, 0, 0), Vec3(1, 1, 1), 1, 1, 1);
  b.prism_pair(1, Vec3(1, 0, 0), Vec3(2, 1, 1));
  return b.build({"mixed"});
}

/// The surface mesh of one_block() only (no volume elements).
inline TestMesh surface_only() {
  MeshBuilder b;
  b.block(1, Vec3(0, 0, 0), Vec3(1, 1, 1), 2, 2, 2);
  return b.build({"shell"}, true);
}

/// Signed volume of a hex / wedge (MeshDB order) by the divergence theorem
/// over its outward faces, each split into triangles about its centroid.
inline double signed_volume(const std::vector<Vec3>& x, const int* e,
                            const std::vector<std::vector<int>>& faces) {
  double v = 0;
  for (const auto& f : faces) {
    Vec3 c = Vec3::Zero();
    for (int k : f) c += x[e[k]];
    c /= static_cast<double>(f.size());
    for (size_t k = 0; k < f.size(); ++k) {
      const Vec3& a = x[e[f[k]]];
      const Vec3& b = x[e[f[(k + 1) % f.size()]]];
      v += a.dot(b.cross(c)) / 6.0;
    }
  }
  return v;
}

}  // namespace cooperage::test
