// Exodus II reader (format_readers.h) on the Exodus C API v6.
//
// libnetcdf trusts the file: a damaged 7.8 KB .exo made it allocate 3.1 GB,
// others made it loop (issue 21). Two guards: a classic netCDF header is
// checked against the file size before libnetcdf sees it (netcdf_header.h),
// and the library runs in a forked child with a time and memory limit
// (framework/core/isolate.h; it covers HDF5-based files too), which sends
// the nodes and blocks back.
#include "framework/io/read/format_readers.h"
#include "framework/io/read/netcdf_header.h"
#include "framework/io/read/read_common.h"

#include "framework/core/isolate.h"
#include "framework/core/text.h"

#include <exodusII.h>
#include "framework/io/exodus_lazy.h"  // the library is loaded on first use

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <filesystem>
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
  if (nodes == 8 && is({"HEX", "HEX8", "HEXAHEDRON"}))
    type = ElementType::Hex;
  else if (nodes == 6 && is({"WEDGE", "WEDGE6"}))
    type = ElementType::Wedge;
  else if (nodes == 4 && is({"QUAD", "QUAD4", "SHELL", "SHELL4"}))
    type = ElementType::Quad;
  else if (nodes == 3 && is({"TRI", "TRI3", "TRIANGLE", "SHELL3", "TRISHELL", "TRISHELL3"}))
    type = ElementType::Tri;
  else
    return false;
  return true;
}

/// Counts the file declares must fit in it before anything is allocated:
/// every value takes at least 4 bytes.
void check_fits(const std::string& path, std::uint64_t file_size, int64_t count, int64_t per,
                const char* what) {
  if (count < 0 || per < 0 ||
      (per > 0 &&
       static_cast<std::uint64_t>(count) > file_size / 4 / static_cast<std::uint64_t>(per)))
    parse_error(path, std::string("declares ") + std::to_string(count) + " " + what +
                          ", more than the file can hold");
}

