// The `cooperage` command under hostile input (issue 21; issue 16 item 5):
// damaged CAD and mesh files, runaway sizes, assemblies with a volume that
// cannot be meshed. Exit codes 0/1/2 only, an error in at most three lines
// without a journal prefix for a command-line run, no file left behind.
#include "run_command.h"
#include "temp_dir.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

namespace cooperage {
namespace {

namespace fs = std::filesystem;
using testing::run_command;

using testing::kCli;
using testing::kSource;
const std::string kCad = kSource + "/tests/framework/geometry/occ/data/";

using testing::lines;

class ReliabilityCommand : public testing::TempDirTest {
 protected:
  std::string journal(const std::string& name, const std::string& body) const {
    std::ofstream(path(name)) << "<cooperage version=\"1\">\n" << body << "</cooperage>\n";
    return path(name);
  }
  std::vector<std::string> files() const {
    std::vector<std::string> out;
    for (const auto& e : fs::directory_iterator(dir_))
      if (e.path().extension() != ".xml") out.push_back(e.path().filename().string());
    std::sort(out.begin(), out.end());
    return out;
  }
};

TEST_F(ReliabilityCommand, ACrashingCadFileIsAnErrorWithoutJournalPrefix) {
  const auto r = run_command(kCli + " mesh " + kCad + "damaged/crash_brick.step --size 1 -o " +
                             path("out.vtu"));
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(lines(r.err), 1u) << r.err;
  EXPECT_NE(r.err.find("crash_brick.step: the CAD kernel could not read it (it crashed"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(r.err.find(":0:"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("<import>"), std::string::npos) << r.err;
  EXPECT_TRUE(files().empty());
  const auto info = run_command(kCli + " info " + kCad + "damaged/crash_brick.step");
  EXPECT_EQ(info.exit_code, 2) << info.err;
}

TEST_F(ReliabilityCommand, AnInvalidBrepIsRefusedNotMeshed) {
  const auto r = run_command(kCli + " mesh " + kCad +
                             "damaged/vertex_off_edges.brep --size 0.5 -o " + path("out.exo"));
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("the B-rep is not valid"), std::string::npos) << r.err;
  EXPECT_LE(lines(r.err), 3u) << r.err;
  EXPECT_TRUE(files().empty());
}

TEST_F(ReliabilityCommand, ARunawaySizeIsRefusedWithTheEstimate) {
  const auto r =
      run_command(kCli + " mesh " + kCad + "brick.step --size 1e-4 -o " + path("out.exo"));
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("the mesh would have about"), std::string::npos) << r.err;
  EXPECT_TRUE(files().empty());
  const auto raised = run_command(kCli + " mesh " + kCad +
                                  "brick.step --size 0.5 --max-elements 100 -o " + path("out.exo"));
  EXPECT_EQ(raised.exit_code, 2) << raised.err;
  EXPECT_NE(raised.err.find("the limit is 1e+02"), std::string::npos) << raised.err;
}

TEST_F(ReliabilityCommand, ADamagedExodusFileIsAnErrorInBoundedTime) {
  std::ifstream in(kSource + "/tests/framework/io/read/data/brick.exo", std::ios::binary);
  std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  bytes.resize(bytes.size() / 3);
  std::ofstream(path("cut.exo"), std::ios::binary) << bytes;
  const auto r = run_command(kCli + " quality " + path("cut.exo"));
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(lines(r.err), 1u) << r.err;
}

const char* kAssembly = R"(  <geometry>
    <brick name="box" origin="0 0 0" size="2 2 2"/>
    <cylinder name="rod" base="10 0 0" axis="0 0 1" radius="1" height="2"/>
  </geometry>
  <mesh size="0.5"><volume id="2" scheme="map"/></mesh>
  <export file="out.vtu"/>
)";

TEST_F(ReliabilityCommand, AnAssemblyPrintsEveryVerdictAndAShortError) {
  const auto r = run_command(kCli + " run -q " + journal("asm.xml", kAssembly));
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.out.find("volume 1: meshed"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("volume 2: refused: "), std::string::npos) << r.out;
  EXPECT_LE(lines(r.err), 3u) << r.err;
  EXPECT_NE(r.err.find("--allow-partial"), std::string::npos) << r.err;
  EXPECT_TRUE(files().empty());
}

// Campaign case 1810 (2026-12-02): four touching bricks, where the foot
// takes the block's mesh of their shared face (it waits for the block). The
// block failed in meshing, the foot was refused for it, and the mesher then
// stopped with an internal error (exit 3) because nothing was left to mesh.
TEST_F(ReliabilityCommand, AVolumeWaitingForAFailedNeighbourIsRefusedNotAnInternalError) {
  const char* body = R"(  <geometry>
    <brick name="block" origin="0 0 0" size="6 4 2"/>
    <brick name="boss1" origin="1 1 2" size="1.5 1.5 1"/>
    <brick name="boss2" origin="0 0.25 2" size="1 0.75 0.5"/>
    <brick name="foot" origin="3.5 1.5 -1" size="1.5 1.5 1"/>
  </geometry>
  <mesh size="0.25"/>
  <export file="out.vtu"/>
)";
  const auto r = run_command(kCli + " run -q " + journal("touching.xml", body));
  EXPECT_NE(r.exit_code, 3) << r.err;
  if (r.exit_code == 0) {  // once the block meshes, everything must
    EXPECT_EQ(files(), std::vector<std::string>{"out.vtu"});
    return;
  }
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.out.find("volume 4: refused: it takes the mesh of a shared surface from volume 1"),
            std::string::npos)
      << r.out;
  EXPECT_TRUE(files().empty());
}

