#include "framework/io/export/inp_writer.h"

#include "framework/io/export/export_common.h"
#include "framework/io/export/mesh_groups.h"
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

// One *ELEMENT section for a group's elements of one type, over its
// entities in order; records where each entity's elements start.
template <class Rows>
void write_elements(StreamBuffer& out, const char* type, const std::string& elset,
                    const std::vector<int>& entities, const Rows& rows_of,
                    std::map<int, int>& start, int& next_id) {
  size_t count = 0;
  for (int id : entities) count += rows_of(id).size();
  if (count == 0) return;
  out << "*ELEMENT, TYPE=" << type << ", ELSET=" << elset << '\n';
  for (int id : entities) {
    start[id] = next_id;
    for (const auto& e : rows_of(id)) {
      out << next_id++;
      for (int v : e) out << ", " << v + 1;
      out << '\n';
    }
  }
}

}  // namespace

void write_inp(const std::string& path, const mesh::MeshDB& db, const geom::Model& model,
               const ExportOptions& options) {
  detail::validate_mesh(db, model);
  const bool volume_mode = detail::has_volume_elements(db);
  const detail::MeshGroups groups = detail::mesh_groups(db, model, options);
  std::map<int, std::vector<detail::FaceHit>> faces;
  if (volume_mode && !groups.side_sets.empty()) {
    faces =
        detail::surface_faces(db, model, detail::abaqus_hex_faces(), detail::abaqus_wedge_faces());
  }
  detail::write_text_atomically(path, [&](std::ostream& os) {
    StreamBuffer out(os);
    out << "*HEADING\n" << options.title << "\n";
    out << "*NODE\n";
    for (size_t i = 0; i < db.node_count(); ++i) {
      const auto& p = db.node(static_cast<int>(i));
      out << i + 1 << ", " << p.x() << ", " << p.y() << ", " << p.z() << '\n';
    }
    // A block is an *ELSET named after it; a block with two element types
    // has one *ELEMENT set per type ("<name>_C3D8", "<name>_C3D6") and an
    // *ELSET of both under its name.
    int next_id = 1;
    std::map<int, int> first_start, second_start;  // entity -> first element id
    const auto hexes = [&](int id) -> const auto& { return db.volume(id).hexes; };
    const auto wedges = [&](int id) -> const auto& { return db.volume(id).wedges; };
    const auto quads = [&](int id) -> const auto& { return db.surface(id).quads; };
    const auto tris = [&](int id) -> const auto& { return db.surface(id).tris; };
    for (const auto& b : groups.blocks) {
      size_t n_first = 0, n_second = 0;
      for (int id : b.entities) {
        n_first += volume_mode ? db.volume(id).hexes.size() : db.surface(id).quads.size();
        n_second += volume_mode ? db.volume(id).wedges.size() : db.surface(id).tris.size();
      }
      const bool both = n_first > 0 && n_second > 0;
      const char* t1 = volume_mode ? "C3D8" : "S4";
      const char* t2 = volume_mode ? "C3D6" : "S3";
      const std::string set1 = both ? b.name + "_" + t1 : b.name;
      const std::string set2 = both ? b.name + "_" + t2 : b.name;
      if (volume_mode) {
        write_elements(out, t1, set1, b.entities, hexes, first_start, next_id);
        write_elements(out, t2, set2, b.entities, wedges, second_start, next_id);
      } else {
        write_elements(out, t1, set1, b.entities, quads, first_start, next_id);
        write_elements(out, t2, set2, b.entities, tris, second_start, next_id);
      }
      if (both) out << "*ELSET, ELSET=" << b.name << '\n' << set1 << '\n' << set2 << '\n';
    }
    for (const auto& n : groups.node_sets) {
      std::vector<int> nodes = n.nodes;
      for (int& v : nodes) ++v;
      out << "*NSET, NSET=" << n.name << '\n';
      write_ids(out, nodes);
    }
    for (const auto& s : groups.side_sets) {
      std::map<int, std::vector<int>> by_face;  // 0-based face -> element ids
      for (int sid : s.surfaces) {
        const int vid = model.surface(sid).volumes.front();
        for (const auto& h : faces.at(sid)) {
          by_face[h.side].push_back((h.wedge ? second_start.at(vid) : first_start.at(vid)) +
                                    h.element);
        }
      }
      for (const auto& [side, ids] : by_face) {
        out << "*ELSET, ELSET=" << s.name << "_S" << side + 1 << '\n';
        write_ids(out, ids);
      }
      out << "*SURFACE, TYPE=ELEMENT, NAME=" << s.name << '\n';
      for (const auto& [side, ids] : by_face) {
        out << s.name << "_S" << side + 1 << ", S" << side + 1 << '\n';
      }
    }
  });
}

}  // namespace cooperage::io