MeshFile read_with_libexodus(const std::string& path, std::uint64_t file_size) {
  ExodusInput f(path);
  ex_init_params init{};
  f.check(ex_get_init_ext(f.id(), &init), "get_init");
  if (init.num_dim < 1 || init.num_dim > 3) {
    parse_error(path, "num_dim " + std::to_string(init.num_dim) + " is not 1, 2 or 3");
  }
  check_fits(path, file_size, init.num_nodes, init.num_dim, "nodes");
  check_fits(path, file_size, init.num_elem_blk, 1, "element blocks");
  const int64_t max_name = ex_inquire_int(f.id(), EX_INQ_DB_MAX_USED_NAME_LENGTH);
  if (max_name > 0)
    ex_set_max_name_length(f.id(), static_cast<int>(std::min<int64_t>(max_name, 255)));

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
    f.check(
        ex_get_block(f.id(), EX_ELEM_BLOCK, id, type_name, &count, &per, &edges, &faces, &attrs),
        "get_block");
    type_name[MAX_STR_LENGTH] = 0;
    ElementType type{};
    if (!element_type(type_name, per, type)) {
      const std::string key =
          clip(upper(type_name), 32) + (per > 0 ? " (" + std::to_string(per) + " nodes)" : "");
      if (count > 0) out.skipped[key] += static_cast<std::size_t>(count);
      continue;
    }
    if (count <= 0) continue;
    check_fits(path, file_size, count, per, "element nodes");
    std::vector<int64_t> conn(static_cast<std::size_t>(count * per));
    f.check(ex_get_conn(f.id(), EX_ELEM_BLOCK, id, conn.data(), nullptr, nullptr), "get_conn");
    std::vector<char> name(256 + 1, 0);
    f.check(ex_get_name(f.id(), EX_ELEM_BLOCK, id, name.data()), "get_name");
    name.back() = 0;
    MeshBlock b;
    b.name = name[0] ? clip(std::string(name.data())) : "block " + std::to_string(id);
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

// ---- the child's answer ----------------------------------------------------------

template <class T>
void put(std::string& out, const T& v) {
  out.append(reinterpret_cast<const char*>(&v), sizeof v);
}
void put_text(std::string& out, const std::string& s) {
  put(out, static_cast<std::uint64_t>(s.size()));
  out += s;
}

std::string serialise(const MeshFile& f) {
  std::string out;
  put(out, static_cast<std::uint64_t>(f.coords.size()));
  for (const auto& p : f.coords) put(out, p);
  put(out, static_cast<std::uint64_t>(f.blocks.size()));
  for (const MeshBlock& b : f.blocks) {
    put_text(out, b.name);
    put(out, static_cast<int>(b.type));
    put(out, static_cast<std::uint64_t>(b.connectivity.size()));
    out.append(reinterpret_cast<const char*>(b.connectivity.data()),
               b.connectivity.size() * sizeof(int));
  }
  put(out, static_cast<std::uint64_t>(f.skipped.size()));
  for (const auto& [type, count] : f.skipped) {
    put_text(out, type);
    put(out, static_cast<std::uint64_t>(count));
  }
  return out;
}

/// Reads what serialise() wrote (in our own child); throws Internal if the
/// bytes run short.
class Payload {
 public:
  explicit Payload(const std::string& s) : s_(s) {}
  template <class T>
  T get() {
    T v;
    take(&v, sizeof v);
    return v;
  }
  std::string text() {
    const auto n = get<std::uint64_t>();
    if (n > s_.size() - pos_) short_payload();
    std::string t = s_.substr(pos_, n);
    pos_ += n;
    return t;
  }
  void take(void* to, std::size_t n) {
    if (n > s_.size() - pos_) short_payload();
    std::memcpy(to, s_.data() + pos_, n);
    pos_ += n;
  }
  std::size_t left() const { return s_.size() - pos_; }

 private:
  [[noreturn]] static void short_payload() {
    throw MeshingError(ErrorCode::Internal, "the Exodus reader's child sent a short answer");
  }
  const std::string& s_;
  std::size_t pos_ = 0;
};

MeshFile deserialise(const std::string& bytes) {
  Payload p(bytes);
  MeshFile f;
  const auto n = p.get<std::uint64_t>();
  if (n > p.left() / sizeof(Eigen::Vector3d))
    throw MeshingError(ErrorCode::Internal, "bad node count from the Exodus reader's child");
  f.coords.resize(n);
  for (auto& c : f.coords) c = p.get<Eigen::Vector3d>();
  const auto blocks = p.get<std::uint64_t>();
  for (std::uint64_t i = 0; i < blocks && p.left() > 0; ++i) {
    MeshBlock b;
    b.name = p.text();
    b.type = static_cast<ElementType>(p.get<int>());
    const auto k = p.get<std::uint64_t>();
    if (k > p.left() / sizeof(int))
      throw MeshingError(ErrorCode::Internal, "bad block size from the Exodus reader's child");
    b.connectivity.resize(k);
    p.take(b.connectivity.data(), k * sizeof(int));
    f.blocks.push_back(std::move(b));
  }
  const auto skipped = p.get<std::uint64_t>();
  for (std::uint64_t i = 0; i < skipped && p.left() > 0; ++i) {
    std::string type = p.text();
    f.skipped[type] = p.get<std::uint64_t>();
  }
  return f;
}

}  // namespace

MeshFile read_exodus(const std::string& path) {
  require_readable_file(path);
  if (check_netcdf_file(path) == NetcdfKind::NotNetcdf)
    parse_error(path, "not an Exodus II file (neither netCDF nor HDF5)");
  std::error_code ec;
  const std::uint64_t size = std::filesystem::file_size(path, ec);
  IsolationLimits limits;
  // Processor time, so a busy machine does not fail a valid file; the wall
  // clock only as a backstop (as for CAD files, framework/geometry/occ/import.cpp).
  limits.cpu_seconds = 30.0 + 10.0 * static_cast<double>(size) / 1e6;
  limits.seconds = 4.0 * limits.cpu_seconds + 60.0;
  limits.memory_bytes = static_cast<std::size_t>(2e9 + 50.0 * static_cast<double>(size));
  const IsolatedRun run = run_isolated(
      [&](std::string& out) { out = serialise(read_with_libexodus(path, size)); }, limits);
  if (run.outcome == IsolatedRun::Outcome::Failed) throw MeshingError(run.code, run.payload);
  if (run.outcome != IsolatedRun::Outcome::Done)
    parse_error(path, "libexodus could not read it (" + run.describe(limits) + ")");
  return deserialise(run.payload);
}

}  // namespace cooperage::io::detail
