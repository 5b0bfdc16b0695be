#include "framework/io/export/exodus_writer.h"

#include "framework/core/error.h"
#include "framework/io/export/export_common.h"
#include "framework/io/export/mesh_groups.h"
#include "framework/io/export/netcdf_classic_data.h"

#include <exodusII.h>
#include "framework/io/exodus_lazy.h"  // the library is loaded on first use
#include <netcdf.h>

#include <algorithm>
#include <cstddef>
#include <map>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace cooperage::io {
namespace {

// An element block: its 0-based connectivity rows stay in the MeshDB (one
// run of rows per entity of the block) and are written 1-based in chunks (a
// whole 1-based copy was 32 bytes per hex).
struct Block {
  int id = 0;
  const char* type = "";
  int nodes_per = 0;
  std::vector<std::pair<const int*, size_t>> runs;  // rows, count; 0-based
  size_t count = 0;
  std::string name;
};

// Elements or nodes converted per netCDF call: bounded scratch memory,
// calls large enough to stream.
constexpr size_t kChunk = 1 << 16;

// Room left in the netCDF header for the definitions made after ex_create
// (blocks, sets, names). A classic netCDF file moves all variable data each
// time define mode is left with a header that outgrew the space before the
// data; reserving it up front makes every later definition in place (issue
// 20: a 1 M-hex export read 4.25 GB and wrote 2.15 GB for a 46 MB file).
size_t header_reserve(size_t blocks, size_t sets, size_t longest_name) {
  return 65536 + (blocks + sets) * (1024 + 2 * longest_name);
}

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
  if (w > 1000000000LL)
    throw MeshingError(ErrorCode::InvalidInput, "too many entities for Exodus block ids");
  return static_cast<int>(w);
}

template <size_t N>
void add_run(Block& b, const std::vector<std::array<int, N>>& elems) {
  static_assert(sizeof(std::array<int, N>) == N * sizeof(int), "rows are contiguous ints");
  if (elems.empty()) return;
  b.nodes_per = static_cast<int>(N);
  b.runs.emplace_back(elems.front().data(), elems.size());
  b.count += elems.size();
}

