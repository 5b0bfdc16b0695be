#include "framework/io/export/netcdf_classic_data.h"

#include "framework/core/error.h"

#include <cerrno>
#include <cstdint>
#include <cstring>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace cooperage::io::detail {
namespace {

// Header tags and the types the writer puts (netCDF's nc_type values).
constexpr std::uint64_t kDimensionTag = 0x0A, kVariableTag = 0x0B, kAttributeTag = 0x0C;
constexpr int kInt = 4, kFloat = 5, kDouble = 6, kInt64 = 10;

std::size_t type_size(std::uint64_t type) {
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

// A big-endian cursor over the header's bytes; `short_read` once it ran
// past them (the caller reads more of the file and starts again).
class Cursor {
 public:
  Cursor(const std::vector<unsigned char>& bytes, bool wide) : b_(bytes), wide_(wide) {}
  bool short_read() const { return short_; }
  std::uint64_t u32() { return take(4); }
  std::uint64_t u64() { return take(8); }
  std::uint64_t non_neg() { return wide_ ? u64() : u32(); }
  std::string name() {
    const std::uint64_t n = non_neg();
    if (!need(padded(n))) return {};
    std::string s(reinterpret_cast<const char*>(b_.data() + at_), static_cast<std::size_t>(n));
    at_ += static_cast<std::size_t>(padded(n));
    return s;
  }
  void skip(std::uint64_t n) {
    if (need(n)) at_ += static_cast<std::size_t>(n);
  }

 private:
  bool need(std::uint64_t n) {
    if (short_ || n > b_.size() - at_) short_ = true;
    return !short_;
  }
  std::uint64_t take(int n) {
    if (!need(static_cast<std::uint64_t>(n))) return 0;
    std::uint64_t v = 0;
    for (int k = 0; k < n; ++k) v = (v << 8) | b_[at_ + static_cast<std::size_t>(k)];
    at_ += static_cast<std::size_t>(n);
    return v;
  }
  const std::vector<unsigned char>& b_;
  bool wide_;
  std::size_t at_ = 0;
  bool short_ = false;
};

[[noreturn]] void not_classic(const std::string& path, const std::string& why) {
  throw MeshingError(ErrorCode::Internal, "Exodus file '" + path + "': " + why);
}

// The format is big-endian.
std::uint32_t big_endian(std::uint32_t v) {
#if __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
  return __builtin_bswap32(v);
#else
  return v;
#endif
}
std::uint64_t big_endian(std::uint64_t v) {
#if __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
  return __builtin_bswap64(v);
#else
  return v;
#endif
}

// count values as Word (std::uint32_t or std::uint64_t) into out: plain
// loops over words, which the compiler turns into vector byte shuffles.
template <class Word, class Value, class Convert>
void encode(const Value* data, std::size_t count, unsigned char* out, const Convert& convert) {
  for (std::size_t k = 0; k < count; ++k) {
    const Word w = big_endian(convert(data[k]));
    std::memcpy(out + k * sizeof(Word), &w, sizeof(Word));
  }
}

}  // namespace

ClassicDataFile::ClassicDataFile(const std::string& path) : path_(path) {
  fd_ = ::open(path.c_str(), O_RDWR | O_CLOEXEC);
  if (fd_ < 0)
    throw MeshingError(ErrorCode::FileNotFound, "cannot reopen Exodus file '" + path + "'");
  struct stat st {};
  if (::fstat(fd_, &st) != 0) not_classic(path, "cannot stat it");
  const auto file_size = static_cast<std::uint64_t>(st.st_size);
  // The header is read in growing pieces until it parses: Exodus leaves
  // room after it, so the first 64 KB usually hold it all.
  for (std::uint64_t want = 65536;; want *= 2) {
    const std::size_t n = static_cast<std::size_t>(std::min(want, file_size));
    std::vector<unsigned char> bytes(n);
    std::size_t got = 0;
    while (got < n) {
      const ssize_t r = ::pread(fd_, bytes.data() + got, n - got, static_cast<off_t>(got));
      if (r < 0 && errno == EINTR) continue;
      if (r <= 0) not_classic(path, "cannot read its header");
      got += static_cast<std::size_t>(r);
    }
    if (n < 4 || std::memcmp(bytes.data(), "CDF", 3) != 0) not_classic(path, "not classic netCDF");
    const int version = bytes[3];
    if (version != 1 && version != 2 && version != 5)
      not_classic(path, "netCDF format version " + std::to_string(version) + " is not classic");
    Cursor c(bytes, version == 5);
    c.skip(4);
    c.non_neg();  // numrecs
    auto attributes = [&] {
      const std::uint64_t tag = c.u32(), count = c.non_neg();
      if (tag != kAttributeTag && !(tag == 0 && count == 0))
        not_classic(path, "bad attribute list");
      for (std::uint64_t a = 0; a < count && !c.short_read(); ++a) {
        c.name();
        const std::uint64_t type = c.u32(), values = c.non_neg();
        c.skip(padded(values * type_size(type)));
      }
    };
    std::vector<std::uint64_t> dims;
    {
      const std::uint64_t tag = c.u32(), count = c.non_neg();
      if (tag != kDimensionTag && !(tag == 0 && count == 0))
        not_classic(path, "bad dimension list");
      for (std::uint64_t d = 0; d < count && !c.short_read(); ++d) {
        c.name();
        dims.push_back(c.non_neg());
      }
    }
    attributes();
    vars_.clear();
    by_name_.clear();
    const std::uint64_t tag = c.u32(), count = c.non_neg();
    if (!c.short_read() && tag != kVariableTag && !(tag == 0 && count == 0))
      not_classic(path, "bad variable list");
    for (std::uint64_t v = 0; v < count && !c.short_read(); ++v) {
      const std::string name = c.name();
      const std::uint64_t rank = c.non_neg();
      Variable var;
      var.values = 1;
      bool record = false;
      for (std::uint64_t k = 0; k < rank && !c.short_read(); ++k) {
        const std::uint64_t id = c.non_neg();
        if (id >= dims.size()) not_classic(path, "variable " + name + " has an unknown dimension");
        record = record || (k == 0 && dims[id] == 0);  // the unlimited dimension
        var.values *= dims[id];
      }
      attributes();
      var.type = static_cast<int>(c.u32());
      c.non_neg();  // vsize
      var.begin = version == 1 ? c.u32() : c.u64();
      if (record) var.values = 0;  // record variables are not written here
      by_name_[name] = static_cast<int>(vars_.size());
      vars_.push_back(var);
    }
    if (!c.short_read()) break;
    if (n == file_size) not_classic(path, "its header runs past its end");
  }
}

ClassicDataFile::~ClassicDataFile() {
  if (fd_ >= 0) ::close(fd_);
}

int ClassicDataFile::var(const std::string& name) const {
  const auto it = by_name_.find(name);
  if (it == by_name_.end() || vars_[static_cast<std::size_t>(it->second)].values == 0)
    throw MeshingError(ErrorCode::Internal, "Exodus file '" + path_ + "' has no variable " + name);
  return it->second;
}

const ClassicDataFile::Variable& ClassicDataFile::checked(int var, std::size_t first,
                                                          std::size_t rows,
                                                          std::size_t per_row) const {
  const Variable& v = vars_.at(static_cast<std::size_t>(var));
  if ((first + rows) * per_row > v.values)
    throw MeshingError(ErrorCode::Internal,
                       "writing past a variable's end in Exodus file '" + path_ + "'");
  return v;
}

void ClassicDataFile::put(int var, std::size_t first, std::size_t rows, std::size_t per_row,
                          const int* data) const {
  const Variable& v = checked(var, first, rows, per_row);
  const std::size_t count = rows * per_row;
  const int width = v.type == kInt ? 4 : v.type == kInt64 ? 8 : 0;
  if (width == 0)
    not_classic(path_, "integers into a variable of nc_type " + std::to_string(v.type));
  scratch_.resize(count * static_cast<std::size_t>(width));
  if (width == 4) {
    encode<std::uint32_t>(data, count, scratch_.data(),
                          [](int x) { return static_cast<std::uint32_t>(x); });
  } else {
    encode<std::uint64_t>(data, count, scratch_.data(), [](int x) {
      return static_cast<std::uint64_t>(static_cast<std::int64_t>(x));
    });
  }
  write_at(v.begin + first * per_row * static_cast<std::size_t>(width), scratch_.data(),
           scratch_.size());
}

void ClassicDataFile::put(int var, std::size_t first, std::size_t rows, std::size_t per_row,
                          const double* data) const {
  const Variable& v = checked(var, first, rows, per_row);
  const std::size_t count = rows * per_row;
  const int width = v.type == kDouble ? 8 : v.type == kFloat ? 4 : 0;
  if (width == 0) not_classic(path_, "reals into a variable of nc_type " + std::to_string(v.type));
  scratch_.resize(count * static_cast<std::size_t>(width));
  if (width == 8) {
    encode<std::uint64_t>(data, count, scratch_.data(), [](double x) {
      std::uint64_t bits;
      std::memcpy(&bits, &x, 8);
      return bits;
    });
  } else {
    encode<std::uint32_t>(data, count, scratch_.data(), [](double x) {
      const float f = static_cast<float>(x);
      std::uint32_t bits;
      std::memcpy(&bits, &f, 4);
      return bits;
    });
  }
  write_at(v.begin + first * per_row * static_cast<std::size_t>(width), scratch_.data(),
           scratch_.size());
}

void ClassicDataFile::write_at(unsigned long long offset, const void* bytes,
                               std::size_t size) const {
  const auto* p = static_cast<const unsigned char*>(bytes);
  while (size > 0) {
    const ssize_t n = ::pwrite(fd_, p, size, static_cast<off_t>(offset));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0)
      throw MeshingError(ErrorCode::FileNotFound, "writing the Exodus data of '" + path_ +
                                                      "' failed (" +
                                                      std::strerror(n < 0 ? errno : ENOSPC) + ")");
    p += n;
    size -= static_cast<std::size_t>(n);
    offset += static_cast<unsigned long long>(n);
  }
}

void ClassicDataFile::close() {
  const int rc = ::close(fd_);
  fd_ = -1;
  if (rc != 0)
    throw MeshingError(ErrorCode::FileNotFound, "closing Exodus file '" + path_ + "' failed");
}

}  // namespace cooperage::io::detail
