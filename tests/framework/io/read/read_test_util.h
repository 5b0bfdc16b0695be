// Helpers of the mesh reader tests: elements as coordinate sequences (so a
// file's node renumbering does not matter, but node order does) and signed
// volumes of read elements.
#pragma once

#include "framework/io/export/export_fixtures.h"
#include "framework/io/read/read_mesh_file.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace cooperage::test {

/// One element as its node coordinates in order, rounded to 1e-9.
using CoordElement = std::vector<long long>;

inline CoordElement coord_element(const std::vector<Eigen::Vector3d>& x, const int* e, int n) {
  CoordElement c;
  for (int k = 0; k < n; ++k) {
    for (int a = 0; a < 3; ++a) c.push_back(std::llround(x[static_cast<size_t>(e[k])][a] * 1e9));
  }
  return c;
}

/// Sorted coordinate sequences of the elements of `type` in a read file.
inline std::vector<CoordElement> elements_of(const io::MeshFile& f, quality::ElementType type) {
  std::vector<CoordElement> out;
  const int n = quality::node_count(type);
  for (const auto& b : f.blocks) {
    if (b.type != type) continue;
    for (size_t e = 0; e < b.size(); ++e) {
      out.push_back(coord_element(f.coords, b.connectivity.data() + e * static_cast<size_t>(n), n));
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

/// Sorted coordinate sequences of the hexes (wedges) of a MeshDB.
inline std::vector<CoordElement> db_elements(const mesh::MeshDB& db, bool wedges) {
  std::vector<Eigen::Vector3d> x;
  for (size_t i = 0; i < db.node_count(); ++i) x.push_back(db.node(static_cast<int>(i)));
  std::vector<CoordElement> out;
  for (const auto& [vid, v] : db.volumes()) {
    if (wedges)
      for (const auto& w : v.wedges) out.push_back(coord_element(x, w.data(), 6));
    else
      for (const auto& h : v.hexes) out.push_back(coord_element(x, h.data(), 8));
  }
  std::sort(out.begin(), out.end());
  return out;
}

/// Minimum signed volume of the hexes and wedges of a read file
/// (+infinity when there are none).
inline double min_volume(const io::MeshFile& f) {
  double v = INFINITY;
  for (const auto& b : f.blocks) {
    const bool hex = b.type == quality::ElementType::Hex;
    if (!hex && b.type != quality::ElementType::Wedge) continue;
    const int n = quality::node_count(b.type);
    for (size_t e = 0; e < b.size(); ++e) {
      v = std::min(v, signed_volume(f.coords, b.connectivity.data() + e * static_cast<size_t>(n),
                                    hex ? hex_outward_faces() : wedge_outward_faces()));
    }
  }
  return v;
}

inline size_t count_of(const io::MeshFile& f, quality::ElementType type) {
  size_t n = 0;
  for (const auto& b : f.blocks) n += b.type == type ? b.size() : 0;
  return n;
}

}  // namespace cooperage::test
