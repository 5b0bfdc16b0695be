#include "framework/io/export/vtu_writer.h"

#include "framework/io/export/export_common.h"

#include <ostream>
#include <vector>

namespace cooperage::io {
namespace {

struct Cells {
  std::vector<long long> connectivity;
  std::vector<long long> offsets;
  std::vector<int> types;
  std::vector<int> block_id;
  std::vector<int> dim;
  std::vector<double> quality;

  template <size_t N>
  void add(const std::array<int, N>& e, const int (&order)[N], int type, int block, int d,
           double q) {
    for (int k : order) connectivity.push_back(e[static_cast<size_t>(k)]);
    offsets.push_back(static_cast<long long>(connectivity.size()));
    types.push_back(type);
    block_id.push_back(block);
    dim.push_back(d);
    quality.push_back(q);
  }
};

template <class T>
void write_array(std::ostream& out, const char* type, const char* name, const std::vector<T>& v,
                 int per_line) {
  out << "        <DataArray type=\"" << type << "\" Name=\"" << name << "\" format=\"ascii\">\n";
  for (size_t i = 0; i < v.size(); ++i) {
    out << (i % static_cast<size_t>(per_line) == 0 ? "          " : " ");
    out << v[i];
    if (i + 1 == v.size() || (i + 1) % static_cast<size_t>(per_line) == 0) out << '\n';
  }
  out << "        </DataArray>\n";
}

Cells collect(const mesh::MeshDB& db, bool with_volumes, bool with_surfaces) {
  static const int kHex[8] = {0, 1, 2, 3, 4, 5, 6, 7};
  static const int kWedge[6] = {0, 2, 1, 3, 5, 4};  // Exodus -> VTK_WEDGE
  static const int kQuad[4] = {0, 1, 2, 3};
  static const int kTri[3] = {0, 1, 2};
  const auto& x = db.coords();
  Cells c;
  if (with_volumes) {
    for (const auto& [vid, v] : db.volumes()) {
      for (const auto& h : v.hexes) c.add(h, kHex, 12, vid, 3, detail::scaled_jacobian(h, x));
      for (const auto& w : v.wedges) c.add(w, kWedge, 13, vid, 3, detail::scaled_jacobian(w, x));
    }
  }
  if (with_surfaces) {
    for (const auto& [sid, s] : db.surfaces()) {
      for (const auto& q : s.quads) c.add(q, kQuad, 9, sid, 2, detail::scaled_jacobian(q, x));
      for (const auto& t : s.tris) c.add(t, kTri, 5, sid, 2, detail::scaled_jacobian(t, x));
    }
  }
  return c;
}

}  // namespace

void write_vtu(const std::string& path, const mesh::MeshDB& db, const geom::Model& model,
               const ExportOptions& options) {
  detail::validate_mesh(db, model);
  const bool volumes = detail::has_volume_elements(db);
  const Cells cells = collect(db, volumes, options.include_surfaces || !volumes);
  detail::write_text_atomically(path, [&](std::ostream& out) {
    out.precision(17);
    out << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
           "header_type=\"UInt64\">\n"
        << "  <UnstructuredGrid>\n"
        << "    <Piece NumberOfPoints=\"" << db.node_count() << "\" NumberOfCells=\""
        << cells.types.size() << "\">\n"
        << "      <Points>\n"
        << "        <DataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\" "
           "format=\"ascii\">\n";
    for (const auto& p : db.coords()) {
      out << "          " << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
    }
    out << "        </DataArray>\n      </Points>\n      <Cells>\n";
    write_array(out, "Int64", "connectivity", cells.connectivity, 8);
    write_array(out, "Int64", "offsets", cells.offsets, 16);
    write_array(out, "UInt8", "types", cells.types, 32);
    out << "      </Cells>\n      <CellData Scalars=\"scaled_jacobian\">\n";
    write_array(out, "Int32", "block_id", cells.block_id, 16);
    write_array(out, "Int32", "entity_dim", cells.dim, 32);
    write_array(out, "Float64", "scaled_jacobian", cells.quality, 4);
    out << "      </CellData>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
  });
}

}  // namespace cooperage::io
