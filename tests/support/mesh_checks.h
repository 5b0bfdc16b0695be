// Independent checks of a mesh that follow from geometry and topology
// (tests only): exact hex volumes, face sharing, duplicate nodes, scaled
// Jacobian. Written here rather than reused from framework/quality so that a
// bug there cannot hide a bug in a scheme.
#pragma once

#include "framework/mesh/mesh_db.h"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <vector>

namespace cooperage::testing {

using Vec3 = Eigen::Vector3d;

/// Volume of a trilinear hex (Exodus order): the integral of det J by 2x2x2
/// Gauss quadrature, exact for trilinear maps.
inline double hex_volume(const std::array<Vec3, 8>& p) {
  static const double g = 1.0 / std::sqrt(3.0);
  static const int sx[8] = {-1, 1, 1, -1, -1, 1, 1, -1};
  static const int sy[8] = {-1, -1, 1, 1, -1, -1, 1, 1};
  static const int sz[8] = {-1, -1, -1, -1, 1, 1, 1, 1};
  double v = 0;
  for (double a : {-g, g}) {
    for (double b : {-g, g}) {
      for (double c : {-g, g}) {
        Eigen::Matrix3d J = Eigen::Matrix3d::Zero();
        for (int i = 0; i < 8; ++i) {
          const double dx = sx[i] * (1 + sy[i] * b) * (1 + sz[i] * c) / 8;
          const double dy = sy[i] * (1 + sx[i] * a) * (1 + sz[i] * c) / 8;
          const double dz = sz[i] * (1 + sx[i] * a) * (1 + sy[i] * b) / 8;
          J.col(0) += dx * p[i];
          J.col(1) += dy * p[i];
          J.col(2) += dz * p[i];
        }
        v += J.determinant();
      }
    }
  }
  return v;
}

inline std::array<Vec3, 8> hex_points(const mesh::MeshDB& db, const mesh::Hex& h) {
  std::array<Vec3, 8> p;
  for (int i = 0; i < 8; ++i) p[i] = db.node(h[i]);
  return p;
}

/// Minimum over the 8 corners of the determinant of the unit edge vectors.
inline double hex_scaled_jacobian(const std::array<Vec3, 8>& p) {
  static const int corner[8][4] = {{0, 1, 3, 4}, {1, 2, 0, 5}, {2, 3, 1, 6}, {3, 0, 2, 7},
                                   {4, 7, 5, 0}, {5, 4, 6, 1}, {6, 5, 7, 2}, {7, 6, 4, 3}};
  double m = 1e300;
  for (const auto& c : corner) {
    Eigen::Matrix3d A;
    for (int k = 0; k < 3; ++k) {
      const Vec3 e = p[c[k + 1]] - p[c[0]];
      A.col(k) = e.norm() > 0 ? Vec3(e.normalized()) : Vec3::Zero();
    }
    m = std::min(m, A.determinant());
  }
  return m;
}

using FaceKey = std::array<int, 4>;

inline FaceKey face_key(std::array<int, 4> f) {
  std::sort(f.begin(), f.end());
  return f;
}

/// Hex faces (Exodus side order) keyed by sorted nodes -> number of hexes using them.
inline std::map<FaceKey, int> hex_face_counts(const mesh::MeshDB& db) {
  static const int side[6][4] = {{0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6},
                                 {0, 4, 7, 3}, {0, 3, 2, 1}, {4, 5, 6, 7}};
  std::map<FaceKey, int> count;
  for (const auto& [id, v] : db.volumes()) {
    for (const auto& h : v.hexes) {
      for (const auto& s : side) count[face_key({h[s[0]], h[s[1]], h[s[2]], h[s[3]]})]++;
    }
  }
  return count;
}

/// Number of node pairs closer than tol (should be 0: no duplicate nodes).
inline int duplicate_node_pairs(const mesh::MeshDB& db, double tol) {
  std::vector<int> order(db.node_count());
  for (size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return db.node(a).x() < db.node(b).x(); });
  int pairs = 0;
  for (size_t i = 0; i < order.size(); ++i) {
    for (size_t j = i + 1; j < order.size(); ++j) {
      if (db.node(order[j]).x() - db.node(order[i]).x() > tol) break;
      if ((db.node(order[j]) - db.node(order[i])).norm() < tol) ++pairs;
    }
  }
  return pairs;
}

}  // namespace cooperage::testing
