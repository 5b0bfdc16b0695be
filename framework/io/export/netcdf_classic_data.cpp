#include "framework/io/export/netcdf_classic_data.h"

#include "framework/core/error.h"
#include "framework/io/read/netcdf_header.h"

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace cooperage::io::detail {
namespace {

// The nc_types the writer puts.
constexpr int kInt = 4, kFloat = 5, kDouble = 6, kInt64 = 10;

[[noreturn]] void not_classic(const std::string& path, const std::string& why) {
  throw MeshingError(ErrorCode::Internal, "Exodus file '" + path + "': " + why);
}

// The format is big-endian.
template <class Word>
Word big_endian(Word v) {
#if __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
  if constexpr (sizeof(Word) == 4) return __builtin_bswap32(v);
  if constexpr (sizeof(Word) == 8) return __builtin_bswap64(v);
#endif
  return v;
}

// count values as Word (std::uint32_t or std::uint64_t) into out: plain
// loops over words, which the compiler turns into vector byte shuffles.
template <class Word, class Value, class Convert>
void encode(const Value* data, std::size_t count, unsigned char* out, const Convert& convert) {
  for (std::size_t k = 0; k < count; ++k) {
    const Word w = big_endian<Word>(convert(data[k]));
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
  // The header, read in growing pieces until the reader's check of it
  // passes: Exodus leaves room after it, so the first 64 KB usually hold it.
  std::vector<NetcdfVariable> variables;
  for (std::uint64_t want = 65536;; want *= 2) {
    const std::size_t n = static_cast<std::size_t>(std::min(want, file_size));
    std::string bytes(n, '\0');
    std::size_t got = 0;
    while (got < n) {
      const ssize_t r = ::pread(fd_, bytes.data() + got, n - got, static_cast<off_t>(got));
      if (r < 0 && errno == EINTR) continue;
      if (r <= 0) not_classic(path, "cannot read its header");
      got += static_cast<std::size_t>(r);
    }
    variables.clear();
    try {
      if (check_netcdf_bytes(path, bytes, file_size, &variables) != NetcdfKind::Classic)
        not_classic(path, "not a classic netCDF file");
      break;
    } catch (const MeshingError&) {
      if (n == file_size) throw;  // the whole file: damaged, not cut short
    }
  }
  for (NetcdfVariable& v : variables) {
    by_name_[v.name] = static_cast<int>(vars_.size());
    vars_.push_back({v.type, v.begin, v.record ? 0 : v.values});
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
