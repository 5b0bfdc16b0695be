#include "mesh_helpers.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace cooperage::testing {

using geom::Vec3;

void mesh_curves(const geom::Model& model, mesh::MeshDB& db, double size,
                 const std::map<int, int>& counts) {
  for (const auto& v : model.vertices()) {
    db.set_vertex_node(v.id, db.add_node(v.point, mesh::NodeOwner{0, v.id}));
  }
  for (const auto& c : model.curves()) {
    auto it = counts.find(c.id);
    const int n = it != counts.end() ? it->second
                                     : std::max(1, static_cast<int>(std::lround(c.length / size)));
    std::vector<int> chain{db.vertex_node(c.start_vertex)};
    for (int k = 1; k < n; ++k) {
      const double t = c.geometry->parameter_at_length(c.length * k / n);
      chain.push_back(db.add_node(c.geometry->point(t), mesh::NodeOwner{1, c.id}));
    }
    chain.push_back(db.vertex_node(c.end_vertex));
    db.set_curve_nodes(c.id, std::move(chain));
  }
}

std::vector<int> commit_nodes(mesh::MeshDB& db, const scheme::EntityMesh& em,
                              mesh::NodeOwner owner) {
  std::vector<int> global(em.global.size());
  for (size_t k = 0; k < em.global.size(); ++k) {
    global[k] = em.global[k] >= 0 ? em.global[k] : db.add_node(em.coords[k], owner);
  }
  return global;
}

void commit_surface(mesh::MeshDB& db, int surface_id, const scheme::EntityMesh& em) {
  const std::vector<int> g = commit_nodes(db, em, mesh::NodeOwner{2, surface_id});
  auto& s = db.mutable_surface(surface_id);
  for (const auto& q : em.quads) {
    s.quads.push_back({g[static_cast<size_t>(q[0])], g[static_cast<size_t>(q[1])],
                       g[static_cast<size_t>(q[2])], g[static_cast<size_t>(q[3])]});
  }
  for (const auto& t : em.tris) {
    s.tris.push_back(
        {g[static_cast<size_t>(t[0])], g[static_cast<size_t>(t[1])], g[static_cast<size_t>(t[2])]});
  }
}

void commit_volume(mesh::MeshDB& db, int volume_id, const scheme::EntityMesh& em) {
  const std::vector<int> g = commit_nodes(db, em, mesh::NodeOwner{3, volume_id});
  auto& v = db.mutable_volume(volume_id);
  for (const auto& h : em.hexes) {
    mesh::Hex out;
    for (size_t c = 0; c < 8; ++c) out[c] = g[static_cast<size_t>(h[c])];
    v.hexes.push_back(out);
  }
}

std::array<Vec3, 8> hex_points(const mesh::MeshDB& db, const mesh::Hex& hex) {
  std::array<Vec3, 8> x;
  for (size_t c = 0; c < 8; ++c) x[c] = db.node(hex[c]);
  return x;
}

double hex_volume(const std::array<Vec3, 8>& x) {
  // Faces with outward orientation for a positive (Exodus-ordered) hex.
  static constexpr int kFaces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                       {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  auto tri = [&](int a, int b, int c) {
    return x[static_cast<size_t>(a)].dot(
        x[static_cast<size_t>(b)].cross(x[static_cast<size_t>(c)]));
  };
  double v = 0.0;
  for (const auto& f : kFaces) {
    const double d1 = tri(f[0], f[1], f[2]) + tri(f[0], f[2], f[3]);
    const double d2 = tri(f[0], f[1], f[3]) + tri(f[1], f[2], f[3]);
    v += 0.5 * (d1 + d2);
  }
  return v / 6.0;
}

double hex_scaled_jacobian(const std::array<Vec3, 8>& x) {
  static constexpr int kNeighbours[8][3] = {{1, 3, 4}, {2, 0, 5}, {3, 1, 6}, {0, 2, 7},
                                            {7, 5, 0}, {4, 6, 1}, {5, 7, 2}, {6, 4, 3}};
  double worst = 1.0;
  for (int c = 0; c < 8; ++c) {
    Vec3 e[3];
    for (int a = 0; a < 3; ++a) {
      e[a] = (x[static_cast<size_t>(kNeighbours[c][a])] - x[static_cast<size_t>(c)]).normalized();
    }
    worst = std::min(worst, e[0].dot(e[1].cross(e[2])));
  }
  return worst;
}

double quad_scaled_jacobian(const mesh::MeshDB& db, const mesh::Quad& q, const Vec3& normal) {
  double worst = 1.0;
  for (size_t c = 0; c < 4; ++c) {
    const Vec3 e1 = db.node(q[(c + 1) % 4]) - db.node(q[c]);
    const Vec3 e2 = db.node(q[(c + 3) % 4]) - db.node(q[c]);
    worst = std::min(worst, e1.cross(e2).dot(normal) / (e1.norm() * e2.norm()));
  }
  return worst;
}

std::array<int, 4> sorted(const mesh::Quad& q) {
  std::array<int, 4> s = q;
  std::sort(s.begin(), s.end());
  return s;
}

std::map<std::array<int, 4>, int> hex_face_counts(const std::vector<mesh::Hex>& hexes) {
  static constexpr int kFaces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                       {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  std::map<std::array<int, 4>, int> counts;
  for (const auto& h : hexes) {
    for (const auto& f : kFaces) {
      ++counts[sorted({h[static_cast<size_t>(f[0])], h[static_cast<size_t>(f[1])],
                       h[static_cast<size_t>(f[2])], h[static_cast<size_t>(f[3])]})];
    }
  }
  return counts;
}

}  // namespace cooperage::testing
