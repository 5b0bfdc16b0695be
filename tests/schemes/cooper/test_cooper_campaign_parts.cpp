// Parts from the plan => mesh campaign that planned and then failed at
// their own size (most at every size): imprinting where loops of a barrel's
// two ends come within a sliver of each other (Blacker 1996, sec. 5), the
// new nodes of a virtual cap between the barrel's ends, a side's columns
// round a hole, a projected subcap folded; and parts the plan refused
// (barrel formation, sec. 4). Each meshes all-hex, conformal,
// with no inverted element, the volume within 1 %, and the same mesh after
// a rigid motion.
#include "support/hex_mesh_check.h"
#include "support/rigid_motion.h"

#include "framework/geometry/occ/workbench.h"
#include "framework/pipeline/mesher.h"
#include "schemes/builtin_schemes.h"
#include "selector/select_schemes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace cooperage::cooper {
namespace {

// A block with a through hole that a boss above and a foot below both
// cross (plan => mesh campaign seed 3 case 8, scaled by 0.1). The hole's
// circle is split by the boss's vertices at the top and the foot's at the
// bottom, so its ribs run half an interval round: in the affine chart the
// foot's rim started at a node a whole interval from its partner and
// crossed the boss's loop, and imprinting found no step at sizes 0.82,
// 0.6 and 0.41 (it meshed at 0.3).
void hole_through_boss_and_foot(occ::Workbench& wb) {
  wb.brick("block", {0, 0, 0}, {2.435, 5.467, 3.73});
  wb.cylinder("hole", {0.775, 3.086, -3.73}, {0, 0, 1}, 0.485, 11.19);
  wb.cylinder("foot", {0.911, 2.658, -1.786}, {0, 0, 1}, 0.299, 1.786);
  wb.cylinder("boss", {0.655, 2.279, 3.73}, {0, 0, 1}, 0.557, 2.244);
  wb.fuse("body", {"block", "foot", "boss"});
  wb.cut("part", {"body", "hole"});
}

pipeline::MeshResult mesh_at(const geom::Model& model, double size) {
  scheme::Registry registry;
  register_builtin_schemes(registry);
  io::MeshSettings settings;
  settings.size = size;
  settings.finer_retries = 0;  // this size, not a retry at a finer one
  return pipeline::mesh_model(model, settings, registry, selector::mesh_options());
}

// Meshes `build` at each size with cooper and checks the mesh: conformal,
// nothing inverted (check_hex_mesh), no wedge, no warning but the worst
// element's note (no retry, no fallback), the hex volume within 1 % of the solid's (round faces are
// meshed by chords); then the same part after `motion` gives the moved
// mesh at each size, every node within `tolerance`.
void expect_meshes(const char* name, void (*build)(occ::Workbench&),
                   const std::vector<double>& sizes, const testing::RigidMotion& motion,
                   double tolerance) {
  occ::Workbench wb;
  build(wb);
  const geom::Model model = wb.build_model();
  const double solid = model.volume(1).volume;
  for (const double size : sizes) {
    const pipeline::MeshResult r = mesh_at(model, size);
    EXPECT_EQ(r.plan.volumes.at(1).scheme, "cooper") << name;
    // The note on a worst element below 0.2 (pipeline/worst_element.h)
    // is no retry or fallback; any other warning is.
    for (const auto& w : r.warnings) {
      EXPECT_EQ(w.message.rfind("its worst hex has a scaled Jacobian of", 0), 0u)
          << name << ": " << w.message;
    }
    const testing::HexMeshSummary s = testing::check_hex_mesh(model, r.mesh);
    EXPECT_EQ(r.mesh.wedge_count(), 0u) << name;
    EXPECT_NEAR(s.volume, solid, 0.01 * solid) << name << " at " << size;
    std::printf(
        "[campaign part] %s, size %.4g: %zu hexes, min scaled Jacobian %.3f, volume %+.3f %%\n",
        name, size, s.hexes, s.min_sj, 100 * (s.volume - solid) / solid);
  }
  occ::Workbench moved;
  build(moved);
  motion.apply(moved, "part");
  const geom::Model moved_model = moved.build_model();
  for (const double size : sizes) {
    const pipeline::MeshResult r0 = mesh_at(model, size);
    const pipeline::MeshResult r1 = mesh_at(moved_model, size);
    ASSERT_EQ(r0.mesh.node_count(), r1.mesh.node_count()) << name << " at " << size;
    EXPECT_LT(testing::moved_node_distance(r0.mesh, r1.mesh, motion), tolerance)
        << name << " at " << size;
  }
}

// The same with the motion of `seed`, nodes within 1e-7.
void expect_meshes(const char* name, void (*build)(occ::Workbench&),
                   const std::vector<double>& sizes, unsigned seed) {
  expect_meshes(name, build, sizes, testing::RigidMotion::random(seed), 1e-7);
}

TEST(CooperImprintSlivers, AHoleWhoseRibsTwistBetweenABossAndAFootIsImprinted) {
  expect_meshes("hole_through_boss_and_foot", hole_through_boss_and_foot, {0.8194, 0.41}, 118);
}

// A foot whose rim runs 0.007 inside a boss's rim (0.04 of the element),
// and a blind hole from the top across the boss's edge (plan => mesh
// campaign seed 6 case 26, scaled by 0.1). The boss's image on the bottom
// was seamed onto two nodes of the foot and cut the bottom's piece through
// the foot; projected without those seams its chords crossed the foot's,
// and the split handed the foot to the wrong piece. Imprinting found no
// step at sizes 0.18, 0.09 and 0.046.
void foot_just_inside_boss(occ::Workbench& wb) {
  wb.brick("block", {0, 0, 0}, {4.201, 3.382, 1.413});
  wb.cylinder("foot", {2.388, 2.227, -0.629}, {0, 0, 1}, 0.257, 0.629);
  wb.cylinder("boss", {2.53, 2.304, 1.413}, {0, 0, 1}, 0.425, 0.371);
  wb.cylinder("blind", {3.029, 2.456, 0.367}, {0, 0, 1}, 0.222, 2.459);
  wb.fuse("body", {"block", "foot", "boss"});
  wb.cut("part", {"body", "blind"});
}

TEST(CooperImprintSlivers, AFootJustInsideABossIsImprintedAsAHole) {
  expect_meshes("foot_just_inside_boss", foot_just_inside_boss, {0.1824, 0.0912}, 119);
}

// A lug with a conical underside on a block's end wall, two pockets cut
// into the top beside it (plan => mesh campaign seed 7 case 66). The virtual
// cap under the first pocket's floor continues the cone's rim, which rises
// to 13.2 on the wall; weighted by distance, the rib ends under the floor's
// corner (z = 11.63) came out above it and the hex between turned inside
// out at every size from 4.1 down to 1.0. A new node of a virtual lower cap
// now keeps at least half the barrel's local depth below its rib's top.
void lug_cone_beside_pockets(occ::Workbench& wb) {
  wb.brick("block", {0, 0, 0}, {47.64, 51.84, 23.97});
  wb.brick("boss", {32.84, 20.95, 23.97}, {10.24, 19.62, 16.5});
  wb.brick("pocket", {27.09, 29.13, 11.63}, {9.42, 13.8, 36.31});
  wb.brick("slot", {23.39, 14.73, 10.31}, {13.38, 6.26, 37.63});
  wb.cylinder("lug", {47.64, 24.6, 13.21}, {0, 0, 1}, 12.4, 10.76);
  wb.cone("under", {47.64, 24.6, 8.45}, {0, 0, 1}, 2.48, 12.4, 4.76);
  wb.fuse("body", {"block", "boss", "lug", "under"});
  wb.cut("part", {"body", "pocket", "slot"});
}

TEST(CooperImprintSlivers, AVirtualCapBesideALugsConeKeepsBelowAPocketFloor) {
  expect_meshes("lug_cone_beside_pockets", lug_cone_beside_pockets, {1.3617, 1.02125}, 120);
}

// A through hole whose wall a slot notches 6 deep from the top, two feet
// below (campaign seed 3 case 121). The notch's arcs, graded towards the
// slot's thin wall, hold 14 of the wall's 22 columns; the bottom circle,
// evenly spaced, leaned those columns 65 degrees round the hole and a hex
// of the barrel beside it inverted at every size. The closed bottom rim
// now follows the notch's nodes (column_spacing.cpp).
void hole_notched_by_slot(occ::Workbench& wb) {
  wb.brick("block", {0, 0, 0}, {25.26, 47.25, 12.59});
  wb.cylinder("foot0", {13.06, 14.42, -6.89}, {0, 0, 1}, 3.15, 6.89);
  wb.cylinder("foot1", {14.29, 18.37, -5.07}, {0, 0, 1}, 3.46, 5.07);
  wb.cylinder("hole", {14.77, 36.35, -12.59}, {0, 0, 1}, 5.83, 37.77);
  wb.brick("slot", {16.24, 25.12, 6.54}, {4.46, 14.44, 18.64});
  wb.fuse("body", {"block", "foot0", "foot1"});
  wb.cut("part", {"body", "hole", "slot"});
}

TEST(CooperSideColumns, ARoundRimFollowsTheGradedArcsOfItsNotchedWall) {
  expect_meshes("hole_notched_by_slot", hole_notched_by_slot, {2.819}, 121);
}

// A lug with a conical underside on a block's end wall, a pocket through
// the top beside it (campaign seed 4 case 180). The top's subcap, projected
// up from its cap stack's seed, folded (worst corner sine -0.998) where
// the lug's rim and the pocket's differ in shape between the ends; guarded
// smoothing cannot open a fold whose every single move first worsens a
// corner, and a hex under it inverted at size 6.632. Untangled against the
// seed's corners (untangle_cap.cpp) the top's worst corner sine is 0.24.
void lug_cone_beside_through_pocket(occ::Workbench& wb) {
  wb.brick("block", {0, 0, 0}, {41.32, 44.64, 32.05});
  wb.cylinder("lug", {41.32, 23.61, 19.19}, {0, 0, 1}, 6.71, 12.86);
  wb.cone("under", {41.32, 23.61, 14.21}, {0, 0, 1}, 2.11, 6.71, 4.98);
  wb.brick("pocket", {28.38, 1.9, 13.17}, {9.96, 12.36, 50.93});
  wb.fuse("body", {"block", "lug", "under"});
  wb.cut("part", {"body", "pocket"});
}

TEST(CooperCapStacks, AFoldedProjectedSubcapIsUntangled) {
  expect_meshes("lug_cone_beside_through_pocket", lug_cone_beside_through_pocket, {6.632, 3.316},
                180);
}

// Folded projected subcaps whose untangling does not settle in its 200
// sweeps (rigid-motion campaign): the part as built and moved by the
// campaign's own motion gave meshes 1.9 apart (seed 4 case 159, a blind
// hole and a pocket under a boss's side; size 10.29) and 3.5 apart (seed 7
// case 149, a lug's cone beside a square boss; 5.892), and seed 7 case 50
// (pockets beside a through hole over a foot; 5.907) inverted a hex as
// built only. The untangling's Newton steps took a corner into account or
// not as rounding put it on either side of the floor a neighbour's step
// had left it on, and were undamped where two corners pulled a node almost
// the same way. Now within 1e-5 of the element (4/159's untangling stops
// at its 200 sweeps before it settles: 3e-6 apart; the others below 6e-7).
void blind_hole_and_pocket_under_boss_side(occ::Workbench& wb) {
  wb.brick("block", {0, 0, 0}, {76.08, 42.07, 25.37});
  wb.cylinder("boss", {46.85, 14.53, 25.37}, {0, 0, 1}, 7.21, 20.48);
  wb.cylinder("blind", {16.85, 26.99, 11.58}, {0, 0, 1}, 2.67, 39.16);
  wb.brick("square", {14.53, 5.96, 25.37}, {29.42, 16.78, 22.94});
  wb.brick("pocket", {43.03, 22.63, 18.86}, {24.84, 4.46, 31.88});
  wb.fuse("body", {"block", "boss", "square"});
  wb.cut("part", {"body", "blind", "pocket"});
}

void lug_cone_beside_square_boss(occ::Workbench& wb) {
  wb.brick("block", {0, 0, 0}, {40.78, 36.55, 33.77});
  wb.brick("boss", {17.19, 27.66, 33.77}, {7.64, 5.32, 30.35});
  wb.cylinder("lug", {40.78, 14.27, 17.28}, {0, 0, 1}, 7.35, 16.49);
  wb.cone("under", {40.78, 14.27, 12.6}, {0, 0, 1}, 1.22, 7.35, 4.68);
  wb.cylinder("foot", {30.75, 25.9, -31.91}, {0, 0, 1}, 7.89, 31.91);
  wb.fuse("part", {"block", "boss", "lug", "under", "foot"});
}

void pockets_beside_through_hole_over_foot(occ::Workbench& wb) {
  wb.brick("block", {0, 0, 0}, {39.39, 20.92, 30.01});
  wb.brick("pocket", {8.37, 5.7, 19.75}, {5.56, 4.06, 40.27});
  wb.cylinder("hole", {12.43, 13.3, -30.01}, {0, 0, 1}, 3.88, 90.03);
  wb.brick("deeper", {7.64, 1.92, 9.83}, {6.14, 6.4, 50.19});
  wb.cylinder("foot", {17.63, 4.76, -29.21}, {0, 0, 1}, 4.44, 29.21);
  wb.fuse("body", {"block", "foot"});
  wb.cut("part", {"body", "pocket", "hole", "deeper"});
}

testing::RigidMotion campaign_motion(const Eigen::Vector3d& axis, double degrees,
                                     const Eigen::Vector3d& shift) {
  testing::RigidMotion m;
  m.axis = axis.normalized();
  m.angle_deg = degrees;
  m.shift = shift;
  return m;
}

TEST(CooperCapStacks, AnUntangledSubcapIsTheSameTurned) {
  expect_meshes(
      "blind_hole_and_pocket_under_boss_side", blind_hole_and_pocket_under_boss_side, {10.29},
      campaign_motion({0.33155, 0.348095, 0.52398}, 161.08453, {-1.479558, 4.167026, 4.925518}),
      1e-5 * 10.29);
  expect_meshes("lug_cone_beside_square_boss", lug_cone_beside_square_boss, {5.892},
                campaign_motion({0.334007, -0.419304, -0.959714}, -173.482058,
                                {-4.778212, -2.073325, 4.162723}),
                1e-5 * 5.892);
  expect_meshes(
      "pockets_beside_through_hole_over_foot", pockets_beside_through_hole_over_foot, {5.907},
      campaign_motion({0.182842, 0.631001, 0.163907}, 125.876291, {3.004649, -3.024658, -3.530092}),
      1e-5 * 5.907);
}

// A pocket from the top, a hole from the bottom into its floor and a
// blind hole beside it, the two holes overlapping (campaign seed 7 case
// 46). The larger hole's wall is one face closed by its seam, its rims cut
// into arcs at four levels by the pocket's floor and wall and the blind
// hole; its top arc is graded towards the pocket's wall 0.04 away. The
// walk round the wall met the seam's vertex a whole turn on and gave up,
// so no rim followed the other's vertices, the columns leaned and a hex
// inverted at every size from 11.3 down to 0.7. The walk now takes the
// seam's turn as the columns' period.
void hole_into_pocket_floor_beside_blind_hole(occ::Workbench& wb) {
  wb.brick("block", {0, 0, 0}, {29.17, 25.58, 28.02});
  wb.brick("pocket", {7.73, 12.81, 15.62}, {10.9, 5.6, 40.42});
  wb.cylinder("blind", {9.26, 18.12, -28.02}, {0, 0, 1}, 1.78, 42.98);
  wb.cylinder("hole", {10.81, 16.86, -28.02}, {0, 0, 1}, 3.04, 47.43);
  wb.cut("part", {"block", "pocket", "blind", "hole"});
}

// At 3.0 two interval assignments cost the same (5 and 7 intervals on the
// hole's arcs 18 and 38, or 7 and 5); CBC's answer moved from one to the
// other when its costs became increments (session 50), and that one fails
// imprinting at the pocket's corner inside the blind hole, with either
// formulation when its counts are given. At 2.5 the sweep inverts a hex
// there. Both open (issue 15); at 3.5 and 1.5 both formulations give
// the same mesh.
TEST(CooperSideColumns, AWallClosedByItsSeamHasPeriodicColumns) {
  expect_meshes("hole_into_pocket_floor_beside_blind_hole",
                hole_into_pocket_floor_beside_blind_hole, {3.5, 1.5}, 46);
}

// A blind hole from below whose floor reaches past a boss's footprint on
// the top and through the block's side wall, a foot and a second blind hole
// beside it (campaign seed 6 case 61). The floor's image crossed the
// footprint, a hole of the top's remainder, and imprinting split the
// remainder as if the footprint were not there: no step applied at any
// size from 12 down to 1.5. It is now split through the footprint
// (imprint_gap_through_hole.cpp); at 3.0 the part meshes. At other sizes
// the floor's image crosses the footprint four times or seams onto its
// corners, which this step leaves alone. Moved by the motion of seed 61,
// a turn of 3 degrees, it meshed with 5,096 hexes against 3,036 while a
// barrel's chart took its u axis from the global x axis (the turn rotated
// the chart within its plane, and imprinting moved a node off an edge
// whose perpendicular from it met the edge's end, or not, by rounding).
void blind_hole_floor_across_boss_footprint(occ::Workbench& wb) {
  wb.brick("block", {0, 0, 0}, {59.07, 28.61, 29.37});
  wb.cylinder("hole", {25.32, 24.08, -29.37}, {0, 0, 1}, 4.75, 49.22);
  wb.brick("boss", {21.99, 21.29, 29.37}, {11.88, 5.92, 27.2});
  wb.cylinder("blind", {38.84, 6.44, -29.37}, {0, 0, 1}, 5.77, 38.82);
  wb.cylinder("foot", {19.94, 23.37, -28.81}, {0, 0, 1}, 2.15, 28.81);
  wb.fuse("body", {"block", "boss", "foot"});
  wb.cut("part", {"body", "hole", "blind"});
}

TEST(CooperImprintSlivers, AFloorsImageThroughAnOpposingFootprintIsImprinted) {
  expect_meshes("blind_hole_floor_across_boss_footprint", blind_hole_floor_across_boss_footprint,
                {3.004}, 61);
}

// A boss on the top with a pocket cut through it, a blind hole from below
// under the pocket's floor and a small blind hole from the middle
// (campaign seed 5 case 110). A split path ran along a hole of a piece and
// left the hole's two halves as two holes of one subcap, sharing the edges
// of the path; the pieces opposite had one hole, so no step applied, at
// every size from 2.5 down to 0.8. Loops sharing an edge are now joined
// (merge_touching_holes). At its own size, 2.499, a layer's hex inverted
// where a cap stack's projected mesh folded; meshed from another piece of
// that stack (mesh_from_a_seed in cap_stacks.cpp) it meshes there too.
void pocket_through_boss_over_blind_hole(occ::Workbench& wb) {
  wb.brick("block", {0, 0, 0}, {47, 27.93, 15.85});
  wb.cylinder("small", {7.27, 10.29, 3.33}, {0, 0, 1}, 1.54, 28.37);
  wb.brick("pocket", {25, 15.05, 8.07}, {9.1, 9.92, 23.63});
  wb.cylinder("boss", {24.84, 11.89, 15.85}, {0, 0, 1}, 6.71, 4.66);
  wb.cylinder("blind", {28.35, 15.64, -15.85}, {0, 0, 1}, 4.54, 19.53);
  wb.fuse("body", {"block", "boss"});
  wb.cut("part", {"body", "small", "pocket", "blind"});
}

TEST(CooperImprintSlivers, HolesSharingASplitPathAreOneHole) {
  expect_meshes("pocket_through_boss_over_blind_hole", pocket_through_boss_over_blind_hole,
                {2.499, 1.2495, 1.0}, 110);
}

// A pocket from the top with a through hole and a wider blind hole from
// below both cutting its corner, a foot below (campaign seed 4 case 155).
// Between the pocket's corner and the two holes' rims imprinting leaves a
// four-node subcap 3.5 long and 0.5 in area with a reflex corner; meshed
// as one quad it was inverted at sizes 6.2 and 4. Pave now meshes such a
// dart as a quad inside joined to its corners. Moved by the motion of
// seed 155 it meshed with nodes up to 3.8 apart while the barrels' charts
// took their u axis from the global x axis.
void pocket_corner_over_two_holes(occ::Workbench& wb) {
  wb.brick("block", {0, 0, 0}, {42.52, 36.23, 40});
  wb.brick("pocket", {6.18, 18.35, 18.43}, {9.54, 9.12, 61.57});
  wb.cylinder("hole", {17.42, 21.01, -40}, {0, 0, 1}, 2.57, 120);
  wb.cylinder("foot", {11.02, 12.5, -15.53}, {0, 0, 1}, 5.01, 15.53);
  wb.cylinder("blind", {19.44, 22.05, -40}, {0, 0, 1}, 4.46, 55.77);
  wb.fuse("body", {"block", "foot"});
  wb.cut("part", {"body", "pocket", "hole", "blind"});
}

TEST(CooperImprintSlivers, AFourNodeDartSubcapIsMeshed) {
  expect_meshes("pocket_corner_over_two_holes", pocket_corner_over_two_holes, {6.213}, 155);
}

// A through hole whose wall a pocket cuts open, beside a slot from the top
// and a blind hole from below (campaign seed 4 case 15). The wall's box
// centre lies near its axis, where every point of the wall is nearly
// nearest: its projection picked a point by rounding, and as built the
// wall faced away from the pocket ("side surface 11 walls the volume in at
// one cap and a hole at another": refused), turned it meshed. The wall is
// now asked at the point nearest its area centroid.
void hole_cut_open_by_pocket(occ::Workbench& wb) {
  wb.brick("block", {0, 0, 0}, {74.99, 22.15, 29.24});
  wb.cylinder("hole", {40.38, 12.18, -29.24}, {0, 0, 1}, 4.4, 87.72);
  wb.brick("slot", {16.38, 11.21, 17.13}, {17.04, 2.52, 41.35});
  wb.brick("pocket", {40.36, 4.78, 10.41}, {11.8, 8.62, 48.07});
  wb.cylinder("blind", {16.19, 8.49, -29.24}, {0, 0, 1}, 3.51, 40.45);
  wb.cut("part", {"block", "hole", "slot", "pocket", "blind"});
}

TEST(CooperImprintSlivers, AHoleWallCutOpenByAPocketFacesTheSameWayTurned) {
  expect_meshes("hole_cut_open_by_pocket", hole_cut_open_by_pocket, {3.266}, 15);
}

// A cut from the top with its floor at 18.82 beside a pocket whose floor
// is at 18.83, a through hole and a small boss (campaign seed 5 case 176).
// Whether the two floors were one level of the sweep came from a tolerance
// of 1e-4 of the part's box diagonal, 0.009 as built: turned, the box grew
// and the 0.01 step became one level, and the walls' nodes moved up to 0.9.
// The length scale is now the span of the part's points, which a motion
// keeps.
void floors_a_hundredth_apart(occ::Workbench& wb) {
  wb.brick("block", {0, 0, 0}, {55.68, 40.1, 29.61});
  wb.cylinder("hole", {36.57, 29.15, -29.61}, {0, 0, 1}, 5.89, 88.83);
  wb.cylinder("cut", {43.31, 26.94, 18.82}, {0, 0, 1}, 9.6, 40.4);
  wb.brick("pocket", {24.58, 16.55, 18.83}, {9.2, 5.12, 40.39});
  wb.cylinder("boss", {33.05, 29.96, 29.61}, {0, 0, 1}, 3.11, 28.54);
  wb.fuse("body", {"block", "boss"});
  wb.cut("part", {"body", "hole", "cut", "pocket"});
}

TEST(CooperImprintSlivers, FloorsAHundredthApartAreLevelsTheSameWayTurned) {
  expect_meshes("floors_a_hundredth_apart", floors_a_hundredth_apart, {4.202}, 176);
}

// A lug with a conical underside on a block's end wall and a blind hole
// from the bottom whose floor (z = 16.13) lies above the cone's top rim
// (z = 7.27; campaign seed 3 case 175). The cone joins the ring of side
// faces between the levels 3.74 and 16.13, so the rings above and below
// the floor's level differ by it, and the plan refused ("cap 11 bounds no
// region between two levels"): the floor was placed only on a region whose
// ring passes its level unchanged. A ring that keeps a face across the
// level continues it now.
void lug_cone_and_blind_hole(occ::Workbench& wb) {
  wb.brick("block", {0, 0, 0}, {20.15, 32.88, 22.41});
  wb.cylinder("lug", {20.15, 14.31, 7.27}, {0, 0, 1}, 7.14, 15.14);
  wb.cone("under", {20.15, 14.31, 3.74}, {0, 0, 1}, 4.28, 7.14, 3.53);
  wb.cylinder("hole", {13.28, 27.77, -22.41}, {0, 0, 1}, 2.66, 38.54);
  wb.fuse("body", {"block", "lug", "under"});
  wb.cut("part", {"body", "hole"});
}

// A blind hole from the top whose floor's rim crosses the rim of a foot
// below at a shallow angle (campaign seed 7 case 39 without its boss). The
// hole's rim, projected down, left the foot's rim by its first segment
// only, 0.05 inside it near their crossing; the probe on that segment put
// the whole arc into the foot's subcap, and imprinting found no step at
// size 2. The arc now cuts the subcap that holds most of its nodes.
void blind_hole_floor_crossing_foot_rim(occ::Workbench& wb) {
  wb.brick("block", {0, 0, 0}, {49.83, 30.79, 29.31});
  wb.cylinder("blind", {28.63, 9.79, 9.02}, {0, 0, 1}, 4.28, 49.6);
  wb.cylinder("foot", {28.94, 11.43, -19.22}, {0, 0, 1}, 3.57, 19.22);
  wb.fuse("body", {"block", "foot"});
  wb.cut("part", {"body", "blind"});
}

TEST(CooperImprintSlivers, AnArcShallowlyCrossingARimCutsTheSubcapHoldingMostOfIt) {
  expect_meshes("blind_hole_floor_crossing_foot_rim", blind_hole_floor_crossing_foot_rim, {2.0},
                139);
}

// A square boss on the top from a through hole's rim across the rim of a
// foot below (campaign seed 3 case 41). The boss's footprint, projected
// onto the bottom, runs from the through hole's rim and back, crossing
// the foot's rim twice; the split handed the whole foot to the footprint's
// piece though the foot's rim crossed it, and imprinting found no step.
// The crossings are now combined onto the foot's rim and the footprint
// leaves the bottom's subcap with the foot's part inside it, as for a
// footprint from the outer loop.
void boss_from_hole_rim_across_foot(occ::Workbench& wb) {
  wb.brick("block", {0, 0, 0}, {76.98, 50.25, 20.36});
  wb.cylinder("hole", {54.83, 28.85, -20.36}, {0, 0, 1}, 7.97, 61.08);
  wb.brick("boss", {28.52, 35.89, 20.36}, {28.64, 5.62, 9.97});
  wb.cylinder("foot", {32.2, 39.33, -5.58}, {0, 0, 1}, 7.9, 5.58);
  wb.fuse("body", {"block", "boss", "foot"});
  wb.cut("part", {"body", "hole"});
}

TEST(CooperImprintSlivers, AFootprintFromAHolesRimAcrossAFootIsSplitAroundIt) {
  expect_meshes("boss_from_hole_rim_across_foot", boss_from_hole_rim_across_foot, {2.743}, 141);
}

// Two pockets from the top, a through hole beside them and a foot below
// (campaign seed 5 case 141): planned, and then refused at its own size
// and at every finer size the run retried. The pocket's image starts and
// ends on the hole's rim and crosses the foot's, as above; it meshes at
// sizes 2.898 and 1.449 now (at 0.72 imprinting still finds no step).
void pockets_beside_hole_over_foot(occ::Workbench& wb) {
  wb.brick("block", {0, 0, 0}, {28.37, 33.19, 17.9});
  wb.brick("pocket", {7.74, 20.67, 10.29}, {8.56, 6.22, 25.51});
  wb.cylinder("foot", {19.05, 23.39, -17.19}, {0, 0, 1}, 6.82, 17.19);
  wb.cylinder("hole", {6.63, 16.4, -17.9}, {0, 0, 1}, 3.26, 25.63);
  wb.brick("slot", {9.47, 4.76, 9.49}, {8.2, 13.28, 26.31});
  wb.fuse("body", {"block", "foot"});
  wb.cut("part", {"body", "pocket", "hole", "slot"});
}

TEST(CooperImprintSlivers, PocketsFromAHolesRimOverAFootMeshAtTheirSize) {
  expect_meshes("pockets_beside_hole_over_foot", pockets_beside_hole_over_foot, {2.898, 1.449},
                142);
}

// A pocket from the top over the edge of a round foot, a second foot
// beside it (campaign seed 6 case 109). One cap stack's mesh, made on its
// first piece and projected through the stack, folded on a 13-node piece
// of surface 13 shaped otherwise (worst corner sine -0.50 after
// untangling), next to a corner of its boundary that no node inside could
// open, and hex 143 inverted at size 7.792 (it meshed at half that). The
// stack is now meshed from the piece whose projections fold least.
void pocket_over_foot_edge(occ::Workbench& wb) {
  wb.brick("block", {0, 0, 0}, {45.66, 42.29, 37.7});
  wb.brick("pocket", {23.4, 27.77, 9.48}, {11.7, 10.8, 65.92});
  wb.cylinder("foot", {31.66, 11.31, -20.92}, {0, 0, 1}, 4.62, 20.92);
  wb.cylinder("edge_foot", {37.27, 35.4, -20.26}, {0, 0, 1}, 4.88, 20.26);
  wb.fuse("body", {"block", "foot", "edge_foot"});
  wb.cut("part", {"body", "pocket"});
}

TEST(CooperCapStacks, AStackFoldingFromItsFirstPieceIsMeshedFromAnother) {
  expect_meshes("pocket_over_foot_edge", pocket_over_foot_edge, {7.792}, 143);
}

// A blind hole from the top whose wall a pocket notches at its top and a
// hole from below notches at its bottom, with a foot (campaign seed 10
// case 66). The pocket's corner on the wall lies 3 degrees before the
// lower hole's ceiling's corner, but the interval counts put its column 4
// columns past it: the ribs ran 90 degrees round the wall in one layer,
// the pocket's image cut the ceiling, which pave had meshed already, and
// the run failed at every size. The columns now keep the wall's order
// (column_order.h); at 3.936 (its own size) imprinting still finds no step
// in the barrel above.
void hole_wall_notched_at_both_ends(occ::Workbench& wb) {
  wb.brick("block", {0, 0, 0}, {37.89, 58.64, 22.91});
  wb.cylinder("blind", {15.14, 19.62, 10.18}, {0, 0, 1}, 9.26, 35.64);
  wb.brick("pocket", {13.59, 21.59, 13.46}, {11.02, 15.14, 32.36});
  wb.cylinder("foot", {23.19, 25.33, -5.74}, {0, 0, 1}, 3.49, 5.74);
  wb.cylinder("from_below", {10.66, 22.84, -22.91}, {0, 0, 1}, 6.3, 34.42);
  wb.fuse("body", {"block", "foot"});
  wb.cut("part", {"body", "blind", "pocket", "from_below"});
}

TEST(CooperSideColumns, AWallNotchedAtBothEndsKeepsItsCornersColumnsInOrder) {
  expect_meshes("hole_wall_notched_at_both_ends", hole_wall_notched_at_both_ends, {3.0, 1.968},
                1066);
}

// A boss on the top, a foot below overhanging the block's edge, and a
// blind hole from the top through the boss's rim (campaign seed 11 case
// 93). The boss's rim, from the hole floor's rim down to the bottom,
// leaves the bottom's subcap across the foot's rim and comes back: it was
// subtracted from the bottom alone, its piece crossed the foot's rim and
// meshing the bottom failed at every size ("loop edges intersect"). The
// crossings are now combined onto nodes of both rims (imprint_gap_crossing.cpp).
void boss_rim_across_a_foot(occ::Workbench& wb) {
  wb.brick("block", {0, 0, 0}, {42.24, 49.86, 31.8});
  wb.cylinder("foot", {8.71, 38.12, -14.91}, {0, 0, 1}, 9.68, 14.91);
  wb.cylinder("hole", {18.93, 23.21, 14.82}, {0, 0, 1}, 2.59, 48.78);
  wb.cylinder("boss", {13.26, 28.18, 31.8}, {0, 0, 1}, 6.71, 12.39);
  wb.fuse("body", {"block", "foot", "boss"});
  wb.cut("part", {"body", "hole"});
}

TEST(CooperImprintSlivers, ARimLeavingTheSubcapItStartsInAndComingBackIsIntersected) {
  expect_meshes("boss_rim_across_a_foot", boss_rim_across_a_foot, {11.642, 5.821, 2.91}, 1193);
}

// A square boss cut by a blind hole from the top whose floor's rim crosses
// a foot's (campaign seed 7 case 39). At size 4.3065 imprinting splits a
// subcap again and again; it gave up after 10,000 steps, 7.7 s. It now
// gives up after 100 steps more than its ends have nodes (imprints take
// at most 15 steps in the campaign, 53 on 1,212 nodes in real CAD).
void boss_over_blind_hole_over_foot(occ::Workbench& wb) {
  wb.brick("block", {0, 0, 0}, {49.83, 30.79, 29.31});
  wb.brick("boss", {25.63, 10.57, 29.31}, {11.36, 3.6, 7.38});
  wb.cylinder("blind", {28.63, 9.79, 9.02}, {0, 0, 1}, 4.28, 49.6);
  wb.cylinder("foot", {28.94, 11.43, -19.22}, {0, 0, 1}, 3.57, 19.22);
  wb.fuse("body", {"block", "boss", "foot"});
  wb.cut("part", {"body", "blind"});
}

TEST(CooperImprintSlivers, ImprintingGoingRoundInCirclesGivesUpWithinItsNodesSteps) {
  occ::Workbench wb;
  boss_over_blind_hole_over_foot(wb);
  const geom::Model model = wb.build_model();
  try {
    mesh_at(model, 4.3065);
    ADD_FAILURE() << "expected imprinting to give up";
  } catch (const MeshingError& e) {
    const std::string text = e.what();
    const std::string lead = "imprinting did not finish within ";
    const size_t at = text.find(lead);
    ASSERT_NE(at, std::string::npos) << text;
    const int steps = std::stoi(text.substr(at + lead.size()));
    EXPECT_GT(steps, 100);
    EXPECT_LT(steps, 1000) << text;
  }
}

// A foot below, a boss and a square boss on the top, a pocket cut into
// the square boss (campaign seed 7 case 116). A crossing of a subcap's
// own loop was combined onto two nodes whose ribs end on two different
// given nodes of the other end; the kept node took the dropped one's
// partner and the partner of its own kept a rib back to it, so two nodes
// of one end were ribbed to one node of the other, and imprinting found
// no step at size 3.115. The kept node now keeps its own rib and the
// dropped node's partner loses its rib. (Tried first without the bound on
// imprinting steps, this sent campaign part 4/126 round in circles for
// 10,000 steps; with the bound it gives up in under a second.)
void pocket_in_square_boss_beside_boss(occ::Workbench& wb) {
  wb.brick("block", {0, 0, 0}, {61.52, 37.34, 22.3});
  wb.cylinder("foot", {9.35, 27.22, -4.58}, {0, 0, 1}, 6.05, 4.58);
  wb.cylinder("boss", {37.69, 6.18, 22.3}, {0, 0, 1}, 8.1, 19.68);
  wb.brick("pocket", {43.6, 11.83, 12.72}, {6.56, 8.26, 31.88});
  wb.brick("square", {38.41, 8.97, 22.3}, {9.28, 7.38, 5.49});
  wb.fuse("body", {"block", "foot", "boss", "square"});
  wb.cut("part", {"body", "pocket"});
}

TEST(CooperImprintSlivers, ACrossingCombinedOntoTwoGivenNodesKeepsOneRibEach) {
  expect_meshes("pocket_in_square_boss_beside_boss", pocket_in_square_boss_beside_boss, {3.115},
                144);
}

TEST(CooperBarrelFormation, AHoleFloorAboveALugsConeEndsItsBarrel) {
  expect_meshes("lug_cone_and_blind_hole", lug_cone_and_blind_hole, {3.954, 1.977}, 175);
}

// A blind hole from the bottom (floor at 12.4) that opens into a notch cut
// from the top into the front wall (floor at 9.51), with a through hole
// and a boss (campaign seed 3 case 128). Between the two floors no cap
// bounds the volume: the notch's floor faces up, the hole's down. There the
// hole's wall walls the volume in (the hole and the notch are one opening
// to the outside) and below the notch's floor a hole, and its facing is
// mixed, so the plan refused ("side surface 1 walls the volume in at one
// cap and a hole at another"). The faces of that ring that wall one side
// at every cap (the block's and the notch's walls, all outer) decide now.
void blind_hole_into_notch(occ::Workbench& wb) {
  wb.brick("block", {0, 0, 0}, {60.93, 55.13, 18.38});
  wb.cylinder("blind", {10.12, 21.76, -18.38}, {0, 0, 1}, 9.52, 30.78);
  wb.cylinder("notch", {19.84, 8.36, 9.51}, {0, 0, 1}, 11.44, 27.25);
  wb.cylinder("hole", {31.86, 41.46, -18.38}, {0, 0, 1}, 5.91, 55.14);
  wb.brick("boss", {12.68, 36.9, 18.38}, {18.62, 5.82, 4.09});
  wb.fuse("body", {"block", "boss"});
  wb.cut("part", {"body", "blind", "notch", "hole"});
}

TEST(CooperBarrelFormation, ABlindHoleOpeningIntoANotchWallsTheVolumeIn) {
  expect_meshes("blind_hole_into_notch", blind_hole_into_notch, {4.79, 3.5}, 128);
}

// A box boss on the top overhanging the block's left edge by 0.73 and a
// blind hole from the top (floor at 11.69) that cuts into the boss's corner
// (campaign seed 3 case 162). The boss's footprint crosses the edge, so it
// notches the top's outer loop, and the hole's rim joins that notch: the
// hole's wall meets the top on its outer loop only, which made it an outer
// wall, and the plan refused ("two outer cycles of side faces (1, ...)
// bound one region"). A ring whose walls all face its middle is a hole
// when only such contacts say otherwise.
void hole_rim_in_an_outer_loop(occ::Workbench& wb) {
  wb.brick("block", {0, 0, 0}, {35.15, 44.6, 18.44});
  wb.cylinder("blind", {14.46, 22.93, 11.69}, {0, 0, 1}, 6.17, 25.19);
  wb.brick("boss", {-0.73, 27.52, 18.44}, {13.88, 14.7, 15.31});
  wb.fuse("body", {"block", "boss"});
  wb.cut("part", {"body", "blind"});
}

TEST(CooperBarrelFormation, AHoleWhoseRimJoinsTheTopsOuterLoopIsAHole) {
  expect_meshes("hole_rim_in_an_outer_loop", hole_rim_in_an_outer_loop, {3.901}, 162);
}

// A blind hole from the bottom (up to 19.19) that cuts into the edge of a
// foot below the block, with a blind hole from the top and a lug (campaign
// seed 7 case 40). The hole's rim at the foot's bottom joins the foot's
// outline, so its wall met caps on outer loops only and counted as an
// outer wall; in the block, between the block's bottom and the hole's
// ceiling, no cap bounds it and its own role stood: "cap 16 bounds no
// region between two levels". A ring of such walls that all face its
// middle is a hole there too (the one-face ring's middle is its area
// centroid, on the hole's axis). The foot overhangs the back wall by 0.1:
// the minimum scaled Jacobian is 0.053 at every size.
void hole_cutting_a_foots_edge(occ::Workbench& wb) {
  wb.brick("block", {0, 0, 0}, {73.36, 47.42, 27.19});
  wb.cylinder("blind", {34.51, 24.89, -27.19}, {0, 0, 1}, 9.11, 46.38);
  wb.cylinder("top", {48.65, 14.75, 17.7}, {0, 0, 1}, 5.45, 36.68);
  wb.cylinder("lug", {73.36, 33.88, 13.07}, {0, 0, 1}, 5.23, 14.12);
  wb.cylinder("foot", {34.23, 39.37, -26.39}, {0, 0, 1}, 8.15, 26.39);
  wb.fuse("body", {"block", "lug", "foot"});
  wb.cut("part", {"body", "blind", "top"});
}

TEST(CooperBarrelFormation, AHoleCuttingAFootsEdgeIsAHoleInTheBlock) {
  expect_meshes("hole_cutting_a_foots_edge", hole_cutting_a_foots_edge, {4.959, 3.0}, 40);
}

// Two box pockets from the top that overlap in an L, floors at 3.34 and
// 10.33, the deeper one through a box boss on the top, a round foot below
// (campaign seed 5 case 73). Between the floors the ring round the L is
// one hole, but the caps' contacts give its walls different roles and
// its walls do not all face the middle of its rims (an L's middle need
// not lie inside it):
// the plan refused ("the sides 9 and 24 form one cycle but wall the volume
// on different sides"). The sign of the ring's section area decides: its
// walls run clockwise round the sweep axis, a hole's.
void pockets_overlapping_in_an_l(occ::Workbench& wb) {
  wb.brick("block", {0, 0, 0}, {54.89, 42.58, 15.35});
  wb.brick("deep", {36.64, 13.75, 3.34}, {9.44, 14.16, 27.36});
  wb.brick("boss", {34.44, 20.24, 15.35}, {15.82, 16.64, 7.83});
  wb.cylinder("foot", {20.4, 32.95, -6.23}, {0, 0, 1}, 10.2, 6.23);
  wb.brick("shallow", {29.33, 4.97, 10.33}, {18.2, 10.92, 20.37});
  wb.fuse("body", {"block", "boss", "foot"});
  wb.cut("part", {"body", "deep", "shallow"});
}

TEST(CooperBarrelFormation, PocketsOverlappingInAnLAreOneHoleByTheSignOfItsSection) {
  expect_meshes("pockets_overlapping_in_an_l", pockets_overlapping_in_an_l, {2.661, 2.0}, 73);
}

// The same family under a boss (campaign seed 7 case 134): two box pockets
// overlapping in an L from the top of a box boss, floors at 7.67 and
// 15.71, a round foot below. It plans by the section's sign and meshes at
// half its size (at its own size a subcap's boundary is odd: 67 nodes).
void pockets_overlapping_under_a_boss(occ::Workbench& wb) {
  wb.brick("block", {0, 0, 0}, {42.81, 42.76, 31.11});
  wb.brick("deep", {27.87, 14.7, 7.67}, {9.16, 6.36, 54.55});
  wb.cylinder("foot", {27.07, 25.81, -13.92}, {0, 0, 1}, 10.01, 13.92);
  wb.brick("shallow", {23.87, 17.58, 15.71}, {6.66, 15.84, 46.51});
  wb.brick("boss", {16.67, 8.83, 31.11}, {17.02, 13.06, 22.12});
  wb.fuse("body", {"block", "foot", "boss"});
  wb.cut("part", {"body", "deep", "shallow"});
}

TEST(CooperBarrelFormation, PocketsOverlappingUnderABossAreOneHole) {
  expect_meshes("pockets_overlapping_under_a_boss", pockets_overlapping_under_a_boss, {1.949}, 134);
}

// Two box pockets and two round ones from the top, overlapping (campaign
// seed 5 case 122): two of the pockets' walls meet at 9.4 degrees along
// the sweep. The plan refused sides meeting within 10 degrees of folding
// flat (imprinting cannot resolve the slivers of a cusp); it refuses
// within 8 now, and this part meshes (minimum scaled Jacobian 0.18 at its
// own size, 0.28 at 8).
void pockets_meeting_at_nine_degrees(occ::Workbench& wb) {
  wb.brick("block", {0, 0, 0}, {54.46, 50.03, 37.79});
  wb.brick("box1", {19.01, 1.89, 21.86}, {12.9, 19.58, 53.72});
  wb.brick("box2", {5.16, 11.27, 14.99}, {18.44, 16.82, 60.59});
  wb.cylinder("round1", {12.81, 36.11, 18.56}, {0, 0, 1}, 8.13, 57.02);
  wb.cylinder("round2", {15.98, 39.13, 25.2}, {0, 0, 1}, 3.52, 50.38);
  wb.cut("part", {"block", "box1", "box2", "round1", "round2"});
}

TEST(CooperBarrelFormation, PocketWallsMeetingAtNineDegreesMesh) {
  expect_meshes("pockets_meeting_at_nine_degrees", pockets_meeting_at_nine_degrees, {13.713, 8.0},
                122);
}

// A blind hole from the bottom whose floor lies under the corners of two
// bosses on the top and overlaps a blind hole from the top (plan => mesh
// campaign seed 19 case 9). The floor's rim, seen from the top, runs from
// one boss's footprint to the other's, to the hole from the top and back:
// three gaps, each joining two holes of the top's remainder and splitting
// nothing alone. Imprinting found no step at every size from 1.19 to 6;
// the gaps are now projected together and the piece they enclose leaves
// the top's remainder.
void floor_between_two_bosses_and_a_hole(occ::Workbench& wb) {
  wb.brick("block", {0, 0, 0}, {25.86, 22.53, 35.55});
  wb.cylinder("from_bottom", {11.54, 11.41, -35.55}, {0, 0, 1}, 4.85, 59.08);
  wb.brick("boss1", {12.73, 2.87, 35.55}, {7.7, 7.38, 7.83});
  wb.brick("boss2", {15.74, 11.08, 35.55}, {9.4, 2.86, 14.87});
  wb.cylinder("from_top", {7.84, 15.33, 7.5}, {0, 0, 1}, 3.4, 63.6);
  wb.fuse("body", {"block", "boss1", "boss2"});
  wb.cut("part", {"body", "from_bottom", "from_top"});
}

TEST(CooperImprintSlivers, AFloorsRimFromHoleToHoleToHoleSplitsTheTopOnce) {
  expect_meshes("floor_between_two_bosses_and_a_hole", floor_between_two_bosses_and_a_hole,
                {4.762, 2.381}, 177);
}

// Blind holes from both ends 1.84 off one axis, both cut by a through hole
// (plan => mesh campaign seed 27 case 81). The top floor's rim, projected
// onto the bottom, runs from the through hole's rim into the part's
// remainder, across the bottom floor's rim and out again back to the
// through hole: it leaves the remainder through the very hole (the through
// hole and the bottom floor together) it starts and ends on. Split along
// the whole path, the piece overlapped the bottom floor, and imprinting
// found no step at every size from 0.96 to 3.85.
void blind_holes_off_axis_across_a_through_hole(occ::Workbench& wb) {
  wb.brick("block", {0, 0, 0}, {29.48, 40.04, 16.47});
  wb.cylinder("from_top", {20.73, 11.59, 9.09}, {0, 0, 1}, 5.89, 23.85);
  wb.cylinder("from_bottom", {20.81, 9.75, -16.47}, {0, 0, 1}, 5.75, 21.64);
  wb.cylinder("through", {22.14, 19.57, -16.47}, {0, 0, 1}, 6.1, 49.41);
  wb.cut("part", {"block", "from_top", "from_bottom", "through"});
}

TEST(CooperImprintSlivers, AFloorsRimLeavingThroughTheHoleItEndsOnIsSplitAroundIt) {
  expect_meshes("blind_holes_off_axis_across_a_through_hole",
                blind_holes_off_axis_across_a_through_hole, {3.845, 0.9613}, 178);
}

// A boss and a square boss over a foot, a through hole beside them (plan =>
// mesh campaign seed 30 case 83). At half its size (1.788) a crossing of
// two subcaps' loops walked to a node on a hole, not on the outer loop it
// split, and the split's walk round that loop never met it: 16.8 GB and a
// minute later the run ran out of memory. Imprinting now stops there and
// says so.
TEST(CooperImprintSlivers, ACrossingThatCannotSplitStopsImprinting) {
  occ::Workbench wb;
  wb.brick("block", {0, 0, 0}, {56.2, 42.63, 13.99});
  wb.cylinder("boss", {35.15, 25.9, 13.99}, {0, 0, 1}, 6.75, 11.13);
  wb.cylinder("foot", {30.09, 23.99, -4.43}, {0, 0, 1}, 8.18, 4.43);
  wb.cylinder("hole", {22.31, 21.15, -13.99}, {0, 0, 1}, 3.42, 41.97);
  wb.brick("square", {28.3, 23.48, 13.99}, {16.7, 6.48, 6.39});
  wb.fuse("body", {"block", "boss", "foot", "square"});
  wb.cut("part", {"body", "hole"});
  try {
    mesh_at(wb.build_model(), 1.788);
    SUCCEED() << "it meshed";
  } catch (const MeshingError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("subcap imprinting failed"), std::string::npos) << what;
    EXPECT_EQ(what.find("memory"), std::string::npos) << what;
  }
}

