// The check a glued model of pieces passes before it is meshed: the part's
// skin and volume. Two bricks stacked have a skin of 64; left unmerged,
// their touching faces add 2 x 16.
#include "framework/decompose/same_part.h"
#include "framework/geometry/occ/solid_pieces.h"
#include "framework/geometry/occ/workbench.h"

#include <gtest/gtest.h>

namespace cooperage::decompose {
namespace {

void stacked_bricks(occ::Workbench& bench) {
  bench.brick("a", {0, 0, 0}, {4, 4, 1});
  bench.brick("b", {0, 0, 1}, {4, 4, 1});
}

TEST(SamePart, TheSkinLeavesOutFacesBetweenTwoVolumes) {
  occ::Workbench bench;
  stacked_bricks(bench);
  EXPECT_NEAR(skin_area(bench.build_model()), 64.0, 1e-9);
  occ::BuildOptions separate;
  separate.imprint_merge = false;
  EXPECT_NEAR(skin_area(bench.build_model(separate)), 96.0, 1e-9);
}

TEST(SamePart, PiecesOfACutAreThePartAndUnmergedOnesAreNot) {
  occ::Workbench bench;
  stacked_bricks(bench);
  const geom::Model part = bench.build_model();
  const occ::SolidPieces all = occ::SolidPieces::of(bench);
  const occ::SolidPieces cut =
      all.replace(0, all.split(0, {occ::CutSurface::Kind::Plane, {1, 0, 0}, {1, 0, 0}, 0}));
  EXPECT_TRUE(same_skin_and_volume(cut.build_model(true, true), part));
  EXPECT_TRUE(same_skin_and_volume(cut.build_model(true), part));
  // Without imprinting the cut faces and the bricks' faces are not shared.
  EXPECT_FALSE(same_skin_and_volume(cut.build_model(false), part));
  occ::BuildOptions separate;
  separate.imprint_merge = false;
  EXPECT_FALSE(same_skin_and_volume(bench.build_model(separate), part));
}

TEST(SamePart, AnotherVolumeIsAnotherPart) {
  occ::Workbench taller;
  taller.brick("a", {0, 0, 0}, {4, 4, 1});
  taller.brick("b", {0, 0, 1}, {4, 4, 1.000001});
  occ::Workbench bench;
  stacked_bricks(bench);
  EXPECT_FALSE(same_skin_and_volume(taller.build_model(), bench.build_model()));
}

}  // namespace
}  // namespace cooperage::decompose
