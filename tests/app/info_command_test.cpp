// `cooperage info` end to end: the real binary on real files.
#include "run_command.h"
#include "temp_dir.h"

#include "framework/geometry/occ/workbench.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

namespace cooperage {
namespace {

namespace fs = std::filesystem;
using testing::run_command;

using testing::kCli;
using testing::kSource;

class InfoCommand : public testing::TempDirTest {
 protected:
  // A fused boss-on-cylinder written as STEP.
  std::string boss_step() const {
    occ::Workbench bench;
    bench.cylinder("body", {0, 0, 0}, {0, 0, 1}, 2.0, 3.0);
    bench.cylinder("boss", {0, 0, 3}, {0, 0, 1}, 1.0, 1.5);
    bench.fuse("part", {"body", "boss"});
    const std::string file = path("boss.step");
    bench.write(file);
    return file;
  }
};

size_t count_lines(const std::string& s) {
  return static_cast<size_t>(std::count(s.begin(), s.end(), '\n'));
}

TEST_F(InfoCommand, FusedBossStepHasOneVolumeAndTypedSurfaces) {
  const auto r = run_command(kCli + " info " + boss_step());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("1 volumes"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("volume 1"), std::string::npos);
  EXPECT_NE(r.out.find(": cylinder, area"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(": plane, area"), std::string::npos) << r.out;
  EXPECT_EQ(r.err, "");  // nothing from the CAD kernel either
}

TEST_F(InfoCommand, JsonIsValidAndComplete) {
  const std::string json = path("info.json");
  const auto r = run_command(kCli + " info --json " + boss_step());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ofstream(json) << r.out;
  // An independent JSON parser checks the document and its counts.
  const auto check = run_command(
      std::string(COOPERAGE_DEBIAN_PYTHON) + " -c \"import json,sys; d=json.load(open('" + json +
      "')); print(len(d['volumes']), len(d['surfaces']) > 0, d['volumes'][0]['volume'] > 0)\"");
  ASSERT_EQ(check.exit_code, 0) << check.err;
  EXPECT_EQ(check.out, "1 True True\n");
}

// A prism whose profile has an 8-degree corner: both caps have it, the
// rectangular sides have 90 degrees. The text names the corner and the
// scaled Jacobian it allows (sin 8 = 0.139); the JSON gives every face's.
TEST_F(InfoCommand, SharpCornersAreNamedWithTheQualityTheyAllow) {
  const double corner = 8.0 * M_PI / 180.0, tip = 2.0 / std::tan(corner);
  occ::Workbench bench;
  bench.prism("blade", {{0, 0, 0}, {tip + 4, 0, 0}, {tip + 4, 2, 0}, {tip, 2, 0}}, {}, {0, 0, 1});
  const std::string file = path("blade.step");
  bench.write(file);
  const auto text = run_command(kCli + " info " + file);
  ASSERT_EQ(text.exit_code, 0) << text.err;
  size_t named = 0;
  for (size_t at = 0;
       (at = text.out.find("corner of 8 degrees at vertex", at)) != std::string::npos; ++at)
    ++named;
  EXPECT_EQ(named, 2u) << text.out;
  EXPECT_NE(text.out.find("scaled Jacobian 0.139"), std::string::npos) << text.out;
  const auto r = run_command(kCli + " info --json " + file);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string json = path("blade.json");
  std::ofstream(json) << r.out;
  const auto check = run_command(std::string(COOPERAGE_DEBIAN_PYTHON) +
                                 " -c \"import json; d=json.load(open('" + json +
                                 "')); print(sorted(round(float(s['sharpest_corner']['degrees']), "
                                 "6) for s in d['surfaces']))\"");
  ASSERT_EQ(check.exit_code, 0) << check.err;
  EXPECT_EQ(check.out, "[8.0, 8.0, 90.0, 90.0, 90.0, 90.0]\n");
}

TEST_F(InfoCommand, JournalExampleDescribesItsGeometry) {
  const auto r = run_command(kCli + " info " + kSource + "/examples/two_bricks.xml");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("2 volumes"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("volumes 1 2"), std::string::npos) << "a shared surface: " << r.out;
}

TEST_F(InfoCommand, MissingFileIsOneLineAndExitCode2) {
  const auto r = run_command(kCli + " info " + path("nope.step"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(count_lines(r.err), 1u) << r.err;
  EXPECT_NE(r.err.find("nope.step"), std::string::npos) << r.err;
}

TEST_F(InfoCommand, CorruptStepIsOneLineAndExitCode2) {
  const std::string good = boss_step();
  const auto size = fs::file_size(good);
  fs::resize_file(good, size / 2);
  const auto r = run_command(kCli + " info " + good);
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_EQ(count_lines(r.err), 1u) << r.err;
  EXPECT_NE(r.err.find("boss.step"), std::string::npos) << r.err;
}

TEST_F(InfoCommand, MalformedJournalNamesFileAndLine) {
  const std::string bad = path("bad.xml");
  std::ofstream(bad) << "<cooperage version=\"1\">\n  <geometry>\n    <brick name=\"b\"\n";
  const auto r = run_command(kCli + " info " + bad);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(count_lines(r.err), 1u) << r.err;
  EXPECT_NE(r.err.find("bad.xml"), std::string::npos) << r.err;
}

TEST_F(InfoCommand, UnknownOptionIsAnError) {
  const auto r = run_command(kCli + " info --frobnicate x.step");
  EXPECT_EQ(r.exit_code, 2);
}

}  // namespace
}  // namespace cooperage