// A foot under a block's edge (it overhangs the side by 1.1) whose rim runs
// from the side under a round boss's footprint, on under a square boss's
// corner and back to the side (campaign seed 37 case 26). On the top's
// remainder the rim's image joins the outer loop to the two footprints'
// holes and back; no single gap splits it, and imprinting found no step at
// any size tried (4.76 down to 1). All the gaps are now projected together.
void foot_from_the_side_under_two_bosses(occ::Workbench& wb) {
  wb.brick("block", {0, 0, 0}, {40.38, 36.78, 17.25});
  wb.cylinder("f0", {31.77, 14.65, 17.25}, {0, 0, 1}, 4.34, 5.41);
  wb.brick("f1", {19.32, 4.13, 17.25}, {7.1, 5.02, 4.51});
  wb.cylinder("f2", {33.76, 7.96, -12.58}, {0, 0, 1}, 7.72, 12.58);
  wb.brick("f3", {7.46, 2.36, 17.25}, {7.24, 9.96, 12.49});
  wb.fuse("part", {"block", "f0", "f1", "f2", "f3"});
}

TEST(CooperImprintSlivers, AFootsRimFromTheSideThroughTwoFootprintsIsImprinted) {
  expect_meshes("foot_from_the_side_under_two_bosses", foot_from_the_side_under_two_bosses,
                {4.759, 2.38}, 179);
}

