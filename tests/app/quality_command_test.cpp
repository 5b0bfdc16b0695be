// `cooperage quality`: the report of a unit-cube hex mesh written by
// io::write_mesh has the block and a scaled Jacobian of exactly 1.
#include "quality_command.h"

#include "framework/core/error.h"
#include "framework/io/export/export_fixtures.h"
#include "framework/io/export/export_test_util.h"
#include "framework/io/export/write_mesh.h"

#include <gtest/gtest.h>

#include <sstream>

namespace cooperage::test {
namespace {

std::string unit_cube(const std::string& ext) {
  const TestMesh t = one_block();  // unit cube, 2 x 2 x 2 hexes; Exodus block "block_one"
  const std::string path = scratch_dir() + "/cube." + ext;
  io::write_mesh(path, t.db, t.model);
  return path;
}

TEST(QualityCommand, TextReportOfAUnitCube) {
  for (const char* ext : {"exo", "msh", "vtu"}) {
    SCOPED_TRACE(ext);
    const std::string path = unit_cube(ext);
    std::ostringstream out;
    EXPECT_EQ(app::run_quality(path, false, out), 0);
    const std::string s = out.str();
    EXPECT_NE(s.find("8 hex"), std::string::npos) << s;
    // scaled_jacobian: min, mean, max, median 1, inverted 0.
    EXPECT_NE(s.find("scaled_jacobian"), std::string::npos) << s;
    std::istringstream lines(s);
    std::string line;
    bool found = false;
    while (std::getline(lines, line)) {
      std::istringstream words(line);
      std::string metric;
      double mn = 0, mean = 0, mx = 0, median = 0;
      int inverted = -1;
      if (!(words >> metric) || metric != "scaled_jacobian") continue;
      ASSERT_TRUE(words >> mn >> mean >> mx >> median >> inverted) << line;
      EXPECT_DOUBLE_EQ(mn, 1.0);
      EXPECT_DOUBLE_EQ(mx, 1.0);
      EXPECT_EQ(inverted, 0);
      found = true;
    }
    EXPECT_TRUE(found) << s;
    for (const char* m : {"jacobian", "skew", "taper", "aspect_frobenius", "edge_ratio", "shape",
                          "relative_size"}) {
      EXPECT_NE(s.find(m), std::string::npos) << m;
    }
  }
  std::ostringstream out;
  app::run_quality(unit_cube("exo"), false, out);
  EXPECT_NE(out.str().find("block \"block_one\""), std::string::npos) << out.str();
}

TEST(QualityCommand, JsonReport) {
  const std::string path = unit_cube("exo");
  std::ostringstream out;
  EXPECT_EQ(app::run_quality(path, true, out), 0);
  const std::string s = out.str();
  EXPECT_EQ(s.front(), '{');
  EXPECT_NE(s.find("\"name\":\"block_one\""), std::string::npos) << s;
  EXPECT_NE(s.find("\"type\":\"hex\""), std::string::npos) << s;
  EXPECT_NE(s.find("\"count\":8"), std::string::npos) << s;
  EXPECT_NE(
      s.find("\"scaled_jacobian\":{\"min\":1,\"mean\":1,\"max\":1,\"median\":1,\"inverted\":0}"),
      std::string::npos)
      << s;
}

TEST(QualityCommand, MissingFileThrows) {
  std::ostringstream out;
  EXPECT_THROW(app::run_quality("/nonexistent/mesh.exo", false, out), MeshingError);
}

}  // namespace
}  // namespace cooperage::test
