// An n x n grid of unit quads in z = 0, counter-clockwise about +z, its
// interior nodes movable: the smoothing and untangling tests' mesh.
#pragma once

#include "framework/mesh/mesh_db.h"

#include <vector>

namespace cooperage::cooper::test_meshes {

struct UnitGrid {
  std::vector<mesh::Vec3> points;
  std::vector<mesh::Quad> quads;
  std::vector<char> movable;
  explicit UnitGrid(int n) {
    for (int j = 0; j <= n; ++j) {
      for (int i = 0; i <= n; ++i) {
        points.emplace_back(i, j, 0);
        movable.push_back(i > 0 && i < n && j > 0 && j < n ? 1 : 0);
      }
    }
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        const int a = j * (n + 1) + i;
        quads.push_back({a, a + 1, a + n + 2, a + n + 1});
      }
    }
  }
};

}  // namespace cooperage::cooper::test_meshes
