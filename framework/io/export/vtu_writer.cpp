#include "framework/io/export/vtu_writer.h"

#include "framework/io/export/export_common.h"
#include "framework/io/export/stream_buffer.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cstdint>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace cooperage::io {
namespace {

using detail::StreamBuffer;

// One run of cells of one kind: rows of `per` ints in the MeshDB.
struct Group {
  const int* rows = nullptr;
  size_t count = 0;
  int per = 0;
  const int* order = nullptr;  // VTK position k takes MeshDB node order[k]
  std::uint8_t vtk_type = 0;
  int block = 0, dim = 0;
};

template <size_t N>
void add_group(std::vector<Group>& groups, const std::vector<std::array<int, N>>& rows,
               const int* order, std::uint8_t type, int block, int dim) {
  if (rows.empty()) return;
  groups.push_back(
      {rows.front().data(), rows.size(), static_cast<int>(N), order, type, block, dim});
}

std::vector<Group> collect(const mesh::MeshDB& db, bool with_volumes, bool with_surfaces) {
  static const int kHex[8] = {0, 1, 2, 3, 4, 5, 6, 7};
  static const int kWedge[6] = {0, 2, 1, 3, 5, 4};  // Exodus -> VTK_WEDGE
  static const int kQuad[4] = {0, 1, 2, 3};
  static const int kTri[3] = {0, 1, 2};
  std::vector<Group> g;
  if (with_volumes) {
    for (const auto& [vid, v] : db.volumes()) {
      add_group(g, v.hexes, kHex, 12, vid, 3);
      add_group(g, v.wedges, kWedge, 13, vid, 3);
    }
  }
  if (with_surfaces) {
    for (const auto& [sid, s] : db.surfaces()) {
      add_group(g, s.quads, kQuad, 9, sid, 2);
      add_group(g, s.tris, kTri, 5, sid, 2);
    }
  }
  return g;
}

// Scaled Jacobian of every cell, in cell order; elements are independent,
// so the parallel loop gives the same values for any thread count.
std::vector<double> cell_quality(const std::vector<Group>& groups, const mesh::MeshDB& db) {
  size_t total = 0;
  for (const auto& g : groups) total += g.count;
  std::vector<double> q(total);
  const auto& x = db.coords();
  size_t first = 0;
  for (const auto& g : groups) {
    double* out = q.data() + first;
    tbb::parallel_for(tbb::blocked_range<size_t>(0, g.count, 8192), [&](const auto& r) {
      for (size_t e = r.begin(); e != r.end(); ++e) {
        const int* row = g.rows + e * static_cast<size_t>(g.per);
        switch (g.per) {
          case 8:
            out[e] = detail::scaled_jacobian(*reinterpret_cast<const mesh::Hex*>(row), x);
            break;
          case 6:
            out[e] = detail::scaled_jacobian(*reinterpret_cast<const mesh::Wedge*>(row), x);
            break;
          case 4:
            out[e] = detail::scaled_jacobian(*reinterpret_cast<const mesh::Quad*>(row), x);
            break;
          default:
            out[e] = detail::scaled_jacobian(*reinterpret_cast<const mesh::Tri*>(row), x);
            break;
        }
      }
    });
    first += g.count;
  }
  return q;
}

// Writes one DataArray: ASCII inline (values `per_line` to a line), or the
// raw bytes appended after the XML (the header then only records the offset).
class ArrayWriter {
 public:
  ArrayWriter(StreamBuffer& xml, bool binary) : xml_(xml), binary_(binary) {}

  /// `each(sink)` calls sink(value) for every value in order; `count` values.
  template <class T, class Each>
  void array(const char* type, const char* name, int components, size_t count, int per_line,
             Each each) {
    xml_ << "        <DataArray type=\"" << type << "\" Name=\"" << name << '"';
    if (components > 1) xml_ << " NumberOfComponents=\"" << components << '"';
    if (binary_) {
      xml_ << " format=\"appended\" offset=\"" << offset_ << "\"/>\n";
      offset_ += sizeof(std::uint64_t) + count * sizeof(T);
      appended_.push_back([each, count](StreamBuffer& out) {
        out.raw(static_cast<std::uint64_t>(count * sizeof(T)));
        each([&](T v) { out.raw(v); });
      });
      return;
    }
    xml_ << " format=\"ascii\">\n";
    size_t i = 0;
    const size_t line = static_cast<size_t>(per_line);
    each([&](T v) {
      xml_ << (i % line == 0 ? std::string_view("          ") : std::string_view(" "));
      if constexpr (sizeof(T) == 1) {
        xml_ << static_cast<int>(v);
      } else {
        xml_ << v;
      }
      if (++i % line == 0 || i == count) xml_ << '\n';
    });
    xml_ << "        </DataArray>\n";
  }

