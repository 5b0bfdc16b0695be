#include "framework/io/read/netcdf_header.h"

#include "framework/io/read/read_common.h"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <limits>
#include <utility>
#include <vector>

namespace cooperage::io::detail {
namespace {

constexpr std::uint32_t kDimensionTag = 0x0A;
constexpr std::uint32_t kVariableTag = 0x0B;
constexpr std::uint32_t kAttributeTag = 0x0C;
constexpr std::uint64_t kMaxName = 256;  // NC_MAX_NAME
constexpr std::uint64_t kStreaming = 0xFFFFFFFFull;

std::uint64_t type_size(std::uint32_t type) {
  switch (type) {
    case 1:
    case 2:
    case 7: return 1;  // byte, char, ubyte
    case 3:
    case 8: return 2;  // short, ushort
    case 4:
    case 5:
    case 9: return 4;  // int, float, uint
    case 6:
    case 10:
    case 11: return 8;  // double, int64, uint64
    default: return 0;
  }
}

std::uint64_t padded(std::uint64_t n) { return (n + 3) / 4 * 4; }

/// Sequential big-endian reader over the header bytes.
class Header {
 public:
  Header(const std::string& path, const std::string& bytes, std::uint64_t file_size)
      : path_(path), s_(bytes), file_size_(file_size) {}

  [[noreturn]] void fail(const std::string& why) const {
    parse_error(path_, "damaged netCDF header at byte " + std::to_string(pos_) + ": " + why);
  }
  std::uint64_t pos() const { return pos_; }
  std::uint64_t left() const { return file_size_ - pos_; }

  std::uint64_t uint(int bytes) {
    if (pos_ + static_cast<std::uint64_t>(bytes) > s_.size())
      fail("the file ends inside the header");
    std::uint64_t v = 0;
    for (int i = 0; i < bytes; ++i)
      v = (v << 8) | static_cast<unsigned char>(s_[pos_ + static_cast<std::uint64_t>(i)]);
    pos_ += static_cast<std::uint64_t>(bytes);
    return v;
  }
  void skip(std::uint64_t n) {
    if (n > s_.size() - pos_) fail("the file ends inside the header");
    pos_ += n;
  }
  /// A count of items of at least `min_bytes` each that must fit in the rest.
  std::uint64_t count(int bytes, std::uint64_t min_bytes, const char* what) {
    const std::uint64_t n = uint(bytes);
    if (n > left() / std::max<std::uint64_t>(min_bytes, 1))
      fail(std::string(what) + " count " + std::to_string(n) + " does not fit in the file");
    return n;
  }
  std::string name(int count_bytes) {
    const std::uint64_t n = uint(count_bytes);
    if (n == 0 || n > kMaxName) fail("a name of " + std::to_string(n) + " bytes");
    const std::uint64_t at = pos_;
    skip(padded(n));
    return s_.substr(static_cast<std::size_t>(at), static_cast<std::size_t>(n));
  }