class ExodusFile {
 public:
  ExodusFile(const std::string& tmp, bool netcdf4) : tmp_(tmp) {
    int cpu_ws = sizeof(double), io_ws = sizeof(double);
    id_ = ex_create(tmp.c_str(), EX_CLOBBER | EX_LARGE_MODEL | (netcdf4 ? EX_NETCDF4 : 0), &cpu_ws,
                    &io_ws);
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
  const std::string& path() const { return tmp_; }
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

// The bulk data of a netCDF-4 file goes straight through netCDF on the file
// Exodus defined, reopened (a classic file's is written by ClassicDataFile:
// through netCDF it was read back before it was written). nc__open's buffer
// size hint is kept for classic files opened here (Exodus's own 8 KB
// buffer cost a read, two seeks and a write per 8 KB page); the file's
// bytes do not depend on it. Variable names are Exodus II's (large model,
// which ex_create is asked for).
class NetcdfData {
 public:
  explicit NetcdfData(const std::string& path) : path_(path) {
    size_t buffer = kBuffer;
    if (nc__open(path.c_str(), NC_WRITE, &buffer, &id_) != NC_NOERR) {
      id_ = -1;
      throw MeshingError(ErrorCode::FileNotFound, "cannot reopen Exodus file '" + path + "'");
    }
  }
  ~NetcdfData() {
    if (id_ >= 0) nc_close(id_);
  }
  NetcdfData(const NetcdfData&) = delete;
  NetcdfData& operator=(const NetcdfData&) = delete;

  int var(const std::string& name) const {
    int v = -1;
    if (nc_inq_varid(id_, name.c_str(), &v) != NC_NOERR) {
      throw MeshingError(ErrorCode::Internal,
                         "Exodus file '" + path_ + "' has no variable " + name);
    }
    return v;
  }
  template <class T>
  void put(int var, size_t first, size_t rows, size_t per_row, const T* data) const {
    const size_t start[2] = {first, 0}, extent[2] = {rows, per_row};
    int rc;
    if constexpr (std::is_same_v<T, double>) {
      rc = nc_put_vara_double(id_, var, start, extent, data);
    } else {
      rc = nc_put_vara_int(id_, var, start, extent, data);
    }
    if (rc != NC_NOERR) {
      throw MeshingError(ErrorCode::FileNotFound,
                         "writing the Exodus data of '" + path_ + "' failed");
    }
  }
  void close() {
    const int rc = nc_close(id_);
    id_ = -1;
    if (rc != NC_NOERR)
      throw MeshingError(ErrorCode::FileNotFound, "closing Exodus file '" + path_ + "' failed");
  }

 private:
  static constexpr size_t kBuffer = size_t{4} << 20;  // 4 MB
  std::string path_;
  int id_ = -1;
};

// Connectivity of the `index`-th block defined (1-based, Exodus's variable
// "connect<index>"), written 1-based in chunks.
template <class DataFile>
void put_connectivity(const DataFile& f, const Block& b, size_t index) {
  const int var = f.var("connect" + std::to_string(index));
  const size_t per = static_cast<size_t>(b.nodes_per);
  std::vector<int> buf(std::min(b.count, kChunk) * per);
  size_t written = 0;
  for (const auto& [rows, count] : b.runs) {
    for (size_t first = 0; first < count; first += kChunk) {
      const size_t n = std::min(kChunk, count - first);
      const int* src = rows + first * per;
      for (size_t k = 0; k < n * per; ++k) buf[k] = src[k] + 1;
      f.put(var, written, n, per, buf.data());
      written += n;
    }
  }
}

// Coordinates one component at a time, in chunks (no x/y/z copies of the mesh).
template <class DataFile>
void put_coordinates(const DataFile& f, const mesh::MeshDB& db) {
  const size_t n = db.node_count();
  const auto& x = db.coords();
  std::vector<double> buf(std::min(n, kChunk));
  const char* const names[3] = {"coordx", "coordy", "coordz"};
  for (int c = 0; c < 3; ++c) {
    const int var = f.var(names[c]);
    for (size_t first = 0; first < n; first += kChunk) {
      const size_t m = std::min(kChunk, n - first);
      for (size_t k = 0; k < m; ++k) buf[k] = x[first + k][c];
      f.put(var, first, m, 1, buf.data());
    }
  }
}

// A set's entries (and sides) into its Exodus variables, 1-based `index`.
template <class DataFile>
void put_set(const DataFile& f, const Set& s, size_t index, bool side_set) {
  const std::string k = std::to_string(index);
  if (s.entries.empty()) return;
  f.put(f.var((side_set ? "elem_ss" : "node_ns") + k), 0, s.entries.size(), 1, s.entries.data());
  if (side_set) f.put(f.var("side_ss" + k), 0, s.sides.size(), 1, s.sides.data());
}

}  // namespace

void write_exodus(const std::string& path, const mesh::MeshDB& db, const geom::Model& model,
                  const ExportOptions& options) {
  detail::validate_mesh(db, model);
  const bool volume_mode = detail::has_volume_elements(db);

  const detail::MeshGroups groups = detail::mesh_groups(db, model, options);

  // ---- element blocks ------------------------------------------------------
  // A group's elements of the first kind (hex / quad) form a block with the
  // group's id; those of the second (wedge / tri) one with the id, or, when
  // the group has both, id + W named "<name>_wedge" / "<name>_tri".
  std::vector<Block> blocks;
  std::map<std::pair<int, bool>, int> start;  // (entity, second kind) -> first element (1-based)
  int next_elem = 1;
  int max_id = 0;
  for (const auto& g : groups.blocks) max_id = std::max(max_id, g.id);
  const int w = block_offset(max_id);
  for (const auto& g : groups.blocks) {
    Block first{g.id, volume_mode ? "HEX8" : "QUAD4", 0, {}, 0, g.name};
    Block second{g.id, volume_mode ? "WEDGE" : "TRI3", 0, {}, 0, g.name};
    for (int id : g.entities) {
      start[{id, false}] = next_elem + static_cast<int>(first.count);
      if (volume_mode)
        add_run(first, db.volume(id).hexes);
      else
        add_run(first, db.surface(id).quads);
    }
    next_elem += static_cast<int>(first.count);
    for (int id : g.entities) {
      start[{id, true}] = next_elem + static_cast<int>(second.count);
      if (volume_mode)
        add_run(second, db.volume(id).wedges);
      else
        add_run(second, db.surface(id).tris);
    }
    next_elem += static_cast<int>(second.count);
    if (first.count > 0 && second.count > 0) {
      second.id = g.id + w;
      second.name = g.name + (volume_mode ? "_wedge" : "_tri");
    }
    if (first.count > 0) blocks.push_back(std::move(first));
    if (second.count > 0) blocks.push_back(std::move(second));
  }
  const int n_elems = next_elem - 1;

  // ---- side sets (volume meshes) ---------------------------------------------
  std::vector<Set> side_sets;
  if (volume_mode && !groups.side_sets.empty()) {
    const auto faces =
        detail::surface_faces(db, model, detail::exodus_hex_sides(), detail::exodus_wedge_sides());
    for (const auto& g : groups.side_sets) {
      Set s{g.id, {}, {}, g.name};
      for (int sid : g.surfaces) {
        const int vid = model.surface(sid).volumes.front();
        for (const auto& h : faces.at(sid)) {
          s.entries.push_back(start.at({vid, h.wedge}) + h.element);
          s.sides.push_back(h.side + 1);
        }
      }
      side_sets.push_back(std::move(s));
    }
  }

  // ---- node sets ---------------------------------------------------------------
  std::vector<Set> node_sets;
  for (const auto& g : groups.node_sets) {
    Set ns{g.id, g.nodes, {}, g.name};
    for (int& n : ns.entries) ++n;
    node_sets.push_back(std::move(ns));
  }

  // ---- write ---------------------------------------------------------------------
  // One pass: every definition first (into a header with room reserved for
  // them), then the bulk data in file order.
  const std::string tmp = detail::temp_path_for(path);
  try {
    ExodusFile f(tmp, options.exodus_netcdf4);
    size_t longest = 0;
    for (const auto& b : blocks) longest = std::max(longest, b.name.size());
    for (const auto& s : side_sets) longest = std::max(longest, s.name.size());
    if (longest > 32) {
      f.check(ex_set_option(f.id(), EX_OPT_MAX_NAME_LENGTH, static_cast<int>(longest)),
              "set max name length");
    }
    if (!options.exodus_netcdf4) {
      // netCDF ignores the room asked for while a file has no variable yet,
      // and then each later definition moves all the data allocated so far,
      // 8 KB at a time (a 1 M-hex file read 221 MB and wrote 140 MB). An
      // info record (a standard Exodus variable naming the writer) comes
      // first, so the room is kept and every later definition fits.
      char info_line[] = "written by Cooperage";
      char* info[] = {info_line};
      f.check(ex_put_info(f.id(), 1, info), "put_info");
      const size_t room =
          header_reserve(blocks.size(), side_sets.size() + node_sets.size(), longest);
      f.check(nc_redef(f.id()) == NC_NOERR ? 0 : -1, "redef");
      f.check(nc__enddef(f.id(), room, 4, 0, 4) == NC_NOERR ? 0 : -1, "reserve header");
    }
    const std::string title = options.title.substr(0, MAX_LINE_LENGTH);
    f.check(ex_put_init(f.id(), title.c_str(), 3, static_cast<int64_t>(db.node_count()), n_elems,
                        static_cast<int64_t>(blocks.size()), static_cast<int64_t>(node_sets.size()),
                        static_cast<int64_t>(side_sets.size())),
            "put_init");
    char cx[] = "x", cy[] = "y", cz[] = "z";
    char* coord_names[] = {cx, cy, cz};
    f.check(ex_put_coord_names(f.id(), coord_names), "put_coord_names");
    for (const auto& b : blocks) {
      f.check(ex_put_block(f.id(), EX_ELEM_BLOCK, b.id, b.type, static_cast<int64_t>(b.count),
                           b.nodes_per, 0, 0, 0),
              "put_block");
    }
    // All sets defined in one call (one define-mode session).
    std::vector<ex_set> defs;
    for (const auto& s : side_sets) {
      defs.push_back(ex_set{s.id, EX_SIDE_SET, static_cast<int64_t>(s.entries.size()), 0, nullptr,
                            nullptr, nullptr});
    }
    for (const auto& s : node_sets) {
      defs.push_back(ex_set{s.id, EX_NODE_SET, static_cast<int64_t>(s.entries.size()), 0, nullptr,
                            nullptr, nullptr});
    }
    if (!defs.empty()) f.check(ex_put_sets(f.id(), defs.size(), defs.data()), "put_sets");
    std::vector<std::string> names;
    for (const auto& b : blocks) names.push_back(b.name);
    put_names(f, EX_ELEM_BLOCK, names);
    names.clear();
    for (const auto& s : side_sets) names.push_back(s.name);
    put_names(f, EX_SIDE_SET, names);
    names.clear();
    for (const auto& s : node_sets) names.push_back(s.name);
    put_names(f, EX_NODE_SET, names);

    f.close();
    auto put_data = [&](auto& data) {
      put_coordinates(data, db);
      for (size_t i = 0; i < blocks.size(); ++i) put_connectivity(data, blocks[i], i + 1);
      for (size_t i = 0; i < side_sets.size(); ++i) put_set(data, side_sets[i], i + 1, true);
      for (size_t i = 0; i < node_sets.size(); ++i) put_set(data, node_sets[i], i + 1, false);
      data.close();
    };
    if (options.exodus_netcdf4) {
      NetcdfData data(tmp);
      put_data(data);
    } else {
      detail::ClassicDataFile data(tmp);
      put_data(data);
    }
  } catch (...) {
    detail::remove_temp_file(tmp);
    throw;
  }
  detail::commit_temp_file(tmp, path);
}

void load_exodus_library() { exodus_lazy::api(); }

}  // namespace cooperage::io