TEST_F(ReliabilityCommand, AllowPartialWritesWhatMeshedAndExitsOne) {
  const auto r = run_command(kCli + " run -q --allow-partial " + journal("asm.xml", kAssembly));
  EXPECT_EQ(r.exit_code, 1) << r.err << r.out;
  EXPECT_NE(r.out.find("volume 2: refused"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("partial"), std::string::npos) << r.out;
  EXPECT_EQ(files(), std::vector<std::string>{"out.vtu"});
  const auto q = run_command(kCli + " quality " + path("out.vtu"));
  EXPECT_EQ(q.exit_code, 0) << q.err;
  EXPECT_NE(q.out.find("64 elements"), std::string::npos) << q.out;
}

TEST_F(ReliabilityCommand, ATighterVolumeToleranceFailsTheRunWithExitOne) {
  // A coarse rod deviates a little from the CAD's volume even after the
  // faceting credit; a tolerance below that fails the run and writes nothing.
  const std::string job = journal(
      "rod.xml",
      R"(  <geometry><cylinder name="rod" base="0 0 0" axis="0 0 1" radius="5" height="20"/></geometry>
  <mesh size="5"/>
  <export file="rod.exo"/>
)");
  const auto ok = run_command(kCli + " run -q " + job);
  EXPECT_EQ(ok.exit_code, 0) << ok.err << ok.out;
  fs::remove(path("rod.exo"));
  const auto tight = run_command(kCli + " run -q --volume-tolerance 1e-6 " + job);
  EXPECT_EQ(tight.exit_code, 1) << tight.err << tight.out;
  EXPECT_NE(tight.out.find("volume 1: failed the volume check"), std::string::npos) << tight.out;
  EXPECT_NE(tight.out.find("exports skipped: a volume check failed"), std::string::npos)
      << tight.out;
  EXPECT_TRUE(files().empty());
}

TEST_F(ReliabilityCommand, AnExportIntoAMissingDirectoryIsRefusedBeforeMeshing) {
  const auto r =
      run_command(kCli + " mesh " + kCad + "brick.step --size 1 -o " + path("no/dir/x.exo"));
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("does not exist"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find(":0:"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace cooperage