 private:
  const std::string& path_;
  const std::string& s_;
  std::uint64_t file_size_;
  std::uint64_t pos_ = 0;
};

/// a * b, or false on 64-bit overflow.
bool multiply(std::uint64_t a, std::uint64_t b, std::uint64_t& out) {
  if (a != 0 && b > std::numeric_limits<std::uint64_t>::max() / a) return false;
  out = a * b;
  return true;
}

void attributes(Header& h, int nb) {
  const std::uint32_t tag = static_cast<std::uint32_t>(h.uint(4));
  const std::uint64_t n = h.count(nb, 12, "attribute");
  if (tag == 0) {
    if (n != 0) h.fail("an absent attribute list with a count");
    return;
  }
  if (tag != kAttributeTag) h.fail("expected an attribute list");
  for (std::uint64_t i = 0; i < n; ++i) {
    h.name(nb);
    const std::uint64_t size = type_size(static_cast<std::uint32_t>(h.uint(4)));
    if (size == 0) h.fail("an attribute of unknown type");
    const std::uint64_t values = h.uint(nb);
    std::uint64_t bytes = 0;
    if (!multiply(values, size, bytes) || padded(bytes) > h.left())
      h.fail("an attribute of " + std::to_string(values) + " values does not fit in the file");
    h.skip(padded(bytes));
  }
}

NetcdfKind check_classic(const std::string& path, const std::string& bytes, std::uint64_t file_size,
                         std::vector<NetcdfVariable>* variables) {
  Header h(path, bytes, file_size);
  h.skip(3);
  const auto version = h.uint(1);
  if (version != 1 && version != 2 && version != 5)
    h.fail("unknown netCDF version " + std::to_string(version));
  const int nb = version == 5 ? 8 : 4;  // counts and sizes
  const int offset_bytes = version == 1 ? 4 : 8;
  std::uint64_t records = h.uint(nb);
  if (nb == 4 && records == kStreaming) records = 0;  // streaming: unknown, the data decides

  // Dimensions: a name and a length (0: the record dimension).
  std::vector<std::uint64_t> dims;
  const std::uint32_t dim_tag = static_cast<std::uint32_t>(h.uint(4));
  const std::uint64_t n_dims = h.count(nb, 8, "dimension");
  if (dim_tag != 0 && dim_tag != kDimensionTag) h.fail("expected a dimension list");
  if (dim_tag == 0 && n_dims != 0) h.fail("an absent dimension list with a count");
  int record_dim = -1;
  for (std::uint64_t i = 0; i < n_dims; ++i) {
    h.name(nb);
    const std::uint64_t length = h.uint(nb);
    if (length == 0) {
      if (record_dim >= 0) h.fail("two record dimensions");
      record_dim = static_cast<int>(i);
    }
    dims.push_back(length);
  }
  attributes(h, nb);  // global attributes

  const std::uint32_t var_tag = static_cast<std::uint32_t>(h.uint(4));
  const std::uint64_t n_vars = h.count(nb, 24, "variable");
  if (var_tag != 0 && var_tag != kVariableTag) h.fail("expected a variable list");
  if (var_tag == 0 && n_vars != 0) h.fail("an absent variable list with a count");
  struct Var {
    std::uint64_t begin, size;
    bool record;
  };
  std::vector<Var> vars;
  std::uint64_t record_size = 0;
  for (std::uint64_t i = 0; i < n_vars; ++i) {
    std::string name = h.name(nb);
    const std::uint64_t rank = h.count(nb, 4, "dimension id");
    std::uint64_t elements = 1;
    bool record = false;
    for (std::uint64_t r = 0; r < rank; ++r) {
      const std::uint64_t id = h.uint(nb);
      if (id >= dims.size())
        h.fail("a variable uses dimension " + std::to_string(id) + " of " +
               std::to_string(dims.size()));
      if (static_cast<int>(id) == record_dim) {
        if (r != 0) h.fail("the record dimension is not a variable's first");
        record = true;
        continue;
      }
      if (!multiply(elements, dims[id], elements)) h.fail("a variable's size overflows");
    }
    attributes(h, nb);
    const auto type = static_cast<std::uint32_t>(h.uint(4));
    const std::uint64_t size = type_size(type);
    if (size == 0) h.fail("a variable of unknown type");
    h.uint(nb);  // vsize: redundant, and wrong by design for huge variables
    const std::uint64_t begin = h.uint(offset_bytes);
    std::uint64_t var_bytes = 0;
    if (!multiply(elements, size, var_bytes)) h.fail("a variable's size overflows");
    if (record) {
      // A record variable of one byte or one short is not padded when it is alone.
      if (record_size > std::numeric_limits<std::uint64_t>::max() - padded(var_bytes))
        h.fail("the record size overflows");
      record_size += padded(var_bytes);
    }
    vars.push_back({begin, var_bytes, record});
    if (variables)
      variables->push_back({std::move(name), static_cast<int>(type), begin, elements, record});
  }
  const std::uint64_t header_end = h.pos();
  for (const Var& v : vars) {
    if (v.begin < header_end) h.fail("a variable's data starts inside the header");
    std::uint64_t extent = v.size;
    if (v.record && records > 0) {
      std::uint64_t all = 0;
      if (!multiply(records - 1, record_size, all) || all > file_size)
        h.fail("the records do not fit in the file");
      extent = all + v.size;
    } else if (v.record) {
      extent = 0;
    }
    if (v.begin > file_size || extent > file_size - v.begin)
      parse_error(path, "damaged netCDF file: a variable's data (" + std::to_string(extent) +
                            " bytes at byte " + std::to_string(v.begin) +
                            ") lies beyond its end (" + std::to_string(file_size) + " bytes)");
  }
  return NetcdfKind::Classic;
}

}  // namespace

NetcdfKind check_netcdf_bytes(const std::string& path, const std::string& bytes,
                              std::uint64_t file_size, std::vector<NetcdfVariable>* variables) {
  if (bytes.size() >= 8 && std::memcmp(bytes.data(), "\x89HDF\r\n\x1a\n", 8) == 0)
    return NetcdfKind::Hdf5;
  if (bytes.size() < 4 || std::memcmp(bytes.data(), "CDF", 3) != 0) return NetcdfKind::NotNetcdf;
  return check_classic(path, bytes, std::max<std::uint64_t>(file_size, bytes.size()), variables);
}

NetcdfKind check_netcdf_file(const std::string& path) {
  require_readable_file(path);
  std::ifstream in(path, std::ios::binary);
  if (!in) parse_error(path, "cannot be read");
  in.seekg(0, std::ios::end);
  const auto end = in.tellg();
  const std::uint64_t size = end > 0 ? static_cast<std::uint64_t>(end) : 0;
  in.seekg(0);
  // The header is at the front; netCDF writers keep it well under this. A
  // header longer than what is read fails as "ends inside the header".
  const std::uint64_t want = std::min<std::uint64_t>(size, 64ull << 20);
  std::string bytes(static_cast<std::size_t>(want), '\0');
  in.read(bytes.data(), static_cast<std::streamsize>(want));
  bytes.resize(static_cast<std::size_t>(in.gcount()));
  return check_netcdf_bytes(path, bytes, size);
}

}  // namespace cooperage::io::detail
