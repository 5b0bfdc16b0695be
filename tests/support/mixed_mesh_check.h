// Conformity and measures of a hex/wedge mesh of a model (tests only):
// every element face (hex quads, wedge quads and triangles) used once or
// twice; the faces used once are exactly the surface elements of surfaces
// bounding one volume (quads and triangles), those of a surface between two
// volumes are used twice; a quad shared by a hex and a wedge has the same
// four nodes in both; no duplicate nodes; no inverted element.
#pragma once

#include "support/mesh_checks.h"

#include "framework/geometry/model.h"
#include "framework/quality/wedge_metrics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

namespace cooperage::testing {

struct MixedMeshSummary {
  double volume = 0;        ///< exact: trilinear hexes, linear wedges
  double min_hex_sj = 1;    ///< smallest hex scaled Jacobian (1 when no hex)
  double min_wedge_sj = 1;  ///< smallest wedge scaled Jacobian (Verdict, 1 when no wedge)
  size_t hexes = 0, wedges = 0;
  size_t hex_wedge_quads = 0;  ///< interior quads shared by a hex and a wedge
};

/// Volume of a linear wedge (Exodus order), its quad faces bilinear (so
/// exact also where a sweep twists them): det J is linear in the triangle
/// coordinates and quadratic along the sweep, so the centroid rule times
/// 2-point Gauss along t integrates it exactly.
inline double wedge_volume(const quality::WedgeNodes& p) {
  const double g = 0.5 / std::sqrt(3.0);
  double v = 0;
  for (double t : {0.5 - g, 0.5 + g}) {
    const Vec3 dr = (1 - t) * (p[1] - p[0]) + t * (p[4] - p[3]);
    const Vec3 ds = (1 - t) * (p[2] - p[0]) + t * (p[5] - p[3]);
    const Vec3 dt = ((p[3] - p[0]) + (p[4] - p[1]) + (p[5] - p[2])) / 3.0;
    v += 0.5 * 0.5 * dr.cross(ds).dot(dt);  // Gauss weight 1/2, triangle area 1/2
  }
  return v;
}

inline std::vector<int> sorted_key(std::vector<int> f) {
  std::sort(f.begin(), f.end());
  return f;
}

inline MixedMeshSummary check_mixed_mesh(const geom::Model& model, const mesh::MeshDB& db) {
  MixedMeshSummary s;
  struct Use {
    int count = 0;
    int by_hex = 0;
  };
  std::map<std::vector<int>, Use> faces;
  static const int hex_side[6][4] = {{0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6},
                                     {0, 4, 7, 3}, {0, 3, 2, 1}, {4, 5, 6, 7}};
  static const int wedge_quad[3][4] = {{0, 1, 4, 3}, {1, 2, 5, 4}, {2, 0, 3, 5}};
  for (const auto& [id, vol] : db.volumes()) {
    for (const auto& h : vol.hexes) {
      const auto p = hex_points(db, h);
      s.volume += hex_volume(p);
      s.min_hex_sj = std::min(s.min_hex_sj, hex_scaled_jacobian(p));
      ++s.hexes;
      for (const auto& f : hex_side) {
        Use& u = faces[sorted_key({h[f[0]], h[f[1]], h[f[2]], h[f[3]]})];
        ++u.count;
        ++u.by_hex;
      }
    }
    for (const auto& w : vol.wedges) {
      quality::WedgeNodes p;
      for (size_t k = 0; k < 6; ++k) p[k] = db.node(w[k]);
      s.volume += wedge_volume(p);
      s.min_wedge_sj = std::min(s.min_wedge_sj, quality::wedge_scaled_jacobian(p));
      ++s.wedges;
      ++faces[sorted_key({w[0], w[1], w[2]})].count;
      ++faces[sorted_key({w[3], w[4], w[5]})].count;
      for (const auto& f : wedge_quad)
        ++faces[sorted_key({w[f[0]], w[f[1]], w[f[2]], w[f[3]]})].count;
    }
  }
  size_t once = 0;
  for (const auto& [key, u] : faces) {
    EXPECT_LE(u.count, 2) << "a face of " << key.size() << " nodes used " << u.count << " times";
    if (u.count == 1) ++once;
    if (u.count == 2 && key.size() == 4 && u.by_hex == 1) ++s.hex_wedge_quads;
  }
  size_t boundary = 0;
  auto check_surface_face = [&](int sid, std::vector<int> f) {
    const int expected = model.surface(sid).volumes.size() == 2 ? 2 : 1;
    const auto it = faces.find(sorted_key(std::move(f)));
    if (it == faces.end()) {
      ADD_FAILURE() << "an element of surface " << sid << " is no element face";
      return;
    }
    EXPECT_EQ(it->second.count, expected) << "surface " << sid;
    if (expected == 1) ++boundary;
  };
  for (const auto& [sid, m] : db.surfaces()) {
    for (const auto& q : m.quads) check_surface_face(sid, {q[0], q[1], q[2], q[3]});
    for (const auto& t : m.tris) check_surface_face(sid, {t[0], t[1], t[2]});
  }
  EXPECT_EQ(once, boundary) << "element faces used once that are no surface element";
  EXPECT_EQ(duplicate_node_pairs(db, 1e-9), 0);
  if (s.hexes) {
    EXPECT_GT(s.min_hex_sj, 0.0);
  }
  if (s.wedges) {
    EXPECT_GT(s.min_wedge_sj, 0.0);
  }
  return s;
}

}  // namespace cooperage::testing
