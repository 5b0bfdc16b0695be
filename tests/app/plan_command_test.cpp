// `cooperage plan` prints a cooper volume's barrel tree (issue 15): the
// barrels, their caps and subcaps, the imprint operations; in text and JSON.
// It takes the options of `mesh` that change a plan.
#include "run_command.h"
#include "temp_dir.h"

#include "support/paper_parts.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace cooperage {
namespace {

namespace fs = std::filesystem;
using testing::run_command;

using testing::kCli;
using testing::kSource;

class PlanCommand : public testing::TempDirTest {};

TEST_F(PlanCommand, PrintsTheBarrelTreeOfABlindHole) {
  fs::copy_file(kSource + "/examples/blind_hole.xml", path("blind_hole.xml"));
  const auto r = run_command(kCli + " plan " + path("blind_hole.xml"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // Two barrels along z: the tube around the hole, then the block below
  // the floor, whose upper cap is the floor and the tube's virtual cap.
  EXPECT_NE(r.out.find("cooper plan of volume 1: 2 barrels, straight along (0, 0, -1)"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("barrel 1: sides"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("lower: virtual cap into barrel 2"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("virtual cap from barrel 1"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("subtract"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("(by the sweep)"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(path("blind_hole.vtu")));  // nothing meshed
}

TEST_F(PlanCommand, JsonCarriesTheBarrelTree) {
  fs::copy_file(kSource + "/examples/blind_hole.xml", path("blind_hole.xml"));
  const auto j = run_command(kCli + " plan --json " + path("blind_hole.xml"));
  ASSERT_EQ(j.exit_code, 0) << j.err;
  std::ofstream(path("plan.json")) << j.out;
  const auto check =
      run_command(std::string(COOPERAGE_DEBIAN_PYTHON) + " -c \"import json; d=json.load(open('" +
                  path("plan.json") +
                  "')); t=d['volumes'][0]['barrel_tree']; b=t['barrels']; "
                  "print(len(b), t['direction'], b[0]['operation'], b[1]['operation'], "
                  "[p.get('virtual_from_barrel', p.get('meshed_by')) for p in b[1]['upper']], "
                  "[p.get('meshed_by') for p in b[1]['lower']])\"");
  ASSERT_EQ(check.exit_code, 0) << check.err;
  EXPECT_EQ(check.out, "2 [0, 0, -1] match subtract ['pave', 1] ['cooper']\n") << j.out;
}

// `plan --dim 2` plans the surfaces alone, as `mesh --dim 2` does: no
// volume section, and the selector's surface-only changes are listed (the
// square boss 0.05 from the block's edge of
// tests/selector/starved_curves_test.cpp: its mapped faces are paved to
// free the thin strip's curves). In 3D the same faces are the sweep's.
TEST_F(PlanCommand, DimTwoPlansTheSurfacesAlone) {
  std::ofstream(path("thin.xml")) << R"(<?xml version="1.0"?>
<cooperage version="1">
  <geometry>
    <brick name="block" origin="0 0 0" size="10 10 3"/>
    <brick name="boss" origin="3 0.05 3" size="4 4 2"/>
    <fuse name="part" inputs="block boss"/>
  </geometry>
  <mesh size="1"/>
</cooperage>
)";
  const auto two = run_command(kCli + " plan --dim 2 " + path("thin.xml"));
  ASSERT_EQ(two.exit_code, 0) << two.err;
  EXPECT_EQ(two.out.find("volumes\n"), std::string::npos) << two.out;
  EXPECT_EQ(two.out.find("cooper plan"), std::string::npos) << two.out;
  EXPECT_NE(two.out.find("relaxed surface "), std::string::npos) << two.out;
  EXPECT_NE(two.out.find(" -> pave (curve "), std::string::npos) << two.out;
  const auto three = run_command(kCli + " plan " + path("thin.xml"));
  ASSERT_EQ(three.exit_code, 0) << three.err;
  EXPECT_NE(three.out.find("volume 1: cooper"), std::string::npos) << three.out;
  EXPECT_EQ(three.out.find(" -> pave (curve "), std::string::npos) << three.out;
  const auto bad = run_command(kCli + " plan --dim 1 " + path("thin.xml"));
  EXPECT_NE(bad.exit_code, 0);
}

// A plan shows what `mesh` with the same options would do: --decompose,
// --no-imprint and --elements change it as they change the mesh. The
// paper's Fig. 3a solid (no volume scheme takes it whole) and two bricks
// that touch on a face.
TEST_F(PlanCommand, TakesTheOptionsOfMeshThatChangeThePlan) {
  occ::Workbench bench;
  testing::build_fig3a(bench);
  const std::string fig3a = path("fig3a.step");
  bench.write(fig3a);
  const auto cut = run_command(kCli + " plan " + fig3a + " --size 0.25");
  ASSERT_EQ(cut.exit_code, 0) << cut.err;
  EXPECT_NE(cut.out.find("cut into volumes"), std::string::npos) << cut.out;
  const auto off = run_command(kCli + " plan " + fig3a + " --size 0.25 --decompose off");
  EXPECT_EQ(off.exit_code, 2) << off.out;
  EXPECT_NE(off.err.find("volume 1: no hex scheme applies"), std::string::npos) << off.err;
  EXPECT_EQ(off.out.find("cut into volumes"), std::string::npos) << off.out;

  occ::Workbench pair;
  pair.brick("a", {0, 0, 0}, {2, 1, 1});
  pair.brick("b", {2, 0, 0}, {1, 1, 1});
  const std::string bricks = path("bricks.step");
  pair.write(bricks);
  // Merged, the touching face is one surface of both volumes (11 in all);
  // kept apart, each brick has its own six.
  const std::string count_surfaces =
      std::string(COOPERAGE_DEBIAN_PYTHON) +
      " -c \"import json,sys; d=json.load(sys.stdin); print(len(d['volumes']), "
      "len(d['surfaces']), [c['scheme'] for c in d['volumes'][0]['candidates']])\"";
  const auto merged =
      run_command(kCli + " plan --json " + bricks + " --size 0.5 | " + count_surfaces);
  ASSERT_EQ(merged.exit_code, 0) << merged.err;
  EXPECT_EQ(merged.out, "2 11 ['map', 'cooper']\n");
  const auto apart =
      run_command(kCli + " plan --json " + bricks + " --size 0.5 --no-imprint | " + count_surfaces);
  ASSERT_EQ(apart.exit_code, 0) << apart.err;
  EXPECT_EQ(apart.out, "2 12 ['map', 'cooper']\n");
  // Wedges come from sweeps only: the volume map is no candidate.
  const auto wedges = run_command(kCli + " plan --json " + bricks +
                                  " --size 0.5 --elements wedge | " + count_surfaces);
  ASSERT_EQ(wedges.exit_code, 0) << wedges.err;
  EXPECT_EQ(wedges.out, "2 11 ['cooper']\n");
  // A surface mesh has no wedges: planning one in wedges is refused, as
  // `mesh --dim 2 --elements wedge` is.
  const auto flat = run_command(kCli + " plan --dim 2 " + bricks + " --size 0.5 --elements wedge");
  EXPECT_EQ(flat.exit_code, 2);
  EXPECT_NE(flat.err.find("asks for volume elements"), std::string::npos) << flat.err;

  // A journal sets how its solids merge; its decomposition and element
  // kind can be overridden as its size can.
  std::ofstream(path("fig3a.xml")) << "<cooperage version=\"1\"><geometry>"
                                      "<import name=\"p\" file=\""
                                   << fig3a << "\"/></geometry><mesh size=\"0.25\"/></cooperage>\n";
  const auto journal_off = run_command(kCli + " plan " + path("fig3a.xml") + " --decompose off");
  EXPECT_EQ(journal_off.exit_code, 2) << journal_off.out;
  EXPECT_NE(journal_off.err.find("no hex scheme applies"), std::string::npos) << journal_off.err;
  const auto journal_wedges =
      run_command(kCli + " plan " + path("fig3a.xml") + " --elements wedge");
  EXPECT_EQ(journal_wedges.exit_code, 0) << journal_wedges.err;
  EXPECT_NE(journal_wedges.out.find("no wedge scheme applies"), std::string::npos)
      << journal_wedges.out;
  const auto journal_apart = run_command(kCli + " plan " + path("fig3a.xml") + " --no-imprint");
  EXPECT_EQ(journal_apart.exit_code, 2);
  EXPECT_NE(journal_apart.err.find("--no-imprint is for a CAD file"), std::string::npos)
      << journal_apart.err;
}

// `plan` refuses the sizes `mesh` refuses before planning, with the same
// message, and takes the same --max-elements: a size in the wrong unit
// (1e-7 on a 60-long part) had `plan` run for 10 s and show a plan.
TEST_F(PlanCommand, RefusesTheSizesMeshRefuses) {
  occ::Workbench bench;
  bench.brick("b", {0, 0, 0}, {2, 3, 4});
  const std::string brick = path("brick.step");
  bench.write(brick);
  // 0.5: 192 hexes and 208 quads; 0.1: 24,000 hexes and 5,200 quads.
  for (const char* size : {"0.5", "0.1"}) {
    const std::string args = brick + " --size " + size + " --max-elements 1e4";
    const auto plan = run_command(kCli + " plan " + args);
    const auto mesh = run_command(kCli + " mesh " + args + " -q -o " + path("b.vtu"));
    EXPECT_EQ(plan.exit_code, mesh.exit_code) << size << ": " << plan.err << mesh.err;
    EXPECT_EQ(plan.exit_code, std::string(size) == "0.5" ? 0 : 2) << size << ": " << plan.err;
  }
  const auto tiny = run_command(kCli + " plan " + brick + " --size 1e-7");
  EXPECT_EQ(tiny.exit_code, 2);
  EXPECT_EQ(tiny.out, "");
  EXPECT_NE(tiny.err.find("the mesh would have about 2.4e+22 elements"), std::string::npos)
      << tiny.err;
}

}  // namespace
}  // namespace cooperage
