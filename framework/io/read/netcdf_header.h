// A bounds check of a netCDF classic header before libnetcdf reads it (issue
// 21: a damaged 7.8 KB .exo made libnetcdf allocate 3.1 GB, others made it
// loop). libnetcdf allocates what the header declares; this check reads the
// header itself and refuses any count, name, attribute or variable that does
// not fit in the file.
// cite: "NetCDF Classic and 64-bit Offset File Formats" (Unidata, the BNF of
// the header) and the CDF-5 extension (64-bit counts and sizes).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace cooperage::io::detail {

enum class NetcdfKind {
  NotNetcdf,  ///< neither a classic netCDF nor an HDF5 (netCDF-4) file
  Classic,    ///< CDF-1, CDF-2 (64-bit offset) or CDF-5; header checked
  Hdf5,       ///< netCDF-4 / HDF5: not checked here (read it isolated)
};

/// A variable of a classic file as its header declares it (the Exodus
/// writer puts its data at `begin`, export/netcdf_classic_data.h).
struct NetcdfVariable {
  std::string name;
  int type = 0;              ///< nc_type
  std::uint64_t begin = 0;   ///< byte offset of its data
  std::uint64_t values = 0;  ///< values (of one record, for a record variable)
  bool record = false;       ///< its first dimension is the record dimension
};

/// Identifies `path` by its first bytes and, for a classic file, checks its
/// whole header against the file size: every count fits in the bytes left,
/// every name is at most 256 bytes, every dimension id exists, every
/// variable's data (and every record) lies inside the file, no size
/// overflows 64 bits. Throws MeshingError(ParseError, "<path>: <reason>")
/// on the first violation.
NetcdfKind check_netcdf_file(const std::string& path);

/// The same check on the bytes of a file held in memory (for the fuzzer);
/// `file_size` is the size of the whole file (>= bytes.size()). A classic
/// file's variables go to `variables` when it is given.
NetcdfKind check_netcdf_bytes(const std::string& path, const std::string& bytes,
                              std::uint64_t file_size,
                              std::vector<NetcdfVariable>* variables = nullptr);

}  // namespace cooperage::io::detail
