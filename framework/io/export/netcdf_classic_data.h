// The bulk data of a classic netCDF file (CDF-1, CDF-2 or CDF-5), written
// straight to the offsets its header gives each variable, big-endian as
// the format stores them (netCDF's "File Format Specification").
//
// Why not nc_put_vara: netCDF's I/O layer reads every region before it
// writes it (read-modify-write of its buffer pages), so an export whose
// variables were all defined first read the whole file back once, into a
// buffer as large as the region: at 0.1 M hexes 6.6 MB read and as much
// fresh memory zeroed by the kernel, a fifth of the export (issue 20).
// Every byte of the data section is written here, once; the header stays
// as Exodus and netCDF wrote it, and is read back (offsets and types) by
// the mesh reader's header check (read/netcdf_header.h).
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace cooperage::io::detail {

class ClassicDataFile {
 public:
  /// Opens `path` (a classic netCDF file whose variables are all defined)
  /// and reads its header. Throws MeshingError when it is not one, or its
  /// header does not pass read/netcdf_header.h's check.
  explicit ClassicDataFile(const std::string& path);
  ~ClassicDataFile();
  ClassicDataFile(const ClassicDataFile&) = delete;
  ClassicDataFile& operator=(const ClassicDataFile&) = delete;

  /// The index of a fixed-size variable; throws when the file has none.
  int var(const std::string& name) const;
  /// Rows [first, first + rows) of a variable of `per_row` values a row,
  /// converted to the variable's type (int to NC_INT or NC_INT64, double
  /// to NC_DOUBLE or NC_FLOAT).
  void put(int var, std::size_t first, std::size_t rows, std::size_t per_row,
           const int* data) const;
  void put(int var, std::size_t first, std::size_t rows, std::size_t per_row,
           const double* data) const;
  void close();

  struct Variable {
    int type = 0;                   ///< nc_type
    unsigned long long begin = 0;   ///< byte offset of its first value
    unsigned long long values = 0;  ///< product of its dimensions; 0: a record variable
  };

 private:
  void write_at(unsigned long long offset, const void* bytes, std::size_t size) const;
  const Variable& checked(int var, std::size_t first, std::size_t rows, std::size_t per_row) const;

  std::string path_;
  int fd_ = -1;
  std::vector<Variable> vars_;
  std::map<std::string, int> by_name_;
  mutable std::vector<unsigned char> scratch_;  // big-endian bytes of one put
};

}  // namespace cooperage::io::detail
