// Round trip: hand-built MeshDBs written by io::write_mesh and read back by
// io::read_mesh_file give the same nodes and the same elements in the same
// node order, with positive volumes.
#include "framework/io/export/export_test_util.h"
#include "framework/io/export/write_mesh.h"
#include "read_test_util.h"

#include <gtest/gtest.h>

#include <set>

namespace cooperage::test {
namespace {

using quality::ElementType;

class RoundTrip : public ::testing::TestWithParam<std::string> {};

void check_round_trip(const TestMesh& t, const std::string& path, bool binary = false) {
  io::ExportOptions options;
  options.binary = binary;
  io::write_mesh(path, t.db, t.model, options);
  const io::MeshFile f = io::read_mesh_file(path);
  ASSERT_EQ(f.coords.size(), t.db.node_count());
  std::set<std::vector<long long>> want, got;
  for (size_t i = 0; i < t.db.node_count(); ++i) {
    want.insert(coord_element({t.db.node(static_cast<int>(i))}, std::vector<int>{0}.data(), 1));
    got.insert(coord_element(f.coords, std::vector<int>{static_cast<int>(i)}.data(), 1));
  }
  EXPECT_EQ(want, got);
  EXPECT_EQ(elements_of(f, ElementType::Hex), db_elements(t.db, false));
  EXPECT_EQ(elements_of(f, ElementType::Wedge), db_elements(t.db, true));
  EXPECT_GT(min_volume(f), 0.0);
  for (const auto& b : f.blocks) EXPECT_GT(b.size(), 0u) << b.name;
}

TEST_P(RoundTrip, OneBlock) {
  const TestMesh t = one_block();
  const std::string path = scratch_dir() + "/one." + GetParam();
  check_round_trip(t, path);
  const io::MeshFile f = io::read_mesh_file(path);
  // Every format keeps the 8 hexes in one block.
  size_t hex_blocks = 0;
  for (const auto& b : f.blocks) hex_blocks += b.type == ElementType::Hex;
  EXPECT_EQ(hex_blocks, 1u);
  EXPECT_EQ(count_of(f, ElementType::Hex), 8u);
}

TEST_P(RoundTrip, TwoBlocksKeepTheirBlocks) {
  const TestMesh t = two_blocks();
  const std::string path = scratch_dir() + "/two." + GetParam();
  check_round_trip(t, path);
  const io::MeshFile f = io::read_mesh_file(path);
  std::vector<size_t> hex_blocks;
  for (const auto& b : f.blocks)
    if (b.type == ElementType::Hex) hex_blocks.push_back(b.size());
  EXPECT_EQ(hex_blocks, (std::vector<size_t>{8, 8}));
}

TEST_P(RoundTrip, WedgesKeepExodusOrder) {
  check_round_trip(two_wedges(), scratch_dir() + "/wedges." + GetParam());
}

TEST_P(RoundTrip, MixedHexAndWedges) {
  check_round_trip(mixed(), scratch_dir() + "/mixed." + GetParam());
}

TEST_P(RoundTrip, SurfaceOnlyMeshGivesQuads) {
  const TestMesh t = surface_only();
  const std::string path = scratch_dir() + "/shell." + GetParam();
  io::write_mesh(path, t.db, t.model);
  const io::MeshFile f = io::read_mesh_file(path);
  EXPECT_EQ(count_of(f, ElementType::Quad), 24u);  // 6 sides x 2 x 2
  EXPECT_EQ(count_of(f, ElementType::Hex), 0u);
}

INSTANTIATE_TEST_SUITE_P(Formats, RoundTrip, ::testing::Values("exo", "msh", "vtu"));

// Binary .msh (4.1, raw little-endian bodies) and .vtu (raw appended data)
// read back as the same mesh as the ASCII files.
class BinaryRoundTrip : public ::testing::TestWithParam<std::string> {};

TEST_P(BinaryRoundTrip, EveryTestMesh) {
  const std::string dir = scratch_dir();
  check_round_trip(one_block(), dir + "/one." + GetParam(), true);
  check_round_trip(two_blocks(), dir + "/two." + GetParam(), true);
  check_round_trip(two_wedges(), dir + "/wedges." + GetParam(), true);
  check_round_trip(mixed(), dir + "/mixed." + GetParam(), true);
}

TEST_P(BinaryRoundTrip, BlocksAndSurfacesAsInAscii) {
  const std::string dir = scratch_dir();
  for (const TestMesh& t : {two_blocks(), surface_only()}) {
    io::ExportOptions binary;
    binary.binary = true;
    io::write_mesh(dir + "/ascii." + GetParam(), t.db, t.model);
    io::write_mesh(dir + "/binary." + GetParam(), t.db, t.model, binary);
    const io::MeshFile a = io::read_mesh_file(dir + "/ascii." + GetParam());
    const io::MeshFile b = io::read_mesh_file(dir + "/binary." + GetParam());
    ASSERT_EQ(a.coords.size(), b.coords.size());
    for (size_t i = 0; i < a.coords.size(); ++i) EXPECT_EQ(a.coords[i], b.coords[i]) << i;
    ASSERT_EQ(a.blocks.size(), b.blocks.size());
    for (size_t k = 0; k < a.blocks.size(); ++k) {
      EXPECT_EQ(a.blocks[k].name, b.blocks[k].name);
      EXPECT_EQ(a.blocks[k].type, b.blocks[k].type);
      EXPECT_EQ(a.blocks[k].connectivity, b.blocks[k].connectivity);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Formats, BinaryRoundTrip, ::testing::Values("msh", "vtu"));

TEST(ReadMeshFile, ExodusBlockNamesAreTheVolumeNames) {
  const TestMesh t = two_blocks();
  const std::string path = scratch_dir() + "/names.exo";
  io::write_mesh(path, t.db, t.model);
  const io::MeshFile f = io::read_mesh_file(path);
  std::vector<std::string> names;
  for (const auto& b : f.blocks)
    if (b.type == ElementType::Hex) names.push_back(b.name);
  EXPECT_EQ(names, (std::vector<std::string>{"left", "right"}));
}

TEST(ReadMeshFile, ExtensionIsCaseInsensitive) {
  const TestMesh t = one_block();
  const std::string dir = scratch_dir();
  io::write_mesh(dir + "/a.vtu", t.db, t.model);
  std::filesystem::rename(dir + "/a.vtu", dir + "/a.VTU");
  EXPECT_EQ(count_of(io::read_mesh_file(dir + "/a.VTU"), ElementType::Hex), 8u);
}

}  // namespace
}  // namespace cooperage::test
