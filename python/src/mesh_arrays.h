// The arrays of a cooperage.Mesh in meshio's conventions, as plain vectors:
// cells per type (hexahedron, wedge, quad, triangle, in meshio's node order:
// VTK's, except the wedge, whose (0,1,2) triangle faces the (3,4,5) one as in
// Gmsh and Exodus, which is also Cooperage's order), cell sets per volume and
// surface, and per-cell quality in the same order.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "framework/geometry/model.h"
#include "framework/mesh/mesh_db.h"
#include "framework/quality/metric.h"

namespace cooperage::python {

enum class CellKind { Hexahedron, Wedge, Quad, Triangle };
inline constexpr CellKind kCellKinds[] = {CellKind::Hexahedron, CellKind::Wedge, CellKind::Quad,
                                          CellKind::Triangle};

/// "hexahedron", "wedge", "quad", "triangle" (meshio's names).
const char* meshio_name(CellKind kind);
/// 8, 6, 4, 3.
int corner_count(CellKind kind);

/// Flat 0-based node indices per kind, corner_count(kind) per cell: the
/// hexes of every volume in id order, then the wedges likewise, the quads
/// of every surface in id order, then the triangles.
using CellArrays = std::array<std::vector<std::int64_t>, 4>;
CellArrays cell_arrays(const mesh::MeshDB& db);

/// The cells of one entity of one kind: indices into that kind's array.
struct CellSet {
  std::string name;  ///< "volume 2", "surface 12"
  CellKind kind;
  std::vector<std::int64_t> indices;
};
/// Volumes then surfaces, in id order; only non-empty sets.
std::vector<CellSet> cell_sets(const mesh::MeshDB& db);

/// `metric` per cell in the order of cell_arrays(); std::nullopt for a kind
/// the metric is not defined for (quality::is_defined). Surface cells are
/// signed against their CAD surface (as the run's quality report does).
std::array<std::optional<std::vector<double>>, 4> cell_quality(const mesh::MeshDB& db,
                                                               const geom::Model& model,
                                                               quality::Metric metric);

}  // namespace cooperage::python
