#include "framework/io/export/exodus_writer.h"

#include "framework/core/error.h"
#include "framework/io/export/export_common.h"

#include <exodusII.h>

#include <algorithm>
#include <vector>

namespace cooperage::io {
namespace {

struct Block {
  int id = 0;
  const char* type = "";
  int nodes_per = 0;
  std::vector<int> conn;  // 1-based
  std::string name;
};

struct Set {
  int id = 0;
  std::vector<int> entries;  // 1-based elements or nodes
  std::vector<int> sides;    // side sets only
  std::string name;
};

/// Smallest power of ten >= 1000 exceeding max_id (second-block offset).
int block_offset(int max_id) {
  long long w = 1000;
  while (w <= max_id) w *= 10;
  if (w > 1000000000LL) throw MeshingError(ErrorCode::InvalidInput, "too many entities for Exodus block ids");
  return static_cast<int>(w);
}

template <size_t N>
void append_conn(std::vector<int>& conn, const std::vector<std::array<int, N>>& elems) {
  conn.reserve(conn.size() + elems.size() * N);
  for (const auto& e : elems) {
    for (int v : e) conn.push_back(v + 1);
  }
}

class ExodusFile {
 public:
  ExodusFile(const std::string& tmp) : tmp_(tmp) {
    int cpu_ws = sizeof(double), io_ws = sizeof(double);
    id_ = ex_create(tmp.c_str(), EX_CLOBBER, &cpu_ws, &io_ws);
    if (id_ < 0) {
      throw MeshingError(ErrorCode::FileNotFound,
                         "cannot create Exodus file '" + tmp + "' (does the directory exist?)");
    }
  }
  ~ExodusFile() {
    if (id_ >= 0) ex_close(id_);
  }
  ExodusFile(const ExodusFile&) = delete;
  ExodusFile& operator=(const ExodusFile&) = delete;

  int id() const { return id_; }
  void check(int rc, const char* what) const {
    if (rc < 0) {
      throw MeshingError(ErrorCode::FileNotFound,
                         std::string("Exodus ") + what + " failed writing '" + tmp_ + "'");
    }
  }
  void close() {
    const int rc = ex_close(id_);
    id_ = -1;
    check(rc, "close");
  }

