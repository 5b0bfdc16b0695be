#include "mesh_arrays.h"

#include "framework/pipeline/quality_report.h"
#include "framework/quality/evaluate.h"

namespace cooperage::python {
namespace {

using quality::ElementType;

std::size_t slot(CellKind kind) { return static_cast<std::size_t>(kind); }

template <std::size_t N>
void append(std::vector<std::int64_t>& out, const std::vector<std::array<int, N>>& elements,
            const std::array<int, N>& order) {
  for (const auto& e : elements) {
    for (std::size_t k = 0; k < N; ++k) out.push_back(e[static_cast<std::size_t>(order[k])]);
  }
}

template <std::size_t N>
void append_quality(std::vector<double>& out, const mesh::MeshDB& db, quality::Metric metric,
                    ElementType type, const std::vector<std::array<int, N>>& elements,
                    const std::vector<Eigen::Vector3d>* normals) {
  if (elements.empty()) return;
  quality::EvaluateOptions options;
  options.normals = normals;
  const auto values = quality::evaluate(metric, type, db.coords(), elements.front().data(),
                                        elements.size(), static_cast<int>(N), options);
  out.insert(out.end(), values.begin(), values.end());
}

}  // namespace

const char* meshio_name(CellKind kind) {
  switch (kind) {
    case CellKind::Hexahedron: return "hexahedron";
    case CellKind::Wedge: return "wedge";
    case CellKind::Quad: return "quad";
    case CellKind::Triangle: return "triangle";
  }
  return "";
}

int corner_count(CellKind kind) {
  switch (kind) {
    case CellKind::Hexahedron: return 8;
    case CellKind::Wedge: return 6;
    case CellKind::Quad: return 4;
    case CellKind::Triangle: return 3;
  }
  return 0;
}

CellArrays cell_arrays(const mesh::MeshDB& db) {
  static constexpr std::array<int, 8> kHex = {0, 1, 2, 3, 4, 5, 6, 7};
  // meshio's linear wedge is Gmsh's prism, which is Exodus's WEDGE6 (not VTK's).
  static constexpr std::array<int, 6> kWedge = {0, 1, 2, 3, 4, 5};
  static constexpr std::array<int, 4> kQuad = {0, 1, 2, 3};
  static constexpr std::array<int, 3> kTri = {0, 1, 2};
  CellArrays out;
  for (const auto& [id, v] : db.volumes()) append(out[slot(CellKind::Hexahedron)], v.hexes, kHex);
  for (const auto& [id, v] : db.volumes()) append(out[slot(CellKind::Wedge)], v.wedges, kWedge);
  for (const auto& [id, s] : db.surfaces()) append(out[slot(CellKind::Quad)], s.quads, kQuad);
  for (const auto& [id, s] : db.surfaces()) append(out[slot(CellKind::Triangle)], s.tris, kTri);
  return out;
}

std::vector<CellSet> cell_sets(const mesh::MeshDB& db) {
  std::array<std::int64_t, 4> next{};
  std::vector<CellSet> sets;
  const auto add = [&](const std::string& name, CellKind kind, std::size_t count) {
    if (count == 0) return;
    CellSet s{name, kind, {}};
    for (std::size_t i = 0; i < count; ++i) s.indices.push_back(next[slot(kind)]++);
    sets.push_back(std::move(s));
  };
  // Same order as cell_arrays(): all hexes first, then all wedges, ...
  for (const auto& [id, v] : db.volumes())
    add("volume " + std::to_string(id), CellKind::Hexahedron, v.hexes.size());
  for (const auto& [id, v] : db.volumes())
    add("volume " + std::to_string(id), CellKind::Wedge, v.wedges.size());
  for (const auto& [id, s] : db.surfaces())
    add("surface " + std::to_string(id), CellKind::Quad, s.quads.size());
  for (const auto& [id, s] : db.surfaces())
    add("surface " + std::to_string(id), CellKind::Triangle, s.tris.size());
  return sets;
}

std::array<std::optional<std::vector<double>>, 4> cell_quality(const mesh::MeshDB& db,
                                                               const geom::Model& model,
                                                               quality::Metric metric) {
  std::array<std::optional<std::vector<double>>, 4> out;
  const std::pair<CellKind, ElementType> kinds[] = {{CellKind::Hexahedron, ElementType::Hex},
                                                    {CellKind::Wedge, ElementType::Wedge},
                                                    {CellKind::Quad, ElementType::Quad},
                                                    {CellKind::Triangle, ElementType::Tri}};
  for (const auto& [kind, type] : kinds) {
    if (quality::is_defined(metric, type)) out[slot(kind)].emplace();
  }
  for (const auto& [id, v] : db.volumes()) {
    if (out[0]) append_quality(*out[0], db, metric, ElementType::Hex, v.hexes, nullptr);
    if (out[1]) append_quality(*out[1], db, metric, ElementType::Wedge, v.wedges, nullptr);
  }
  for (const auto& [id, s] : db.surfaces()) {
    const geom::Surface& surface = model.surface(id);
    if (out[2] && !s.quads.empty()) {
      const auto normals = pipeline::reference_normals(db, surface, s.quads);
      append_quality(*out[2], db, metric, ElementType::Quad, s.quads, &normals);
    }
    if (out[3] && !s.tris.empty()) {
      const auto normals = pipeline::reference_normals(db, surface, s.tris);
      append_quality(*out[3], db, metric, ElementType::Tri, s.tris, &normals);
    }
  }
  return out;
}

}  // namespace cooperage::python
