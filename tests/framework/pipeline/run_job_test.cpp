// A journal run end to end: geometry, meshing, quality checks, exports read
// back by the Exodus library itself.
#include "framework/core/error.h"
#include "framework/io/journal_reader.h"
#include "framework/pipeline/mesher.h"
#include "schemes/builtin_schemes.h"
#include "selector/select_schemes.h"

#include <exodusII.h>
#include "journal_fixture.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace cooperage::pipeline {
namespace {

namespace fs = std::filesystem;

class RunJob : public testing::JournalFixture {};

const char* kTwoBricks = R"(  <geometry>
    <brick name="a" origin="0 0 0" size="1 1 1"/>
    <brick name="b" origin="1 0 0" size="1 1 1"/>
  </geometry>
  <mesh size="0.25"/>
)";

TEST_F(RunJob, TwoMergedBricksExodusHasTwoBlocksAndOneSideSetPerSurface) {
  io::Job job = journal(std::string(kTwoBricks) + "  <export file=\"out.exo\"/>\n");
  const RunResult r = run_job(job, registry_, selector::mesh_options());
  ASSERT_EQ(r.written.size(), 1u);
  const std::string file = (dir_ / "out.exo").string();
  ASSERT_TRUE(fs::exists(file));

  int cpu = 8, io_ws = 0;
  float version = 0;
  const int exo = ex_open(file.c_str(), EX_READ, &cpu, &io_ws, &version);
  ASSERT_GE(exo, 0);
  char title[MAX_LINE_LENGTH + 1];
  int dim = 0, nodes = 0, elems = 0, blocks = 0, node_sets = 0, side_sets = 0;
  ASSERT_EQ(ex_get_init(exo, title, &dim, &nodes, &elems, &blocks, &node_sets, &side_sets), 0);
  EXPECT_EQ(dim, 3);
  EXPECT_EQ(nodes, 9 * 5 * 5);  // shared face nodes exist once
  EXPECT_EQ(elems, 128);
  EXPECT_EQ(blocks, 2);
  EXPECT_EQ(side_sets, static_cast<int>(r.model.surfaces().size()));
  std::vector<int> ids(static_cast<size_t>(side_sets));
  ASSERT_EQ(ex_get_side_set_ids(exo, ids.data()), 0);
  for (int id : ids) {
    int sides = 0, df = 0;
    ASSERT_EQ(ex_get_side_set_param(exo, id, &sides, &df), 0);
    EXPECT_EQ(sides, 16) << "side set " << id;  // every face of a unit cube at 0.25
  }
  ex_close(exo);
}

TEST_F(RunJob, FailingQualityCheckSkipsExports) {
  io::Job job =
      journal(std::string(kTwoBricks) +
              "  <quality metric=\"jacobian\" min=\"1\" action=\"fail\"/>\n"  // each hex: 1/64
              "  <export file=\"out.vtu\"/>\n");
  const RunResult r = run_job(job, registry_, selector::mesh_options());
  EXPECT_TRUE(r.quality.failed());
  EXPECT_TRUE(r.exports_skipped);
  EXPECT_FALSE(fs::exists(dir_ / "out.vtu"));
}

// The exports are written beside the mesher's checks and renamed only
// when the run passes: a failing check leaves neither the file nor the
// private directory it was staged in.
TEST_F(RunJob, FailingQualityCheckLeavesNoStagedExport) {
  io::Job job =
      journal(std::string(kTwoBricks) +
              "  <quality metric=\"jacobian\" min=\"1\" action=\"fail\"/>\n"  // each hex: 1/64
              "  <export file=\"out.exo\"/>\n  <export file=\"out.vtu\"/>\n");
  for (int threads : {1, 2}) {
    const RunResult r = run_job(job, registry_, selector::mesh_options(3, threads));
    EXPECT_TRUE(r.exports_skipped);
    std::vector<std::string> left;
    for (const auto& e : fs::directory_iterator(dir_)) left.push_back(e.path().filename().string());
    EXPECT_EQ(left, std::vector<std::string>{"job.xml"}) << threads << " threads";
  }
}

std::string bytes_of(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

TEST_F(RunJob, ExportsBesideTheChecksAreTheSameOnOneAndTwoThreads) {
  const std::string one = (dir_ / "one.exo").string(), two = (dir_ / "two.exo").string();
  run_job(journal(std::string(kTwoBricks) + "  <export file=\"one.exo\"/>\n"), registry_,
          selector::mesh_options(3, 1));
  run_job(journal(std::string(kTwoBricks) + "  <export file=\"two.exo\"/>\n"), registry_,
          selector::mesh_options(3, 2));
  const std::string a = bytes_of(one), b = bytes_of(two);
  ASSERT_GT(a.size(), 1000u);
  EXPECT_TRUE(a == b);
}

TEST_F(RunJob, WarningCheckCountsButWrites) {
  io::Job job =
      journal(std::string(kTwoBricks) +
              "  <quality metric=\"jacobian\" min=\"1\" action=\"warn\"/>\n"  // each hex: 1/64
              "  <export file=\"out.vtu\"/>\n");
  const RunResult r = run_job(job, registry_, selector::mesh_options());
  EXPECT_FALSE(r.quality.failed());
  ASSERT_EQ(r.quality.checks.size(), 1u);
  EXPECT_EQ(r.quality.checks[0].violations, 128u);
  EXPECT_TRUE(fs::exists(dir_ / "out.vtu"));
}

TEST_F(RunJob, ConflictingHardIntervalsAreReportedWithTheirCurves) {
  // Curves 1 and 3 of a brick face are opposite sides of a map face: pinning
  // them to different counts cannot be satisfied.
  io::Job job = journal(R"(  <geometry><brick name="a" origin="0 0 0" size="1 1 1"/></geometry>
  <mesh size="0.25">
    <curve id="1" intervals="3" firmness="hard"/>
    <curve id="3" intervals="5" firmness="hard"/>
  </mesh>
  <export file="never.exo"/>
)");
  try {
    run_job(job, registry_, selector::mesh_options());
    FAIL() << "infeasible intervals were accepted";
  } catch (const MeshingError& e) {
    EXPECT_EQ(e.code(), ErrorCode::Infeasible) << e.what();
    EXPECT_NE(std::string(e.what()).find("1"), std::string::npos);
  }
  EXPECT_FALSE(fs::exists(dir_ / "never.exo"));
}

TEST_F(RunJob, JournalWithoutMeshIsAnError) {
  io::Job job =
      journal("  <geometry><brick name=\"a\" origin=\"0 0 0\" size=\"1 1 1\"/></geometry>\n");
  EXPECT_THROW(run_job(job, registry_, selector::mesh_options()), MeshingError);
}

}  // namespace
}  // namespace cooperage::pipeline
