// The journal's named element blocks, side sets and node sets in the
// exported files, read back by independent readers (groups_readback.py:
// netCDF4 for Exodus's variables, meshio, the gmsh module), and the errors
// for groups a mesh cannot honour.
#include "framework/core/error.h"
#include "framework/io/export/write_mesh.h"

#include "export_fixtures.h"
#include "export_test_util.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace cooperage::test {
namespace {

using Lines = std::vector<std::vector<std::string>>;

bool has_line(const Lines& lines, const std::vector<std::string>& want) {
  for (const auto& l : lines)
    if (l == want) return true;
  return false;
}

std::string dump(const Lines& lines) {
  std::string s;
  for (const auto& l : lines) {
    for (const auto& w : l) s += w + " ";
    s += "\n";
  }
  return s;
}

io::SourceLocation line(int n, const char* element) { return {"job.xml", n, element}; }

/// The boundary surfaces of `volume` only (not shared), ascending.
std::vector<int> own_surfaces(const geom::Model& m, int volume) {
  std::vector<int> out;
  for (const auto& s : m.surfaces())
    if (s.volumes == std::vector<int>{volume}) out.push_back(s.id);
  return out;
}

/// two_blocks() with volumes 1 and 2 in one block "solid", a side set
/// "inlet" (one surface of volume 1: 4 faces), "walls" (two surfaces of
/// volume 2: 8 faces), node sets "fixed" (one surface: 9 nodes) and
/// "corner" (vertex 1: 1 node).
struct Named {
  TestMesh t = two_blocks();
  io::ExportOptions options;
  Named() {
    const auto left = own_surfaces(t.model, 1), right = own_surfaces(t.model, 2);
    auto& g = options.groups;
    g.blocks.push_back({10, "solid", {1, 2}, {}, line(6, "block")});
    g.side_sets.push_back({5, "inlet", {left[0]}, line(7, "sideset")});
    g.side_sets.push_back({6, "walls", {right[0], right[1]}, line(8, "sideset")});
    g.node_sets.push_back({7, "fixed", {left[0]}, {}, {}, line(9, "nodeset")});
    g.node_sets.push_back({8, "corner", {}, {}, {1}, line(10, "nodeset")});
  }
};

TEST(NamedGroups, ExodusKeepsIdsAndNamesAndMeshioReadsIt) {
  COOPERAGE_REQUIRE_MESHIO();
  if (!have_netcdf4()) GTEST_SKIP() << "python3-netcdf4 missing: Exodus read-back skipped";
  const Named n;
  const std::string path = scratch_dir() + "/named.exo";
  io::write_mesh(path, n.t.db, n.t.model, n.options);
  const Lines r = readback(path, "", "groups_readback.py");
  EXPECT_TRUE(has_line(r, {"EXO_BLOCK", "10", "solid", "HEX8", "16"})) << dump(r);
  EXPECT_TRUE(has_line(r, {"EXO_SIDESET", "5", "inlet", "4"})) << dump(r);
  EXPECT_TRUE(has_line(r, {"EXO_SIDESET", "6", "walls", "8"})) << dump(r);
  EXPECT_TRUE(has_line(r, {"EXO_NODESET", "7", "fixed", "9"})) << dump(r);
  EXPECT_TRUE(has_line(r, {"EXO_NODESET", "8", "corner", "1"})) << dump(r);
  EXPECT_EQ(with_key(r, "EXO_BLOCK").size(), 1u) << dump(r);
  EXPECT_EQ(with_key(r, "EXO_SIDESET").size(), 2u) << dump(r);  // no default per-surface sets
  EXPECT_EQ(with_key(r, "EXO_NODESET").size(), 2u) << dump(r);
  EXPECT_TRUE(has_line(r, {"MESHIO_CELLS", "hexahedron", "16"})) << dump(r);
}

TEST(NamedGroups, ExodusWedgeBlocksAreTypedWedgeSoMeshioReadsThem) {
  COOPERAGE_REQUIRE_MESHIO();
  if (!have_netcdf4()) GTEST_SKIP() << "python3-netcdf4 missing: Exodus read-back skipped";
  const TestMesh t = mixed();  // volume 1 "mixed": 1 hex, 2 wedges
  const std::string dir = scratch_dir();
  io::write_mesh(dir + "/default.exo", t.db, t.model);
  Lines r = readback(dir + "/default.exo", "", "groups_readback.py");
  EXPECT_TRUE(has_line(r, {"EXO_BLOCK", "1", "mixed", "HEX8", "1"})) << dump(r);
  EXPECT_TRUE(has_line(r, {"EXO_BLOCK", "1001", "mixed_wedge", "WEDGE", "2"})) << dump(r);
  EXPECT_TRUE(has_line(r, {"MESHIO_CELLS", "wedge", "2"})) << dump(r);
  // A named block with both kinds: id and id + 1000, "<name>_wedge".
  io::ExportOptions o;
  o.groups.blocks.push_back({3, "body", {1}, {}, line(6, "block")});
  io::write_mesh(dir + "/named.exo", t.db, t.model, o);
  r = readback(dir + "/named.exo", "", "groups_readback.py");
  EXPECT_TRUE(has_line(r, {"EXO_BLOCK", "3", "body", "HEX8", "1"})) << dump(r);
  EXPECT_TRUE(has_line(r, {"EXO_BLOCK", "1003", "body_wedge", "WEDGE", "2"})) << dump(r);
}

class NamedMsh : public ::testing::TestWithParam<bool> {};

TEST_P(NamedMsh, PhysicalGroupsCarryTheNamesForMeshioAndGmsh) {
  COOPERAGE_REQUIRE_MESHIO();
  Named n;
  n.options.binary = GetParam();
  const std::string path = scratch_dir() + "/named.msh";
  io::write_mesh(path, n.t.db, n.t.model, n.options);
  const Lines r = readback(path, "", "groups_readback.py");
  EXPECT_TRUE(has_line(r, {"MESHIO_PHYS", "3", "10", "solid"})) << dump(r);
  EXPECT_TRUE(has_line(r, {"MESHIO_PHYS", "2", "5", "inlet"})) << dump(r);
  EXPECT_TRUE(has_line(r, {"MESHIO_PHYS", "2", "6", "walls"})) << dump(r);
  EXPECT_TRUE(has_line(r, {"GMSH_PHYS", "3", "10", "solid", "16"})) << dump(r);
  EXPECT_TRUE(has_line(r, {"GMSH_PHYS", "2", "5", "inlet", "4"})) << dump(r);
  EXPECT_TRUE(has_line(r, {"GMSH_PHYS", "2", "6", "walls", "8"})) << dump(r);
  EXPECT_EQ(with_key(r, "GMSH_PHYS").size(), 3u) << dump(r);
}

INSTANTIATE_TEST_SUITE_P(AsciiAndBinary, NamedMsh, ::testing::Bool(),
                         [](const auto& p) { return p.param ? "binary" : "ascii"; });

TEST(NamedGroups, AbaqusSetsAndSurfacesCarryTheNames) {
  COOPERAGE_REQUIRE_MESHIO();
  const Named n;
  const std::string path = scratch_dir() + "/named.inp";
  io::write_mesh(path, n.t.db, n.t.model, n.options);
  const Lines r = readback(path, "", "groups_readback.py");
  EXPECT_TRUE(has_line(r, {"INP_ELSET", "solid", "16"})) << dump(r);
  EXPECT_TRUE(has_line(r, {"INP_NSET", "fixed", "9"})) << dump(r);
  EXPECT_TRUE(has_line(r, {"INP_NSET", "corner", "1"})) << dump(r);
  EXPECT_TRUE(has_line(r, {"INP_SURFACE", "inlet", "4"})) << dump(r);
  EXPECT_TRUE(has_line(r, {"INP_SURFACE", "walls", "8"})) << dump(r);
  EXPECT_EQ(with_key(r, "INP_NSET").size(), 2u) << dump(r);
  EXPECT_EQ(with_key(r, "INP_SURFACE").size(), 2u) << dump(r);
}

/// Writes `path` expecting MeshingError(InvalidInput) containing `parts`, and no file.
void expect_refused(const std::string& path, const TestMesh& t, const io::ExportOptions& o,
                    std::initializer_list<std::string> parts) {
  try {
    io::write_mesh(path, t.db, t.model, o);
    ADD_FAILURE() << "no error writing " << path;
  } catch (const MeshingError& e) {
    EXPECT_EQ(e.code(), ErrorCode::InvalidInput) << e.what();
    for (const auto& p : parts)
      EXPECT_NE(std::string(e.what()).find(p), std::string::npos) << e.what() << " lacks " << p;
  }
  EXPECT_FALSE(std::filesystem::exists(path)) << path;
  for (const auto& entry :
       std::filesystem::directory_iterator(std::filesystem::path(path).parent_path()))
    ADD_FAILURE() << "left behind: " << entry.path();
}

TEST(NamedGroups, AVolumeInNoBlockIsRefusedInEveryFormat) {
  const TestMesh t = two_blocks();
  io::ExportOptions o;
  o.groups.blocks.push_back({1, "left", {1}, {}, line(6, "block")});
  for (const char* ext : {"exo", "msh", "inp"})
    expect_refused(scratch_dir() + "/a." + ext, t, o,
                   {"job.xml:6: <block>: ", "volume 2 has elements but is in no <block>"});
}

TEST(NamedGroups, BlocksOfTheWrongDimensionAreRefused) {
  io::ExportOptions o;
  o.groups.blocks.push_back({1, "skin", {}, {1, 2}, line(6, "block")});
  expect_refused(scratch_dir() + "/a.exo", two_blocks(), o,
                 {"job.xml:6: <block>: block 1 \"skin\" lists surfaces", "takes volumes="});
  o.groups.blocks = {{1, "body", {1}, {}, line(7, "block")}};
  expect_refused(scratch_dir() + "/a.inp", surface_only(), o,
                 {"job.xml:7: <block>: block 1 \"body\" lists volumes", "--dim 2", "surfaces="});
}

TEST(NamedGroups, GroupsWithNothingMeshedAreRefusedOrLeftOutOfAPartialRun) {
  TestMesh t = two_blocks();
  t.db.mutable_volume(2).hexes.clear();  // volume 2 refused, as in a partial run
  io::ExportOptions o;
  o.groups.blocks.push_back({1, "left", {1}, {}, line(6, "block")});
  o.groups.blocks.push_back({2, "right", {2}, {}, line(7, "block")});
  o.groups.side_sets.push_back({3, "far", own_surfaces(t.model, 2), line(8, "sideset")});
  expect_refused(scratch_dir() + "/a.exo", t, o,
                 {"job.xml:7: <block>: block 2 \"right\": none of its volumes has elements"});
  o.groups.blocks.pop_back();
  expect_refused(scratch_dir() + "/a.inp", t, o,
                 {"job.xml:8: <sideset>: side set 3 \"far\": none of its surfaces"});
  o.groups.blocks.push_back({2, "right", {2}, {}, line(7, "block")});
  o.skip_empty_groups = true;
  COOPERAGE_REQUIRE_MESHIO();
  const std::string path = scratch_dir() + "/partial.inp";
  io::write_mesh(path, t.db, t.model, o);
  const Lines r = readback(path, "", "groups_readback.py");
  EXPECT_TRUE(has_line(r, {"INP_ELSET", "left", "8"})) << dump(r);
  EXPECT_TRUE(with_key(r, "INP_SURFACE").empty()) << dump(r);
}

TEST(NamedGroups, SurfaceMeshBlocksOfSurfaces) {
  COOPERAGE_REQUIRE_MESHIO();
  const TestMesh t = surface_only();  // six surfaces of 4 quads
  io::ExportOptions o;
  o.groups.blocks.push_back({1, "sides", {}, {1, 2, 3, 4}, line(6, "block")});
  o.groups.blocks.push_back({2, "caps", {}, {5, 6}, line(7, "block")});
  o.groups.side_sets.push_back({3, "ignored", {1}, line(8, "sideset")});  // no volume elements
  const std::string dir = scratch_dir();
  io::write_mesh(dir + "/shell.msh", t.db, t.model, o);
  const Lines r = readback(dir + "/shell.msh", "", "groups_readback.py");
  EXPECT_TRUE(has_line(r, {"GMSH_PHYS", "2", "1", "sides", "16"})) << dump(r);
  EXPECT_TRUE(has_line(r, {"GMSH_PHYS", "2", "2", "caps", "8"})) << dump(r);
  EXPECT_EQ(with_key(r, "GMSH_PHYS").size(), 2u) << dump(r);
  io::write_mesh(dir + "/shell.inp", t.db, t.model, o);
  const Lines q = readback(dir + "/shell.inp", "", "groups_readback.py");
  EXPECT_TRUE(has_line(q, {"INP_ELSET", "sides", "16"})) << dump(q);
  EXPECT_TRUE(has_line(q, {"INP_ELSET", "caps", "8"})) << dump(q);
}

}  // namespace
}  // namespace cooperage::test
