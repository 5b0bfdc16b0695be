// `--report` of `cooperage mesh`, `run` and `quality`: the HTML report is
// written next to the mesh, atomically, and a bad path is exit code 2 with
// no file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "framework/geometry/occ/workbench.h"
#include "run_command.h"
#include "temp_dir.h"

namespace cooperage {
namespace {

namespace fs = std::filesystem;
using testing::run_command;
using testing::slurp;

using testing::kCli;

class ReportOption : public testing::TempDirTest {
 protected:
  void SetUp() override {
    TempDirTest::SetUp();
    occ::Workbench bench;
    bench.brick("a", {0, 0, 0}, {1, 1, 1});
    bench.brick("b", {1, 0, 0}, {1, 1, 1});
    bench.write(path("pair.step"));
  }
  bool leftovers() const {
    for (const auto& e : fs::directory_iterator(dir_)) {
      if (e.path().filename().string().find(".tmp-") != std::string::npos) return true;
    }
    return false;
  }
};

TEST_F(ReportOption, MeshWritesTheMeshAndTheReport) {
  const auto r = run_command(kCli + " mesh " + path("pair.step") + " --size 0.25 -q -o " +
                             path("pair.exo") + " --report " + path("pair.html"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("wrote " + path("pair.html")), std::string::npos) << r.out;
  ASSERT_TRUE(fs::exists(path("pair.exo")));
  const std::string html = slurp(path("pair.html"));
  EXPECT_NE(html.find("Cooperage report: " + path("pair.step")), std::string::npos);
  EXPECT_NE(html.find("<b>128</b> hexes"), std::string::npos);
  EXPECT_NE(html.find("data-picture=\"1\""), std::string::npos) << "one picture per volume";
  EXPECT_FALSE(leftovers());
}

TEST_F(ReportOption, QualityReportsAnExistingFile) {
  ASSERT_EQ(run_command(kCli + " mesh " + path("pair.step") + " --size 0.25 -q -o " + path("p.vtu"))
                .exit_code,
            0);
  const auto q = run_command(kCli + " quality " + path("p.vtu") + " --report " + path("q.html"));
  ASSERT_EQ(q.exit_code, 0) << q.err;
  EXPECT_NE(q.out.find("wrote " + path("q.html")), std::string::npos) << q.out;
  const std::string html = slurp(path("q.html"));
  EXPECT_NE(html.find("<b>128</b> hexes"), std::string::npos);
  // With --json, stdout stays one JSON object.
  const auto j =
      run_command(kCli + " quality " + path("p.vtu") + " --json --report " + path("q2.html"));
  ASSERT_EQ(j.exit_code, 0) << j.err;
  EXPECT_EQ(j.out.find("wrote"), std::string::npos);
  EXPECT_TRUE(fs::exists(path("q2.html")));
}

TEST_F(ReportOption, RunAddsAReportToTheJournal) {
  std::ofstream(path("job.xml"))
      << "<cooperage version=\"1\"><geometry><brick name=\"b\" size=\"1 1 1\"/>"
         "</geometry><mesh size=\"0.5\"/></cooperage>\n";
  const auto r = run_command(kCli + " run -q " + path("job.xml") + " --report " + path("job.html"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(slurp(path("job.html")).find("<b>8</b> hexes"), std::string::npos);
}

TEST_F(ReportOption, UnwritableReportIsExitCode2AndLeavesNoFile) {
  const std::string bad = path("missing_dir/r.html");
  const auto r = run_command(kCli + " mesh " + path("pair.step") + " --size 0.25 -q -o " +
                             path("pair.vtu") + " --report " + bad);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("r.html"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(path("missing_dir")));
  EXPECT_FALSE(leftovers());
  const auto q = run_command(kCli + " quality " + path("pair.vtu") + " --report " + bad);
  EXPECT_EQ(q.exit_code, 2);
  EXPECT_FALSE(fs::exists(path("missing_dir")));
}

}  // namespace
}  // namespace cooperage
