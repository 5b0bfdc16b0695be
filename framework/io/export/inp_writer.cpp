#include "framework/io/export/inp_writer.h"

#include "framework/io/export/export_common.h"
#include "framework/io/export/stream_buffer.h"

#include <map>
#include <ostream>
#include <vector>

namespace cooperage::io {
namespace {

using detail::StreamBuffer;

/// Writes integers 16 per line, comma separated (no leading blanks: some
/// readers test the first character of a data line).
void write_ids(StreamBuffer& out, const std::vector<int>& ids) {
  for (size_t i = 0; i < ids.size(); ++i) {
    out << ids[i];
    out << std::string_view((i + 1) % 16 == 0 || i + 1 == ids.size() ? "\n" : ", ");
  }
}

template <size_t N>
void write_elements(StreamBuffer& out, const char* type, const std::string& elset,
                    const std::vector<std::array<int, N>>& elems, int& next_id) {
  if (elems.empty()) return;
  out << "*ELEMENT, TYPE=" << type << ", ELSET=" << elset << '\n';
  for (const auto& e : elems) {
    out << next_id++;
    for (int v : e) out << ", " << v + 1;
    out << '\n';
  }
}

}  // namespace

void write_inp(const std::string& path, const mesh::MeshDB& db, const geom::Model& model,
               const ExportOptions& options) {
  detail::validate_mesh(db, model);
  const bool volume_mode = detail::has_volume_elements(db);
  std::map<int, std::vector<detail::FaceHit>> faces;
  if (volume_mode) {
    faces = detail::surface_faces(db, model, detail::abaqus_hex_faces(),
                                  detail::abaqus_wedge_faces());
  }
  detail::write_text_atomically(path, [&](std::ostream& os) {
    StreamBuffer out(os);
    out << "*HEADING\n" << options.title << "\n";
    out << "*NODE\n";
    for (size_t i = 0; i < db.node_count(); ++i) {
      const auto& p = db.node(static_cast<int>(i));
      out << i + 1 << ", " << p.x() << ", " << p.y() << ", " << p.z() << '\n';
    }
    int next_id = 1;
    std::map<int, int> hex_start, wedge_start;
    if (volume_mode) {
      for (const auto& [vid, v] : db.volumes()) {
        const std::string label = detail::volume_label(model, vid);
        const bool both = !v.hexes.empty() && !v.wedges.empty();
        hex_start[vid] = next_id;
        write_elements(out, "C3D8", both ? label + "_C3D8" : label, v.hexes, next_id);
        wedge_start[vid] = next_id;
        write_elements(out, "C3D6", both ? label + "_C3D6" : label, v.wedges, next_id);
        if (both) out << "*ELSET, ELSET=" << label << '\n' << label << "_C3D8\n" << label << "_C3D6\n";
      }
    } else {
      for (const auto& [sid, s] : db.surfaces()) {
        const std::string label = "surface_" + std::to_string(sid);
        write_elements(out, "S4", label, s.quads, next_id);
        write_elements(out, "S3", label, s.tris, next_id);
      }
    }
    for (const auto& [sid, s] : db.surfaces()) {
      if (s.size() == 0) continue;
      std::vector<int> nodes = detail::surface_node_set(s);
      for (int& v : nodes) ++v;
      out << "*NSET, NSET=surface_" << sid << '\n';
      write_ids(out, nodes);
    }
    for (const auto& [sid, hits] : faces) {
      const int vid = model.surface(sid).volumes.front();
      std::map<int, std::vector<int>> by_face;  // 0-based face -> element ids
      for (const auto& h : hits) {
        by_face[h.side].push_back((h.wedge ? wedge_start.at(vid) : hex_start.at(vid)) + h.element);
      }
      const std::string name = "surface_" + std::to_string(sid);
      for (const auto& [side, ids] : by_face) {
        out << "*ELSET, ELSET=" << name << "_S" << side + 1 << '\n';
        write_ids(out, ids);
      }
      out << "*SURFACE, TYPE=ELEMENT, NAME=" << name << '\n';
      for (const auto& [side, ids] : by_face) {
        out << name << "_S" << side + 1 << ", S" << side + 1 << '\n';
      }
    }
  });
}

}  // namespace cooperage::io