 private:
  std::string tmp_;
  int id_ = -1;
};

void put_names(const ExodusFile& f, ex_entity_type type, const std::vector<std::string>& names) {
  if (names.empty()) return;
  std::vector<char*> ptrs;
  std::vector<std::string> copies = names;
  for (auto& s : copies) ptrs.push_back(s.data());
  f.check(ex_put_names(f.id(), type, ptrs.data()), "put_names");
}

}  // namespace

void write_exodus(const std::string& path, const mesh::MeshDB& db, const geom::Model& model,
                  const ExportOptions& options) {
  detail::validate_mesh(db, model);
  const bool volume_mode = detail::has_volume_elements(db);

  // ---- element blocks ------------------------------------------------------
  std::vector<Block> blocks;
  std::map<int, int> hex_start, wedge_start;  // volume id -> first global element (1-based)
  int next_elem = 1;
  if (volume_mode) {
    const int w = block_offset(static_cast<int>(model.volumes().size()));
    for (const auto& [vid, v] : db.volumes()) {
      const std::string label = detail::volume_label(model, vid);
      if (!v.hexes.empty()) {
        Block b{vid, "HEX8", 8, {}, label};
        append_conn(b.conn, v.hexes);
        hex_start[vid] = next_elem;
        next_elem += static_cast<int>(v.hexes.size());
        blocks.push_back(std::move(b));
      }
      if (!v.wedges.empty()) {
        const bool both = !v.hexes.empty();
        Block b{both ? vid + w : vid, "WEDGE6", 6, {}, both ? label + "_wedge" : label};
        append_conn(b.conn, v.wedges);
        wedge_start[vid] = next_elem;
        next_elem += static_cast<int>(v.wedges.size());
        blocks.push_back(std::move(b));
      }
    }
  } else {
    const int w = block_offset(static_cast<int>(model.surfaces().size()));
    for (const auto& [sid, s] : db.surfaces()) {
      const std::string label = "surface_" + std::to_string(sid);
      if (!s.quads.empty()) {
        Block b{sid, "QUAD4", 4, {}, label};
        append_conn(b.conn, s.quads);
        next_elem += static_cast<int>(s.quads.size());
        blocks.push_back(std::move(b));
      }
      if (!s.tris.empty()) {
        const bool both = !s.quads.empty();
        Block b{both ? sid + w : sid, "TRI3", 3, {}, both ? label + "_tri" : label};
        append_conn(b.conn, s.tris);
        next_elem += static_cast<int>(s.tris.size());
        blocks.push_back(std::move(b));
      }
    }
  }
  const int n_elems = next_elem - 1;

  // ---- side sets (volume meshes) ---------------------------------------------
  std::vector<Set> side_sets;
  if (volume_mode) {
    const auto faces = detail::surface_faces(db, model, detail::exodus_hex_sides(),
                                             detail::exodus_wedge_sides());
    for (const auto& [sid, hits] : faces) {
      const int vid = model.surface(sid).volumes.front();
      Set s{sid, {}, {}, "surface_" + std::to_string(sid)};
      for (const auto& h : hits) {
        s.entries.push_back((h.wedge ? wedge_start.at(vid) : hex_start.at(vid)) + h.element);
        s.sides.push_back(h.side + 1);
      }
      side_sets.push_back(std::move(s));
    }
  }

  // ---- node sets ---------------------------------------------------------------
  std::vector<Set> node_sets;
  for (const auto& [sid, s] : db.surfaces()) {
    if (s.size() == 0) continue;
    Set ns{sid, detail::surface_node_set(s), {}, "surface_" + std::to_string(sid)};
    for (int& n : ns.entries) ++n;
    node_sets.push_back(std::move(ns));
  }

  // ---- write ---------------------------------------------------------------------
  const std::string tmp = detail::temp_path_for(path);
  try {
    ExodusFile f(tmp);
    size_t longest = 0;
    for (const auto& b : blocks) longest = std::max(longest, b.name.size());
    if (longest > 32) {
      f.check(ex_set_option(f.id(), EX_OPT_MAX_NAME_LENGTH, static_cast<int>(longest)),
              "set max name length");
    }
    const std::string title = options.title.substr(0, MAX_LINE_LENGTH);
    f.check(ex_put_init(f.id(), title.c_str(), 3, static_cast<int64_t>(db.node_count()), n_elems,
                        static_cast<int64_t>(blocks.size()),
                        static_cast<int64_t>(node_sets.size()),
                        static_cast<int64_t>(side_sets.size())),
            "put_init");
    // Every definition first, then the bulk data: netCDF classic files move
    // all data written so far each time define mode is re-entered, which
    // made large exports read and rewrite themselves once per block.
    char cx[] = "x", cy[] = "y", cz[] = "z";
    char* coord_names[] = {cx, cy, cz};
    f.check(ex_put_coord_names(f.id(), coord_names), "put_coord_names");
    for (const auto& b : blocks) {
      f.check(ex_put_block(f.id(), EX_ELEM_BLOCK, b.id, b.type,
                           static_cast<int64_t>(b.conn.size()) / b.nodes_per, b.nodes_per, 0, 0, 0),
              "put_block");
    }
    for (const auto& s : side_sets) {
      f.check(ex_put_set_param(f.id(), EX_SIDE_SET, s.id, static_cast<int64_t>(s.entries.size()), 0),
              "put_set_param (side set)");
    }
    for (const auto& s : node_sets) {
      f.check(ex_put_set_param(f.id(), EX_NODE_SET, s.id, static_cast<int64_t>(s.entries.size()), 0),
              "put_set_param (node set)");
    }
    std::vector<std::string> names;
    for (const auto& b : blocks) names.push_back(b.name);
    put_names(f, EX_ELEM_BLOCK, names);
    names.clear();
    for (const auto& s : side_sets) names.push_back(s.name);
    put_names(f, EX_SIDE_SET, names);
    names.clear();
    for (const auto& s : node_sets) names.push_back(s.name);
    put_names(f, EX_NODE_SET, names);

    std::vector<double> x(db.node_count()), y(db.node_count()), z(db.node_count());
    for (size_t i = 0; i < db.node_count(); ++i) {
      const auto& p = db.node(static_cast<int>(i));
      x[i] = p.x();
      y[i] = p.y();
      z[i] = p.z();
    }
    f.check(ex_put_coord(f.id(), x.data(), y.data(), z.data()), "put_coord");
    for (const auto& b : blocks) {
      f.check(ex_put_conn(f.id(), EX_ELEM_BLOCK, b.id, b.conn.data(), nullptr, nullptr),
              "put_conn");
    }
    for (const auto& s : side_sets) {
      f.check(ex_put_set(f.id(), EX_SIDE_SET, s.id, s.entries.data(), s.sides.data()),
              "put_set (side set)");
    }
    for (const auto& s : node_sets) {
      f.check(ex_put_set(f.id(), EX_NODE_SET, s.id, s.entries.data(), nullptr),
              "put_set (node set)");
    }
    f.close();
  } catch (...) {
    detail::remove_temp_file(tmp);
    throw;
  }
  detail::commit_temp_file(tmp, path);
}

}  // namespace cooperage::io
