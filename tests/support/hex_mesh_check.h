// Conformity and measures of an all-hex mesh of a model (tests only): every
// hex face used once or twice; the faces used once are exactly the quads of
// surfaces bounding one volume; the quads of a surface between two volumes
// are used twice; no duplicate nodes; no inverted hex.
#pragma once

#include "support/mesh_checks.h"

#include "framework/geometry/model.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace cooperage::testing {

struct HexMeshSummary {
  double volume = 0;  ///< sum of the exact trilinear hex volumes
  double min_sj = 1;  ///< smallest scaled Jacobian
  size_t hexes = 0;
};

inline HexMeshSummary check_hex_mesh(const geom::Model& model, const mesh::MeshDB& db) {
  HexMeshSummary s;
  for (const auto& [id, vol] : db.volumes()) {
    EXPECT_TRUE(vol.wedges.empty());
    for (const auto& h : vol.hexes) {
      const auto p = hex_points(db, h);
      s.volume += hex_volume(p);
      s.min_sj = std::min(s.min_sj, hex_scaled_jacobian(p));
      ++s.hexes;
    }
  }
  const auto faces = hex_face_counts(db);
  size_t once = 0;
  for (const auto& [key, n] : faces) {
    EXPECT_LE(n, 2);
    if (n == 1) ++once;
  }
  size_t boundary_quads = 0;
  for (const auto& [sid, m] : db.surfaces()) {
    const int expected = static_cast<int>(model.surface(sid).volumes.size()) == 2 ? 2 : 1;
    for (const auto& q : m.quads) {
      auto it = faces.find(face_key(q));
      if (it == faces.end()) {
        ADD_FAILURE() << "a quad of surface " << sid << " is no hex face";
        continue;
      }
      EXPECT_EQ(it->second, expected) << "surface " << sid;
      if (expected == 1) ++boundary_quads;
    }
  }
  EXPECT_EQ(once, boundary_quads);
  EXPECT_EQ(duplicate_node_pairs(db, 1e-9), 0);
  EXPECT_GT(s.min_sj, 0.0);
  return s;
}

}  // namespace cooperage::testing
