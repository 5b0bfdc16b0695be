// `cooperage mesh --min-scaled-jacobian`: the run fails below it, and a
// volume that meshes below it is first meshed again at half its size. The
// real binary on a block with a boss on the top and a foot below whose
// edges nearly meet (the plan => mesh campaign's seed 4 case 94): at size
// 4.39 its worst hex has a scaled Jacobian of 0.003; `cooperage quality`
// reads the file written back.
#include "run_command.h"
#include "temp_dir.h"

#include "framework/geometry/occ/workbench.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <regex>

namespace cooperage {
namespace {

namespace fs = std::filesystem;
using testing::kCli;
using testing::run_command;

class MinScaledJacobianOption : public testing::TempDirTest {
 protected:
  std::string boss_over_foot_step() const {
    occ::Workbench bench;
    bench.brick("block", {0, 0, 0}, {33.68, 58.96, 28.64});
    bench.brick("boss", {24.75, 16.66, 28.64}, {5.46, 13.34, 7.9});
    bench.cylinder("foot", {25.91, 20.15, -7.27}, {0, 0, 1}, 3.97, 7.27);
    bench.fuse("part", {"block", "boss", "foot"});
    const std::string file = path("part.step");
    bench.write(file);
    return file;
  }
  // The smallest scaled Jacobian `cooperage quality` finds in a file.
  static double file_minimum(const std::string& file) {
    const auto q = run_command(kCli + " quality " + file);
    EXPECT_EQ(q.exit_code, 0) << q.out << q.err;
    std::smatch m;
    const std::regex row(R"(\n  scaled_jacobian +([-0-9.eE+]+))");
    EXPECT_TRUE(std::regex_search(q.out, m, row)) << q.out;
    return m.empty() ? -1.0 : std::stod(m[1].str());
  }
};

TEST_F(MinScaledJacobianOption, AVolumeBelowItIsMeshedAgainAtHalfItsSize) {
  const std::string step = boss_over_foot_step();
  const auto plain = run_command(kCli + " mesh -q " + step + " --size 4.39 -o " + path("a.vtu"));
  ASSERT_EQ(plain.exit_code, 0) << plain.out << plain.err;
  const double coarse = file_minimum(path("a.vtu"));
  EXPECT_LT(coarse, 0.05);
  EXPECT_GT(coarse, 0.0);

  const auto floored = run_command(kCli + " mesh -q " + step +
                                   " --size 4.39 --min-scaled-jacobian 0.05 -o " + path("b.vtu"));
  ASSERT_EQ(floored.exit_code, 0) << floored.out << floored.err;
  EXPECT_NE((floored.out + floored.err)
                .find("volume 1: meshed at size 2.195, half the size asked for (4.39), "
                      "where its worst element's scaled Jacobian was"),
            std::string::npos)
      << floored.out << floored.err;
  const double fine = file_minimum(path("b.vtu"));
  EXPECT_GE(fine, 0.05);
  std::printf("[min scaled Jacobian] %.4g at 4.39, %.4g with the floor 0.05\n", coarse, fine);
}

TEST_F(MinScaledJacobianOption, AFloorNoSizeReachesFailsWithoutAFile) {
  const std::string step = boss_over_foot_step();
  const auto r = run_command(kCli + " mesh -q " + step +
                             " --size 4.39 --min-scaled-jacobian 0.99 -o " + path("c.vtu"));
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_FALSE(fs::exists(path("c.vtu")));
  const auto bad = run_command(kCli + " mesh -q " + step +
                               " --size 4.39 --min-scaled-jacobian 2 -o " + path("d.vtu"));
  EXPECT_EQ(bad.exit_code, 2) << bad.out << bad.err;
  EXPECT_FALSE(fs::exists(path("d.vtu")));
}

}  // namespace
}  // namespace cooperage
