// ClassicDataFile against netCDF's own reader: files defined with the
// library in each classic format (CDF-1, CDF-2, CDF-5), their data written
// by ClassicDataFile, read back with nc_get_var_*.
#include "framework/io/export/netcdf_classic_data.h"

#include "framework/core/error.h"

#include <gtest/gtest.h>
#include <netcdf.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <type_traits>
#include <vector>

#include <unistd.h>

namespace cooperage::io::detail {
namespace {

std::string temp_file(const std::string& tag) {
  return (std::filesystem::temp_directory_path() /
          ("cooperage-classic-" + tag + "-" + std::to_string(::getpid()) + ".nc"))
      .string();
}

void ok(int rc) { ASSERT_EQ(rc, NC_NOERR) << nc_strerror(rc); }

// rows x 4 ints, rows doubles, rows floats, a record variable and
// attributes before and among the variables; `extra` more variables with
// long names grow the header past the first piece ClassicDataFile reads.
void define(const std::string& path, int format, size_t rows, int extra = 0) {
  int id = -1, row = -1, four = -1, time = -1, v = -1;
  ok(nc_create(path.c_str(), NC_CLOBBER | format, &id));
  ok(nc_put_att_text(id, NC_GLOBAL, "title", 9, "a header."));
  ok(nc_def_dim(id, "rows", rows, &row));
  ok(nc_def_dim(id, "four", 4, &four));
  ok(nc_def_dim(id, "time", NC_UNLIMITED, &time));
  const int rows_four[2] = {row, four};
  ok(nc_def_var(id, "conn", NC_INT, 2, rows_four, &v));
  ok(nc_put_att_text(id, v, "elem_type", 4, "HEX8"));
  ok(nc_def_var(id, "x", NC_DOUBLE, 1, &row, &v));
  ok(nc_def_var(id, "f", NC_FLOAT, 1, &row, &v));
  ok(nc_def_var(id, "t", NC_DOUBLE, 1, &time, &v));
  if (format == NC_64BIT_DATA) ok(nc_def_var(id, "big", NC_INT64, 1, &row, &v));
  for (int k = 0; k < extra; ++k) {
    const std::string name = "a_variable_with_a_long_name_to_fill_the_header_" +
                             std::string(150, 'x') + std::to_string(k);
    ok(nc_def_var(id, name.c_str(), NC_INT, 1, &row, &v));
  }
  ok(nc_set_fill(id, NC_NOFILL, nullptr));
  ok(nc_enddef(id));
  ok(nc_close(id));
}

template <class T>
std::vector<T> read_back(const std::string& path, const char* name, size_t count) {
  int id = -1, v = -1;
  std::vector<T> out(count);
  EXPECT_EQ(nc_open(path.c_str(), NC_NOWRITE, &id), NC_NOERR);
  EXPECT_EQ(nc_inq_varid(id, name, &v), NC_NOERR) << name;
  int rc = NC_NOERR;
  if constexpr (std::is_same_v<T, int>) {
    rc = nc_get_var_int(id, v, out.data());
  } else if constexpr (std::is_same_v<T, double>) {
    rc = nc_get_var_double(id, v, out.data());
  } else if constexpr (std::is_same_v<T, float>) {
    rc = nc_get_var_float(id, v, out.data());
  } else {
    rc = nc_get_var_longlong(id, v, out.data());
  }
  EXPECT_EQ(rc, NC_NOERR) << name;
  nc_close(id);
  return out;
}

class ClassicFormats : public ::testing::TestWithParam<int> {};

TEST_P(ClassicFormats, DataWrittenAtTheHeadersOffsetsReadsBackThroughNetcdf) {
  const std::string path = temp_file("formats");
  const size_t rows = 5;
  define(path, GetParam(), rows, GetParam() == NC_64BIT_OFFSET ? 400 : 0);
  std::vector<int> conn(rows * 4);
  for (size_t k = 0; k < conn.size(); ++k) conn[k] = static_cast<int>(k * 1000003 % 99991) - 7;
  const std::vector<double> x{1.5, -2.25, 1e300, -0.0, 3.0000000000000004};
  {
    ClassicDataFile f(path);
    const int c = f.var("conn");
    f.put(c, 0, 2, 4, conn.data());  // rows 0-1, then 2-4: offsets within the variable
    f.put(c, 2, 3, 4, conn.data() + 8);
    f.put(f.var("x"), 0, rows, 1, x.data());
    f.put(f.var("f"), 0, rows, 1, x.data());
    if (GetParam() == NC_64BIT_DATA) f.put(f.var("big"), 0, rows, 1, conn.data());
    f.close();
  }
  EXPECT_EQ(read_back<int>(path, "conn", conn.size()), conn);
  EXPECT_EQ(read_back<double>(path, "x", rows), x);
  const std::vector<float> f = read_back<float>(path, "f", rows);
  for (size_t k = 0; k < rows; ++k) {
    if (std::abs(x[k]) < 1e38) {
      EXPECT_EQ(f[k], static_cast<float>(x[k])) << k;
    }
  }
  if (GetParam() == NC_64BIT_DATA) {
    const std::vector<long long> big = read_back<long long>(path, "big", rows);
    for (size_t k = 0; k < rows; ++k) EXPECT_EQ(big[k], conn[k]) << k;
  }
  std::remove(path.c_str());
}

INSTANTIATE_TEST_SUITE_P(NetcdfClassic, ClassicFormats,
                         ::testing::Values(NC_CLASSIC_MODEL, NC_64BIT_OFFSET, NC_64BIT_DATA),
                         [](const ::testing::TestParamInfo<int>& format) {
                           return format.param == NC_CLASSIC_MODEL  ? std::string("Cdf1")
                                  : format.param == NC_64BIT_OFFSET ? std::string("Cdf2")
                                                                    : std::string("Cdf5");
                         });

TEST(ClassicDataFile, RefusesWhatItCannotWrite) {
  const std::string path = temp_file("refuses");
  define(path, NC_64BIT_OFFSET, 3);
  {
    ClassicDataFile f(path);
    EXPECT_THROW(f.var("no_such_variable"), MeshingError);
    EXPECT_THROW(f.var("t"), MeshingError);  // a record variable
    const std::vector<int> four(16, 1);
    EXPECT_THROW(f.put(f.var("conn"), 2, 2, 4, four.data()), MeshingError);  // past its 3 rows
    const std::vector<double> reals(3, 1.0);
    EXPECT_THROW(f.put(f.var("conn"), 0, 3, 1, reals.data()), MeshingError);  // reals into ints
  }
  std::remove(path.c_str());
  {
    std::ofstream text(path);
    text << "not a netCDF file\n";
  }
  EXPECT_THROW(ClassicDataFile{path}, MeshingError);
  std::remove(path.c_str());
  EXPECT_THROW(ClassicDataFile{path}, MeshingError);  // gone
}

}  // namespace
}  // namespace cooperage::io::detail