// A pocket whose corner pokes out of a blind hole from below, under a
// square boss (campaign seed 8 case 168): imprinting stops at every size
// tried (2.29 down to 0.3), the pocket's corner beside the hole's rim. The
// refusal says where, so a person can look: near the hole's rim. When
// imprinting learns this part, mesh it above and take another that stops.
void pocket_corner_out_of_a_hole(occ::Workbench& wb) {
  wb.brick("block", {0, 0, 0}, {27.26, 25.49, 12.92});
  wb.cylinder("hole", {19.19, 12.19, -12.92}, {0, 0, 1}, 6.31, 18.18);
  wb.brick("pocket", {13.78, 7.15, 9.03}, {5.42, 5.6, 16.81});
  wb.brick("boss", {13.73, 1.16, 12.92}, {9.52, 7.76, 7.55});
  wb.cylinder("pin", {10.29, 14.03, -12.92}, {0, 0, 1}, 1.51, 21.55);
  wb.fuse("body", {"block", "boss"});
  wb.cut("part", {"body", "hole", "pocket", "pin"});
}

TEST(CooperImprintSlivers, AnImprintThatStopsSaysWhere) {
  occ::Workbench wb;
  pocket_corner_out_of_a_hole(wb);
  const double size = 2.292;
  try {
    mesh_at(wb.build_model(), size);
    FAIL() << "it meshed: move it to expect_meshes() and take a part that stops";
  } catch (const MeshingError& e) {
    const std::string what = e.what();
    ASSERT_NE(what.find("subcap imprinting failed"), std::string::npos) << what;
    EXPECT_EQ(what.find("upper 7"), std::string::npos) << "internal ids: " << what;
    double x = 0, y = 0, z = 0;
    const size_t at = what.find("; near (");
    ASSERT_NE(at, std::string::npos) << what;
    ASSERT_EQ(std::sscanf(what.c_str() + at, "; near (%lf, %lf, %lf)", &x, &y, &z), 3) << what;
    // Inside the part's box, within an element of the hole's rim.
    EXPECT_TRUE(x >= 0 && x <= 27.26 && y >= 0 && y <= 25.49 && z >= 0 && z <= 20.47) << what;
    EXPECT_LT(std::abs(std::hypot(x - 19.19, y - 12.19) - 6.31), size) << what;
  }
}

}  // namespace
}  // namespace cooperage::cooper
