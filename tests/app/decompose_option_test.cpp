// `cooperage mesh --decompose auto|off` and the decomposition in
// `cooperage plan --json`: the real binary on the paper's Fig. 3a solid,
// which no volume scheme takes whole.
#include "run_command.h"
#include "temp_dir.h"

#include "support/paper_parts.h"
#include "support/real_cad.h"

#include "framework/geometry/occ/workbench.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace cooperage {
namespace {

namespace fs = std::filesystem;
using testing::run_command;

using testing::kCli;

class DecomposeOption : public testing::TempDirTest {
 protected:
  // Blacker 1996, Fig. 3a, as shape "part".
  static void fig3a(occ::Workbench& bench) { testing::build_fig3a(bench); }
  // The same as a STEP file.
  std::string fig3a_step() const {
    occ::Workbench bench;
    fig3a(bench);
    const std::string file = path("fig3a.step");
    bench.write(file);
    return file;
  }
};

TEST_F(DecomposeOption, OffRefusesTheVolumeWithExitTwoAndNoFile) {
  const std::string step = fig3a_step();
  const auto r =
      run_command(kCli + " mesh -q " + step + " --size 0.25 --decompose off -o " + path("out.vtu"));
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("volume 1: no hex scheme applies"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("automatic decomposition"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(path("out.vtu")));
}

TEST_F(DecomposeOption, AutoIsTheDefaultAndSearchesCuts) {
  const std::string step = fig3a_step();
  // A size coarser than the bosses: every cut would leave a piece thinner
  // than one element, and the refusal says so.
  const auto r = run_command(kCli + " mesh -q " + step + " --size 2.5 -o " + path("out.vtu"));
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("automatic decomposition tried 0 cuts"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(path("out.vtu")));
}

// After the cuts the volumes are numbered afresh: a volume whose id moved
// says which input volume it is, in the per-volume lines of a run.
TEST_F(DecomposeOption, VolumesRenumberedByTheCutsNameTheirInputVolume) {
  occ::Workbench bench;
  fig3a(bench);
  bench.brick("plain", {10, 0, 0}, {2, 2, 2});
  const std::string step = path("two.step");
  bench.write(step, {"part", "plain"});
  const auto r = run_command(kCli + " mesh " + step + " --size 0.25 -o " + path("out.vtu"));
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  // The Fig. 3a part (input volume 1) is cut; the plain block, input
  // volume 2, follows its pieces.
  EXPECT_NE(r.out.find("volume 1: meshed"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("volume 2 (input volume 1): meshed"), std::string::npos) << r.out;
  const auto last = r.out.find(" (input volume 2): meshed");
  ASSERT_NE(last, std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("input volume 3"), std::string::npos) << r.out;
}

// gmsh_as1-tu-203: volume 10 of the file is cut in two, and the housing
// (the file's volume 11) is refused as volume 12. Every line naming it
// says which volume of the file it is.
TEST_F(DecomposeOption, ARefusedVolumeRenumberedByTheCutsNamesItsInputVolume) {
  const std::string step = testing::real_cad("gmsh_as1-tu-203.stp");
  if (!fs::exists(step))
    GTEST_SKIP() << step << " is absent (the shared real-CAD folder is not here)";
  const auto r = run_command(kCli + " mesh -q " + step + " --size 6.6 -o " + path("out.vtu"));
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.out.find("volume 11 (input volume 10): meshed"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("volume 12 (input volume 11): refused: "), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("cooperage: error: volume 12 (input volume 11): no applicable scheme"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(path("out.vtu")));
}

// --elements applies to every volume, so the pieces of a cut take it too;
// it used to be given per volume id, which stopped the decomposition
// ("would renumber the entities that <--elements> at command line refers
// to by id").
TEST_F(DecomposeOption, ElementsAreThoseOfThePieces) {
  const std::string step = fig3a_step();
  const auto r =
      run_command(kCli + " mesh " + step + " --size 0.25 --elements wedge -o " + path("out.vtu"));
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const std::string all = r.out + r.err;
  EXPECT_NE(all.find("cut into volumes"), std::string::npos) << all;
  EXPECT_NE(all.find("hexes 0, wedges "), std::string::npos) << all;
  EXPECT_TRUE(fs::exists(path("out.vtu")));
}

// An L-bracket with a hole in each leg: its legs sweep across each other,
// so the cut face is one piece's cap and the other's side. In wedges that
// is a triangle cap on a quad side, which no wedge mesh joins: the refusal
// says that mixed elements mesh it, and they do.
TEST_F(DecomposeOption, WedgePiecesThatCannotJoinPointToMixed) {
  occ::Workbench bench;
  bench.brick("foot", {0, 0, 0}, {8, 4, 1});
  bench.brick("wall", {0, 0, 0}, {1, 4, 8});
  bench.cylinder("down", {5, 2, -1}, {0, 0, 1}, 1, 3);
  bench.cylinder("across", {-1, 2, 5}, {1, 0, 0}, 1, 3);
  bench.fuse("l", {"foot", "wall"});
  bench.cut("part", {"l", "down", "across"});
  const std::string step = path("l_bracket.step");
  bench.write(step);
  const auto wedge =
      run_command(kCli + " mesh -q " + step + " --size 0.5 --elements wedge -o " + path("w.vtu"));
  EXPECT_EQ(wedge.exit_code, 2) << wedge.out << wedge.err;
  EXPECT_NE(wedge.err.find("elements \"mixed\" (--elements mixed)"), std::string::npos)
      << wedge.err;
  EXPECT_FALSE(fs::exists(path("w.vtu")));
  const auto mixed =
      run_command(kCli + " mesh -q " + step + " --size 0.5 --elements mixed -o " + path("m.vtu"));
  EXPECT_EQ(mixed.exit_code, 0) << mixed.out << mixed.err;
}

TEST_F(DecomposeOption, AnUnknownValueIsABadArgument) {
  const auto r = run_command(kCli + " mesh x.step --size 1 --decompose yes -o " + path("o.vtu"));
  EXPECT_EQ(r.exit_code, 2);
}

TEST_F(DecomposeOption, PlanJsonCarriesTheDecomposition) {
  const std::string journal = path("brick.xml");
  std::ofstream(journal) << "<cooperage version=\"1\"><geometry>"
                            "<brick name=\"b\" origin=\"0 0 0\" size=\"2 1 1\"/></geometry>"
                            "<mesh size=\"0.5\"/></cooperage>\n";
  const auto r = run_command(kCli + " plan --json " + journal);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("\"decomposition\":{\"tried\":0,\"volumes\":[]}"), std::string::npos)
      << r.out;
}

}  // namespace
}  // namespace cooperage
