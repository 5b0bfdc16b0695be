// cooperage::Options::groups: named blocks, side sets and node sets from
// code, written with their names (read back by meshio) and checked as a
// journal's are.
#include <cooperage/cooperage.h>

#include "framework/core/error.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace cooperage {
namespace {

namespace fs = std::filesystem;

const std::string kPart = std::string(COOPERAGE_SOURCE_DIR) + "/examples/part.step";

std::string scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("cooperage-api-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return (dir / name).string();
}

std::string error_of(const Options& o) {
  try {
    mesh_file(kPart, 2.0, o);
  } catch (const MeshingError& e) {
    EXPECT_EQ(e.code(), ErrorCode::InvalidInput) << e.what();
    return e.what();
  }
  ADD_FAILURE() << "no error";
  return {};
}

TEST(ApiGroups, NamedBlockAndNodeSetReachTheAbaqusFile) {
  Options o;
  o.exports = {scratch("part.inp")};
  o.groups.blocks.push_back({1, "body", {1, 2}, {}, {}});
  o.groups.node_sets.push_back({4, "", {}, {}, {1}, {}});  // default name nodeset_4
  const Result r = mesh_file(kPart, 2.0, o);
  ASSERT_EQ(r.written, o.exports);
  if (std::system(
          (std::string(COOPERAGE_DEBIAN_PYTHON) + " -c 'import meshio' 2>/dev/null").c_str()) != 0)
    GTEST_SKIP() << "meshio missing: read-back skipped";
  const std::string out = scratch("readback.txt");
  ASSERT_EQ(
      std::system((std::string(COOPERAGE_DEBIAN_PYTHON) + " " + COOPERAGE_SOURCE_DIR +
                   "/tests/framework/io/export/groups_readback.py " + o.exports[0] + " > " + out)
                      .c_str()),
      0);
  std::stringstream text;
  text << std::ifstream(out).rdbuf();
  const std::string lines = text.str();
  EXPECT_NE(lines.find("INP_ELSET body " + std::to_string(r.mesh.hex_count()) + "\n"),
            std::string::npos)
      << lines;
  EXPECT_NE(lines.find("INP_NSET nodeset_4 1\n"), std::string::npos) << lines;
  fs::remove_all(fs::path(out).parent_path());
}

TEST(ApiGroups, BadGroupsAreRefusedBeforeMeshingNamingTheOption) {
  Options o;
  o.groups.blocks = {{1, "a", {1}, {}, {}}, {1, "b", {2}, {}, {}}};
  std::string m = error_of(o);
  EXPECT_NE(m.find("Options::groups"), std::string::npos) << m;
  EXPECT_NE(m.find("block id 1 is used twice"), std::string::npos) << m;
  o.groups.blocks = {{1, "a", {1, 2}, {}, {}}, {2, "b", {2}, {}, {}}};
  m = error_of(o);
  EXPECT_NE(m.find("volume 2 is in blocks 1 and 2"), std::string::npos) << m;
  o.groups.blocks = {{1, "steel block", {1}, {}, {}}};
  EXPECT_NE(error_of(o).find("must be a letter"), std::string::npos);
  o.groups.blocks = {{1, "a", {9}, {}, {}}};
  EXPECT_NE(error_of(o).find("no volume 9"), std::string::npos);
}

}  // namespace
}  // namespace cooperage
