// `--size D/N` and <mesh size="D/N">: the element size as the model's
// bounding-box diagonal over N. A 3 x 4 x 12 brick has the diagonal 13, so
// D/13 is size 1: 3 x 4 x 12 unit hexes, the same file as --size 1.
#include "run_command.h"
#include "temp_dir.h"

#include "framework/geometry/occ/workbench.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace cooperage {
namespace {

namespace fs = std::filesystem;
using testing::kCli;
using testing::run_command;
using testing::slurp;

class RelativeSizeOption : public testing::TempDirTest {
 protected:
  std::string brick_step() const {
    occ::Workbench bench;
    bench.brick("brick", {0, 0, 0}, {3, 4, 12});
    const std::string file = path("brick.step");
    bench.write(file);
    return file;
  }
};

TEST_F(RelativeSizeOption, TheDiagonalOverNIsTheSizeOfTheWholeModel) {
  const std::string step = brick_step();
  const auto relative = run_command(kCli + " mesh " + step + " --size D/13 -o " + path("a.vtu"));
  ASSERT_EQ(relative.exit_code, 0) << relative.out << relative.err;
  EXPECT_NE(relative.out.find("hexes 144,"), std::string::npos) << relative.out;
  EXPECT_NE(relative.out.find("size D/13 = 1\n"), std::string::npos) << relative.out;
  const auto absolute = run_command(kCli + " mesh -q " + step + " --size 1 -o " + path("b.vtu"));
  ASSERT_EQ(absolute.exit_code, 0) << absolute.out << absolute.err;
  EXPECT_EQ(slurp(path("a.vtu")), slurp(path("b.vtu")));

  const auto plan = run_command(kCli + " plan " + step + " --size d/13");
  EXPECT_EQ(plan.exit_code, 0) << plan.out << plan.err;
  EXPECT_EQ(plan.out.find("interval feasibility not checked"), std::string::npos) << plan.out;
}

TEST_F(RelativeSizeOption, InfoGivesTheDiagonal) {
  const auto r = run_command(kCli + " info " + brick_step());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find(", diagonal D 13 (--size D/40 = 0.325)\n"), std::string::npos) << r.out;
}

TEST_F(RelativeSizeOption, ABadSizeNamesTheFormAndWritesNothing) {
  const std::string step = brick_step();
  for (const char* size : {"D/0", "D/", "3mm", "E/40"}) {
    const auto r = run_command(kCli + " mesh " + step + " --size " + size + " -o " + path("c.vtu"));
    EXPECT_EQ(r.exit_code, 2) << size;
    EXPECT_NE(r.err.find("--size must be a positive length or D/N"), std::string::npos)
        << size << ": " << r.err;
    EXPECT_FALSE(fs::exists(path("c.vtu"))) << size;
  }
}

TEST_F(RelativeSizeOption, AJournalsSizeIsResolvedAfterItsGeometry) {
  // Two bricks fused into 3 x 4 x 12: the diagonal is the fused part's.
  std::ofstream(path("job.xml")) << R"(<cooperage version="1">
  <geometry>
    <brick name="a" origin="0 0 0" size="3 4 6"/>
    <brick name="b" origin="0 0 6" size="3 4 6"/>
    <fuse name="ab" inputs="a b"/>
  </geometry>
  <mesh size="D/13"/>
  <export file="j.vtu"/>
</cooperage>
)";
  const auto r = run_command(kCli + " run " + path("job.xml"));
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("hexes 144,"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace cooperage