  /// The appended block (binary only), after the XML's closing tags.
  void finish() {
    if (!binary_) return;
    xml_ << "  <AppendedData encoding=\"raw\">\n   _";
    for (auto& write : appended_) write(xml_);
    xml_ << "\n  </AppendedData>\n";
  }

 private:
  StreamBuffer& xml_;
  bool binary_;
  std::uint64_t offset_ = 0;
  std::vector<std::function<void(StreamBuffer&)>> appended_;
};

}  // namespace

void write_vtu(const std::string& path, const mesh::MeshDB& db, const geom::Model& model,
               const ExportOptions& options) {
  detail::validate_mesh(db, model);
  const bool volumes = detail::has_volume_elements(db);
  const std::vector<Group> groups = collect(db, volumes, options.include_surfaces || !volumes);
  const std::vector<double> quality = cell_quality(groups, db);
  size_t cells = 0, corners = 0;
  for (const auto& g : groups) {
    cells += g.count;
    corners += g.count * static_cast<size_t>(g.per);
  }
  const auto& x = db.coords();

  // Each cell-wise array walks the groups in order.
  auto for_cells = [&groups](auto&& f) {
    for (const auto& g : groups) {
      for (size_t e = 0; e < g.count; ++e) f(g, g.rows + e * static_cast<size_t>(g.per));
    }
  };

  detail::write_text_atomically(path, [&](std::ostream& os) {
    StreamBuffer out(os);
    ArrayWriter arrays(out, options.binary);
    out << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
           "header_type=\"UInt64\">\n"
        << "  <UnstructuredGrid>\n"
        << "    <Piece NumberOfPoints=\"" << db.node_count() << "\" NumberOfCells=\"" << cells
        << "\">\n"
        << "      <Points>\n";
    arrays.array<double>("Float64", "Points", 3, 3 * x.size(), 3, [&](auto sink) {
      for (const auto& p : x) {
        sink(p.x());
        sink(p.y());
        sink(p.z());
      }
    });
    out << "      </Points>\n      <Cells>\n";
    arrays.array<std::int64_t>("Int64", "connectivity", 1, corners, 8, [&](auto sink) {
      for_cells([&](const Group& g, const int* row) {
        for (int k = 0; k < g.per; ++k) sink(static_cast<std::int64_t>(row[g.order[k]]));
      });
    });
    arrays.array<std::int64_t>("Int64", "offsets", 1, cells, 16, [&](auto sink) {
      std::int64_t end = 0;
      for_cells([&](const Group& g, const int*) { sink(end += g.per); });
    });
    arrays.array<std::uint8_t>("UInt8", "types", 1, cells, 32, [&](auto sink) {
      for_cells([&](const Group& g, const int*) { sink(g.vtk_type); });
    });
    out << "      </Cells>\n      <CellData Scalars=\"scaled_jacobian\">\n";
    arrays.array<std::int32_t>("Int32", "block_id", 1, cells, 16, [&](auto sink) {
      for_cells([&](const Group& g, const int*) { sink(static_cast<std::int32_t>(g.block)); });
    });
    arrays.array<std::int32_t>("Int32", "entity_dim", 1, cells, 32, [&](auto sink) {
      for_cells([&](const Group& g, const int*) { sink(static_cast<std::int32_t>(g.dim)); });
    });
    arrays.array<double>("Float64", "scaled_jacobian", 1, cells, 4, [&](auto sink) {
      for (double q : quality) sink(q);
    });
    out << "      </CellData>\n    </Piece>\n  </UnstructuredGrid>\n";
    arrays.finish();
    out << "</VTKFile>\n";
  });
}

}  // namespace cooperage::io
