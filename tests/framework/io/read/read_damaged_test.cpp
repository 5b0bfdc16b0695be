// Damaged mesh files (issue 21 item 2): counts are checked against the file
// size before anything is allocated; libexodus never sees a netCDF header
// that declares more than the file holds, and runs in a child process with a
// time and memory limit. The reproducers are mutations of the files in data/
// (written by `cooperage run`, reduced by hand).
#include "framework/core/error.h"
#include "framework/io/read/netcdf_header.h"
#include "framework/io/read/read_mesh_file.h"
#include "framework/io/export/export_test_util.h"
#include "read_test_util.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstring>
#include <fstream>
#include <random>

namespace cooperage::test {
namespace {

using quality::ElementType;

const std::string kData = std::string(COOPERAGE_SOURCE_DIR) + "/tests/framework/io/read/data/";

std::string bytes_of(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string write(const std::string& name, const std::string& bytes) {
  const std::string path = scratch_dir() + "/" + name;
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

// The error read_mesh_file throws (code must not be Internal), or "" if it reads.
std::string read_error(const std::string& path) {
  try {
    io::read_mesh_file(path);
  } catch (const MeshingError& e) {
    EXPECT_NE(e.code(), ErrorCode::Internal) << e.what();
    return e.what();
  }
  return "";
}

/// Offset of the big-endian length of the first dimension called `name`.
std::size_t dimension_length_offset(const std::string& bytes, const std::string& name) {
  const std::size_t at = bytes.find(name);
  EXPECT_NE(at, std::string::npos);
  return at + (name.size() + 3) / 4 * 4;
}

void put_u32(std::string& bytes, std::size_t at, std::uint32_t v) {
  for (int i = 0; i < 4; ++i)
    bytes[at + static_cast<std::size_t>(i)] = static_cast<char>(v >> (24 - 8 * i));
}

TEST(ReadDamaged, TheDataFilesRead) {
  for (const char* ext : {"exo", "msh", "vtu"}) {
    const io::MeshFile brick = io::read_mesh_file(kData + "brick." + ext);
    EXPECT_EQ(count_of(brick, ElementType::Hex), 24u) << ext;
    EXPECT_GT(min_volume(brick), 0) << ext;
    const io::MeshFile rod = io::read_mesh_file(kData + "rod_wedges." + ext);
    EXPECT_GT(count_of(rod, ElementType::Wedge), 0u) << ext;
  }
  EXPECT_GT(count_of(io::read_mesh_file(kData + "plate_quads.exo"), ElementType::Quad), 0u);
  EXPECT_EQ(io::detail::check_netcdf_file(kData + "brick.exo"), io::detail::NetcdfKind::Classic);
}

TEST(ReadDamaged, ANodeCountBeyondTheFileIsRefusedBeforeAllocating) {
  // The case: 7.8 KB of .exo made libnetcdf allocate 3.1 GB.
  std::string bytes = bytes_of(kData + "brick.exo");
  put_u32(bytes, dimension_length_offset(bytes, "num_nodes"), 0x7FFFFFFF);
  const std::string path = write("huge_nodes.exo", bytes);
  const auto t0 = std::chrono::steady_clock::now();
  const std::string msg = read_error(path);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 5.0);
  EXPECT_NE(msg.find("huge_nodes.exo: damaged netCDF"), std::string::npos) << msg;
}

TEST(ReadDamaged, HeaderCountsThatDoNotFitAreRefused) {
  const std::string good = bytes_of(kData + "brick.exo");
  // The dimension count (bytes 12..15 of a CDF-2 header) and a name length.
  std::string dims = good;
  put_u32(dims, 12, 0x10000000);
  EXPECT_NE(read_error(write("dims.exo", dims)).find("dimension count"), std::string::npos);
  std::string name = good;
  put_u32(name, 16, 0xFFFFFFF0);
  EXPECT_NE(read_error(write("name.exo", name)).find("a name of"), std::string::npos);
  EXPECT_NE(read_error(write("cut.exo", good.substr(0, good.size() / 2))).find("beyond its end"),
            std::string::npos);
  EXPECT_NE(read_error(write("header.exo", good.substr(0, 40))).find("damaged netCDF header"),
            std::string::npos);
  EXPECT_NE(read_error(write("magic.exo", good.substr(0, 6))).find("ends inside the header"),
            std::string::npos);
}

TEST(ReadDamaged, RandomDamageToTheHeaderEndsInAnErrorOrAMesh) {
  const std::string good = bytes_of(kData + "brick.exo");
  std::mt19937 rng(21);
  for (int k = 0; k < 40; ++k) {
    std::string bytes = good;
    for (int flips = 0; flips < 3; ++flips) {
      const std::size_t at = rng() % 1200;
      bytes[at] = static_cast<char>(rng() & 0xFF);
    }
    const std::string path = write("flip" + std::to_string(k) + ".exo", bytes);
    const std::string msg = read_error(path);  // no crash, no Internal, bounded time
    if (msg.empty()) {
      const io::MeshFile f = io::read_mesh_file(path);
      for (const auto& b : f.blocks)
        for (int n : b.connectivity) EXPECT_LT(static_cast<std::size_t>(n), f.coords.size());
    }
  }
}

TEST(ReadDamaged, MshCountsBeyondTheFileAreRefused) {
  std::string text = bytes_of(kData + "brick.msh");
  const std::size_t at = text.find("$Nodes\n");
  ASSERT_NE(at, std::string::npos);
  const std::size_t eol = text.find('\n', at + 7);
  text.replace(at + 7, eol - at - 7, "1 2000000000 1 2000000000");
  const std::string msg = read_error(write("huge.msh", text));
  EXPECT_NE(msg.find("more than the file holds"), std::string::npos) << msg;
}

}  // namespace
}  // namespace cooperage::test
