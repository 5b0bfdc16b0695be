// Issue 20, start-up: OCCT's STEP/IGES toolkits are loaded only when a STEP
// or IGES file is read or written, its loft toolkit (with the fillet and
// boolean toolkits it needs) only for a <loft>, CBC only for a run that
// assigns intervals (framework/core/lazy_module.h). The
// dynamic loader's own trace (LD_DEBUG=files names every library it opens)
// tells which libraries a command mapped.
#include "run_command.h"
#include "temp_dir.h"

#include "framework/geometry/occ/workbench.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <initializer_list>
#include <sstream>
#include <string>
#include <vector>

namespace cooperage {
namespace {

using testing::kCli;

// A line "file=<name or path of library...>" of the trace.
bool opened(const std::string& trace, const std::string& library) {
  std::istringstream lines(trace);
  for (std::string line; std::getline(lines, line);) {
    const size_t at = line.find("file=");
    if (at != std::string::npos && line.find(library, at) != std::string::npos) return true;
  }
  return false;
}

class StartupLibraries : public testing::TempDirTest {
 protected:
  // Shell commands that copy an example journal into the scratch directory
  // and enter it (its exports land there, not in the source tree).
  std::string journal_here(const std::string& example) const {
    return "cp " + std::string(COOPERAGE_SOURCE_DIR) + "/examples/" + example + " " +
           dir_.string() + " && cd " + dir_.string();
  }

  // A 2 x 3 x 4 brick written in the scratch directory in each file format.
  void write_brick(std::initializer_list<const char*> files) {
    occ::Workbench bench;
    bench.brick("b", {0, 0, 0}, {2, 3, 4});
    for (const char* file : files) bench.write(path(file), {});
  }

  // Runs `command`, whose "LD_DEBUG=files " gets LD_DEBUG_OUTPUT beside it:
  // the loader writes one trace per process, so the import's child (which
  // opens the STEP module; its stderr goes to /dev/null) is traced too.
  // `err` holds every process's trace; `traces` them one by one.
  struct Traced : testing::CommandResult {
    std::vector<std::string> traces;
  };
  Traced traced(const std::string& command) {
    const std::string base = "trace" + std::to_string(++runs_);
    const std::string marker = "LD_DEBUG=files ";
    std::string full = command;
    full.insert(full.find(marker) + marker.size(),
                "LD_DEBUG_OUTPUT=" + (dir_ / base).string() + " ");
    Traced r;
    static_cast<testing::CommandResult&>(r) = testing::run_command(full);
    std::vector<std::filesystem::path> files;
    for (const auto& e : std::filesystem::directory_iterator(dir_))
      if (e.path().filename().string().rfind(base + ".", 0) == 0) files.push_back(e.path());
    std::sort(files.begin(), files.end());
    for (const auto& f : files) {
      r.traces.push_back(testing::slurp(f.string()));
      r.err += r.traces.back();
    }
    return r;
  }

