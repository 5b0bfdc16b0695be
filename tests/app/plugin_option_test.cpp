// Plug-ins on the command line: `cooperage schemes` lists every scheme with
// its origin; --plugin (before or after the subcommand), a journal's
// <plugin> (relative to the journal) and COOPERAGE_PLUGIN_PATH load the
// example plug-in, whose scheme the selector then picks for triangles; a
// broken plug-in or an unknown pin is exit code 2 with the reason and no mesh.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <vector>

#include "run_command.h"
#include "temp_dir.h"

namespace cooperage {
namespace {

namespace fs = std::filesystem;
using testing::run_command;

using testing::kCli;
const std::string kPlugin = COOPERAGE_TEST_TRIPRIMITIVE;

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// An equilateral triangle of side 2 extruded by 1 (surfaces 1..3 are the
// rectangles), meshed by cooper at size 0.3.
std::string prism_journal(const std::string& plugin_line, const std::string& mesh_lines = "") {
  return "<cooperage version=\"1\">\n" + plugin_line +
         "<geometry><prism name=\"p\" direction=\"0 0 1\">"
         "<profile points=\"0 0 0, 2 0 0, 1 1.7320508075688772 0\"/></prism></geometry>\n"
         "<mesh size=\"0.3\">" +
         mesh_lines +
         "</mesh>\n<export file=\"prism.vtu\"/>\n"
         "</cooperage>\n";
}

class PluginOption : public testing::TempDirTest {
 protected:
  void write(const std::string& name, const std::string& text) {
    std::ofstream(path(name)) << text;
  }
};

TEST_F(PluginOption, SchemesListsTheBuiltInsAndThePluginsOrigin) {
  auto r = run_command(kCli + " schemes");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* name : {"map", "submap", "pave", "tri", "quad_dominant", "cooper"})
    EXPECT_TRUE(contains(r.out, name)) << r.out;
  EXPECT_TRUE(contains(r.out, "built in")) << r.out;
  EXPECT_FALSE(contains(r.out, "triprimitive")) << r.out;
  const std::string canonical = fs::canonical(kPlugin).string();
  for (const std::string& args : std::vector<std::string>{
           " --plugin " + kPlugin + " schemes --json", " schemes --json --plugin " + kPlugin}) {
    r = run_command(kCli + args);
    ASSERT_EQ(r.exit_code, 0) << args << ": " << r.err;
    EXPECT_TRUE(contains(r.out, "\"triprimitive\"")) << r.out;
    EXPECT_TRUE(contains(r.out, "\"" + canonical + "\"")) << r.out;
  }
}

TEST_F(PluginOption, TheSelectorPicksThePluginsSchemeForACapAndMeshes) {
  write("job.xml", prism_journal(""));
  auto r = run_command(kCli + " --plugin " + kPlugin + " plan " + path("job.xml"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "triprimitive")) << r.out;
  r = run_command(kCli + " plan " + path("job.xml"));  // without it, pave caps the triangle
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_FALSE(contains(r.out, "triprimitive")) << r.out;
  r = run_command("cd " + dir_.string() + " && " + kCli + " run job.xml -q --plugin " + kPlugin);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(path("prism.vtu")));
}

TEST_F(PluginOption, AJournalLoadsItRelativeToItselfAndPinsItsScheme) {
  fs::create_directories(path("lib"));
  fs::copy_file(kPlugin, path("lib/libtri.so"));
  fs::create_directories(path("jobs"));
  // plan shows the plug-in's applicable() on every surface, both ways.
  write("jobs/job.xml", prism_journal("<plugin file=\"../lib/libtri.so\"/>\n"));
  auto r = run_command(kCli + " plan " + path("jobs/job.xml"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "- triprimitive: surface 1 has 4 corners; triprimitive needs 3"))
      << r.out;
  EXPECT_TRUE(contains(r.out, "+ triprimitive score 0.87")) << r.out;
  // A pin to it on a side face contradicts cooper's role for the side.
  write("jobs/pinned.xml", prism_journal("<plugin file=\"../lib/libtri.so\"/>\n",
                                         "<surface id=\"1\" scheme=\"triprimitive\"/>"));
  r = run_command(kCli + " plan " + path("jobs/pinned.xml"));
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_TRUE(contains(r.err, "surface 1 is pinned to triprimitive")) << r.err;
  // The same pin without the plug-in names the registered schemes.
  write("jobs/bare.xml", prism_journal("", "<surface id=\"1\" scheme=\"triprimitive\"/>"));
  r = run_command("cd " + path("jobs") + " && " + kCli + " run bare.xml -q");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(contains(r.err, "bare.xml:3")) << r.err;
  EXPECT_TRUE(contains(r.err, "no surface scheme \"triprimitive\" is registered")) << r.err;
  EXPECT_TRUE(contains(r.err, "quad_dominant")) << r.err;
  EXPECT_FALSE(fs::exists(path("jobs/prism.vtu")));
}

TEST_F(PluginOption, ThePluginPathVariableLoadsADirectory) {
  fs::create_directories(path("plugins"));
  fs::copy_file(kPlugin, path("plugins/libtri.so"));
  const auto r = run_command("COOPERAGE_PLUGIN_PATH=" + path("plugins") + " " + kCli + " schemes");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "triprimitive")) << r.out;
  EXPECT_TRUE(contains(r.out, fs::canonical(path("plugins/libtri.so")).string())) << r.out;
}

TEST_F(PluginOption, ABrokenPluginIsExitCodeTwoOnEverySubcommandAndNoMesh) {
  write("fake.so", "not a library\n");
  write("job.xml", prism_journal(""));
  for (const std::string& sub :
       std::vector<std::string>{"schemes", "info " + path("job.xml"), "plan " + path("job.xml"),
                                "run -q " + path("job.xml")}) {
    const auto r = run_command(kCli + " --plugin " + path("fake.so") + " " + sub);
    EXPECT_EQ(r.exit_code, 2) << sub;
    EXPECT_TRUE(contains(r.err, "plug-in " + fs::canonical(path("fake.so")).string() +
                                    " (--plugin): cannot be loaded"))
        << sub << ": " << r.err;
  }
  EXPECT_FALSE(fs::exists(path("prism.vtu")));
  const auto r = run_command(kCli + " --plugin " + path("none.so") + " schemes");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(contains(r.err, "none.so (--plugin): no such file")) << r.err;
}

}  // namespace
}  // namespace cooperage
