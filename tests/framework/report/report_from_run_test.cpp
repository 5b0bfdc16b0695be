// The report of real runs: a journal's <report>, a surface mesh, a failing
// quality check, and a mesh file read back (report_from_file).
#include "framework/report/report_from_run.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "framework/core/error.h"
#include "framework/io/export/write_mesh.h"
#include "framework/io/journal_reader.h"
#include "framework/io/read/read_mesh_file.h"
#include "framework/report/html_report.h"
#include "framework/report/report_from_file.h"
#include "schemes/builtin_schemes.h"
#include "selector/select_schemes.h"

namespace cooperage::report {
namespace {

namespace fs = std::filesystem;

class RunReport : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("cooperage-runreport-" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    register_builtin_schemes(registry_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  pipeline::RunResult run(const std::string& body, int dim = 3) {
    const fs::path file = dir_ / "job.xml";
    std::ofstream(file) << "<cooperage version=\"1\">\n" << body << "</cooperage>\n";
    return pipeline::run_job(io::read_journal(file.string()), registry_,
                             selector::mesh_options(dim));
  }
  static std::string slurp(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }

  fs::path dir_;
  scheme::Registry registry_;
};

// Two merged bricks, 1 x 1 x 1 each at size 0.25: 64 cubes each.
const char* kTwoBricks = R"(  <geometry>
    <brick name="a" origin="0 0 0" size="1 1 1"/>
    <brick name="b" origin="1 0 0" size="1 1 1"/>
  </geometry>
  <mesh size="0.25"/>
)";

TEST_F(RunReport, JournalReportShowsEachVolumeThePlanAndTheStages) {
  const auto r = run(std::string(kTwoBricks) +
                     "  <export file=\"out.vtu\"/>\n  <report file=\"out.html\"/>\n");
  const fs::path report = dir_ / "out.html";
  ASSERT_TRUE(fs::exists(report));
  ASSERT_EQ(r.written.size(), 2u);
  EXPECT_EQ(r.written[1], report.string()) << "reports are listed after the exports";
  const std::string html = slurp(report);
  EXPECT_NE(html.find("data-picture=\"0\" aria-label=\"volume 1 (a)\""), std::string::npos);
  EXPECT_NE(html.find("data-picture=\"1\" aria-label=\"volume 2 (b)\""), std::string::npos);
  EXPECT_EQ(html.find("data-picture=\"2\""), std::string::npos);
  EXPECT_NE(html.find("<b>128</b> hexes"), std::string::npos);
  // A cube's skin at 4 x 4 x 4: 96 faces, the shared face included.
  EXPECT_NE(html.find("64 elements, 96 boundary faces"), std::string::npos);
  // Unit-cube hexes: scaled Jacobian 1 in the last bin, per block.
  EXPECT_NE(html.find("0.95 to 1.00: 64 elements"), std::string::npos);
  EXPECT_NE(html.find("wrote " + (dir_ / "out.vtu").string()), std::string::npos);
  for (const char* stage : {">geometry<", ">plan<", ">intervals<", ">curves<", ">surfaces<",
                            ">volumes<", ">quality<", ">exports<"}) {
    EXPECT_NE(html.find(stage), std::string::npos) << stage;
  }
  // The plan: both volumes by map, with every scheme's verdict as notes.
  EXPECT_NE(html.find("<td>volume 1 (a)</td><td>map</td>"), std::string::npos);
  EXPECT_NE(html.find("+ map score"), std::string::npos);
  EXPECT_NE(html.find("<tr><td>surface 1</td><td>map</td>"), std::string::npos);
}

TEST_F(RunReport, StagesOfTheRunAddUpAndFollowTheDataFlow) {
  const auto r = run(kTwoBricks);
  std::vector<std::string> names;
  for (const auto& s : r.stages) {
    names.push_back(s.stage);
    EXPECT_GE(s.seconds, 0.0);
  }
  const std::vector<std::string> expected = {"geometry", "plan",    "intervals", "curves",
                                             "surfaces", "volumes", "quality"};
  EXPECT_EQ(names, expected);
}

TEST_F(RunReport, FailingCheckSkipsExportsButWritesTheReport) {
  const auto r =
      run(std::string(kTwoBricks) +
          "  <quality metric=\"jacobian\" min=\"1\" action=\"fail\"/>\n"  // each hex: 1/64
          "  <export file=\"out.exo\"/>\n  <report file=\"why.html\"/>\n");
  EXPECT_TRUE(r.exports_skipped);
  EXPECT_FALSE(fs::exists(dir_ / "out.exo"));
  ASSERT_TRUE(fs::exists(dir_ / "why.html"));
  const std::string html = slurp(dir_ / "why.html");
  EXPECT_NE(html.find("quality check jacobian &gt;= 1: 128 elements outside, FAILED"),
            std::string::npos);
  EXPECT_NE(html.find("exports skipped"), std::string::npos);
}

TEST_F(RunReport, SurfaceMeshIsOnePictureOfAllSurfaces) {
  const auto r =
      run("  <geometry><brick name=\"a\" size=\"1 1 1\"/></geometry>\n"
          "  <mesh size=\"0.5\"/>\n",
          2);
  const ReportInput in = report_input(r, "cube");
  ASSERT_EQ(in.blocks.size(), 6u);
  for (const auto& b : in.blocks) {
    EXPECT_EQ(b.part, "all surfaces");
    EXPECT_EQ(b.type, quality::ElementType::Quad);
    EXPECT_EQ(b.normals.size(), b.count) << "signed against the CAD surface";
  }
  const std::string html = render_report(in);
  EXPECT_NE(html.find("<b>24</b> quads"), std::string::npos);
  EXPECT_NE(html.find("24 elements, 24 boundary faces"), std::string::npos);
}

TEST_F(RunReport, MeshFileReportDrawsVolumeBlocks) {
  const auto r = run(std::string(kTwoBricks) + "  <export file=\"out.exo\"/>\n");
  const io::MeshFile file = io::read_mesh_file((dir_ / "out.exo").string());
  const ReportInput in = report_input(file, "out.exo");
  ASSERT_EQ(in.blocks.size(), 2u);
  const std::string html = render_report(in);
  EXPECT_NE(html.find("data-picture=\"1\""), std::string::npos);
  EXPECT_NE(html.find("<b>128</b> hexes"), std::string::npos);
  EXPECT_NE(html.find("<b>" + std::to_string(r.mesh.mesh.node_count()) + "</b> nodes"),
            std::string::npos);
  EXPECT_EQ(html.find("id=\"plan\""), std::string::npos) << "a file has no plan";
}

TEST_F(RunReport, ErrorInTheRunWritesNoReport) {
  EXPECT_THROW(run("  <geometry><brick name=\"a\" size=\"1 1 1\"/></geometry>\n"
                   "  <mesh size=\"0.5\"><volume id=\"1\" scheme=\"cooper\" elements=\"wedge\" "
                   "sources=\"99\"/></mesh>\n  <report file=\"x.html\"/>\n"),
               MeshingError);
  EXPECT_FALSE(fs::exists(dir_ / "x.html"));
}

}  // namespace
}  // namespace cooperage::report