 private:
  int runs_ = 0;
};

TEST_F(StartupLibraries, AJournalRunMapsNoStepOrIgesToolkit) {
  const auto version = traced("LD_DEBUG=files " + kCli + " --version");
  ASSERT_EQ(version.exit_code, 0) << version.err;
  EXPECT_TRUE(opened(version.err, "libTKernel")) << "the trace should name OCCT's kernel";
  const auto run =
      traced(journal_here("brick.xml") + " && LD_DEBUG=files " + kCli + " run -q brick.xml");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  for (const char* toolkit :
       {"libTKSTEP", "libTKIGES", "libTKXSBase", "libTKOffset", "libTKFillet", "libTKBool"}) {
    EXPECT_FALSE(opened(version.err, toolkit)) << toolkit << " mapped by --version";
    EXPECT_FALSE(opened(run.err, toolkit)) << toolkit << " mapped by a journal of primitives";
  }
}

TEST_F(StartupLibraries, OcctsKernelIsNearTheFrontOfTheLookupScope) {
  // Every symbol reference is resolved by walking the scope in order
  // (cmake/CooperageLookupOrder.cmake); OCCT's toolkits refer mostly to
  // themselves, TKernel and TKMath, which the link order had put last (28th
  // and 27th of 30).
  const auto run = testing::run_command("LD_DEBUG=scopes " + kCli + " --version");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const size_t at = run.err.find("scope 0:");
  ASSERT_NE(at, std::string::npos) << run.err;
  std::istringstream scope(run.err.substr(at + 8, run.err.find('\n', at) - at - 8));
  std::vector<std::string> objects;
  for (std::string o; scope >> o;) objects.push_back(o);
  auto position = [&](const std::string& name) {
    for (size_t k = 0; k < objects.size(); ++k)
      if (objects[k].find(name) != std::string::npos) return static_cast<int>(k);
    return -1;
  };
  ASSERT_GT(objects.size(), 20u);
  for (const char* toolkit : {"libTKernel", "libTKMath", "libTKGeomAlgo"}) {
    const int k = position(toolkit);
    EXPECT_GE(k, 1) << toolkit;
    EXPECT_LE(k, 6) << toolkit << " is object " << k << " of " << objects.size();
  }
}

TEST_F(StartupLibraries, AStepOrIgesFileLoadsItsFormatsModuleAlone) {
  write_brick({"b.step", "b.igs"});
  const auto step = traced("LD_DEBUG=files " + kCli + " info " + path("b.step"));
  const auto iges = traced("LD_DEBUG=files " + kCli + " info " + path("b.igs"));
  for (const auto* r : {&step, &iges}) {
    ASSERT_EQ(r->exit_code, 0) << r->err;
    EXPECT_NE(r->out.find("1 volumes, 6 surfaces"), std::string::npos) << r->out;
    EXPECT_TRUE(opened(r->err, "libTKXSBase"));
  }
  EXPECT_TRUE(opened(step.err, "libcooperage_occ_step"));
  EXPECT_TRUE(opened(iges.err, "libcooperage_occ_iges"));
  // A STEP run maps none of IGES's toolkits (TKIGES needs TKBool: 17,600
  // relocations), and an IGES run none of STEP's.
  for (const char* library : {"libcooperage_occ_iges", "libTKIGES", "libTKBool"})
    EXPECT_FALSE(opened(step.err, library)) << library << " mapped by a STEP run";
  for (const char* library : {"libcooperage_occ_step", "libTKSTEP"})
    EXPECT_FALSE(opened(iges.err, library)) << library << " mapped by an IGES run";
}

TEST_F(StartupLibraries, TheImportsChildAloneOpensTheStepModule) {
  // The command has one thread when it imports, so its child loads the
  // module and the command itself never maps STEP's toolkits.
  write_brick({"b.step"});
  const auto info = traced("LD_DEBUG=files " + kCli + " info " + path("b.step"));
  ASSERT_EQ(info.exit_code, 0) << info.err;
  // Each trace line starts with the pid of the process that wrote it.
  auto pid_opening = [&](const std::string& library) {
    std::istringstream lines(info.err);
    for (std::string line; std::getline(lines, line);) {
      const size_t at = line.find("file=");
      if (at != std::string::npos && line.find(library, at) != std::string::npos)
        return std::stol(line);
    }
    return 0L;
  };
  const long command = pid_opening("libTKernel");  // mapped at start-up
  const long module = pid_opening("libcooperage_occ_step");
  ASSERT_NE(command, 0) << info.err;
  ASSERT_NE(module, 0) << info.err;
  EXPECT_NE(module, command) << "the command itself opened the STEP module";
}

TEST_F(StartupLibraries, CbcIsLoadedOnlyByARunThatAssignsIntervals) {
  write_brick({"b.step"});
  const auto version = traced("LD_DEBUG=files " + kCli + " --version");
  const auto info = traced("LD_DEBUG=files " + kCli + " info " + path("b.step"));
  const auto mesh = traced("LD_DEBUG=files " + kCli + " mesh " + path("b.step") +
                           " --size 1 -q -o " + path("b.vtu"));
  for (const auto* r : {&version, &info, &mesh}) ASSERT_EQ(r->exit_code, 0) << r->err;
  for (const char* library : {"libcooperage_cbc", "libCbc", "libClp", "libCoinUtils", "libOsi"}) {
    EXPECT_FALSE(opened(version.err, library)) << library << " mapped by --version";
    EXPECT_FALSE(opened(info.err, library)) << library << " mapped by info";
  }
  EXPECT_TRUE(opened(mesh.err, "libcooperage_cbc"));
  EXPECT_TRUE(opened(mesh.err, "libCbcSolver"));
  EXPECT_TRUE(std::filesystem::exists(path("b.vtu")));
}

TEST_F(StartupLibraries, ALoftLoadsTheLoftModule) {
  const auto run = traced(journal_here("twisted_block.xml") + " && LD_DEBUG=files " + kCli +
                          " run -q twisted_block.xml");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(opened(run.err, "libcooperage_occ_loft"));
  EXPECT_TRUE(opened(run.err, "libTKOffset"));
  EXPECT_FALSE(opened(run.err, "libTKSTEP"));
}

TEST_F(StartupLibraries, CooperageModuleDirIsLookedInFirst) {
  // The built module, linked into a scratch directory named by the variable:
  // the loader's trace shows the one it opened.
  write_brick({"b.step"});
  const auto where = traced("LD_DEBUG=files " + kCli + " info " + path("b.step"));
  ASSERT_EQ(where.exit_code, 0) << where.err;
  std::string built;
  std::istringstream lines(where.err);
  for (std::string line; std::getline(lines, line);) {
    const size_t at = line.find("file=/");
    const size_t end = line.find("libcooperage_occ_step.so");
    if (at != std::string::npos && end != std::string::npos && end > at)
      built = line.substr(at + 5, end - at - 5) + "libcooperage_occ_step.so";
  }
  ASSERT_FALSE(built.empty()) << where.err;
  const std::filesystem::path modules = dir_ / "modules";
  std::filesystem::create_directories(modules);
  std::filesystem::create_symlink(built, modules / "libcooperage_occ_step.so");
  const auto run = traced("COOPERAGE_MODULE_DIR=" + modules.string() + " LD_DEBUG=files " + kCli +
                          " info " + path("b.step"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(opened(run.err, (modules / "libcooperage_occ_step.so").string())) << run.err;
}

}  // namespace
}  // namespace cooperage
