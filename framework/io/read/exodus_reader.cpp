// Exodus II reader (format_readers.h) on the Exodus C API v6.
#include "framework/io/read/format_readers.h"
#include "framework/io/read/read_common.h"

#include <exodusII.h>
#include "framework/io/exodus_lazy.h"  // the library is loaded on first use

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <string>
#include <vector>

namespace cooperage::io::detail {
namespace {

using quality::ElementType;

/// Closes the file on every path out of read_exodus().
class ExodusInput {
 public:
  explicit ExodusInput(const std::string& path) : path_(path) {
    int cpu_ws = sizeof(double);
    int io_ws = 0;
    float version = 0;
    id_ = ex_open(path.c_str(), EX_READ, &cpu_ws, &io_ws, &version);
    if (id_ < 0) parse_error(path, "not an Exodus II file (ex_open failed)");
    ex_set_int64_status(id_, EX_ALL_INT64_API);
  }
  ~ExodusInput() { ex_close(id_); }
  ExodusInput(const ExodusInput&) = delete;
  ExodusInput& operator=(const ExodusInput&) = delete;

  int id() const { return id_; }
  void check(int rc, const char* what) const {
    if (rc < 0) parse_error(path_, std::string("Exodus ") + what + " failed");
  }

 private:
  std::string path_;
  int id_ = -1;
};

std::string upper(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  return s;
}

/// The element type of an Exodus block (type name, nodes per element), or
/// false for one the quality report does not cover.
bool element_type(const std::string& name, int64_t nodes, ElementType& type) {
  const std::string n = upper(name);
  auto is = [&](std::initializer_list<const char*> names) {
    return std::find(names.begin(), names.end(), n) != names.end();
  };
  if (nodes == 8 && is({"HEX", "HEX8", "HEXAHEDRON"})) type = ElementType::Hex;
  else if (nodes == 6 && is({"WEDGE", "WEDGE6"})) type = ElementType::Wedge;
  else if (nodes == 4 && is({"QUAD", "QUAD4", "SHELL", "SHELL4"})) type = ElementType::Quad;
  else if (nodes == 3 && is({"TRI", "TRI3", "TRIANGLE", "SHELL3", "TRISHELL", "TRISHELL3"}))
    type = ElementType::Tri;
  else return false;
  return true;
}

}  // namespace

MeshFile read_exodus(const std::string& path) {
  require_file(path);
  ExodusInput f(path);
  ex_init_params init{};
  f.check(ex_get_init_ext(f.id(), &init), "get_init");
  if (init.num_dim < 1 || init.num_dim > 3) {
    parse_error(path, "num_dim " + std::to_string(init.num_dim) + " is not 1, 2 or 3");
  }
  const int64_t max_name = ex_inquire_int(f.id(), EX_INQ_DB_MAX_USED_NAME_LENGTH);
  if (max_name > 0) ex_set_max_name_length(f.id(), static_cast<int>(max_name));

  MeshFile out;
  const auto n = static_cast<std::size_t>(init.num_nodes);
  std::vector<double> x(n, 0.0), y(n, 0.0), z(n, 0.0);
  if (n > 0) {
    f.check(ex_get_coord(f.id(), x.data(), init.num_dim > 1 ? y.data() : nullptr,
                         init.num_dim > 2 ? z.data() : nullptr),
            "get_coord");
  }
  out.coords.reserve(n);
  for (std::size_t i = 0; i < n; ++i) out.coords.emplace_back(x[i], y[i], z[i]);

  std::vector<int64_t> ids(static_cast<std::size_t>(init.num_elem_blk));
  if (!ids.empty()) f.check(ex_get_ids(f.id(), EX_ELEM_BLOCK, ids.data()), "get_ids");
  for (int64_t id : ids) {
    char type_name[MAX_STR_LENGTH + 1] = {0};
    int64_t count = 0, per = 0, edges = 0, faces = 0, attrs = 0;
    f.check(ex_get_block(f.id(), EX_ELEM_BLOCK, id, type_name, &count, &per, &edges, &faces,
                         &attrs),
            "get_block");
    ElementType type{};
    if (!element_type(type_name, per, type)) {
      const std::string key = upper(type_name) + (per > 0 ? " (" + std::to_string(per) + " nodes)" : "");
      if (count > 0) out.skipped[key] += static_cast<std::size_t>(count);
      continue;
    }
    if (count <= 0) continue;
    std::vector<int64_t> conn(static_cast<std::size_t>(count * per));
    f.check(ex_get_conn(f.id(), EX_ELEM_BLOCK, id, conn.data(), nullptr, nullptr), "get_conn");
    std::vector<char> name(static_cast<std::size_t>(std::max<int64_t>(max_name, MAX_STR_LENGTH)) + 1, 0);
    f.check(ex_get_name(f.id(), EX_ELEM_BLOCK, id, name.data()), "get_name");
    MeshBlock b;
    b.name = name[0] ? std::string(name.data()) : "block " + std::to_string(id);
    b.type = type;
    b.connectivity.reserve(conn.size());
    for (int64_t v : conn) {
      if (v < 1 || v > init.num_nodes) {
        parse_error(path, "element block " + std::to_string(id) + " uses node " +
                              std::to_string(v) + " (nodes are 1.." +
                              std::to_string(init.num_nodes) + ")");
      }
      b.connectivity.push_back(static_cast<int>(v - 1));
    }
    out.blocks.push_back(std::move(b));
  }
  return out;
}

}  // namespace cooperage::io::detail
