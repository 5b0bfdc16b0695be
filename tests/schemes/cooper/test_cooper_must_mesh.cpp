// The machined parts issue 15 lists as "must mesh", built from journal
// primitives: blind holes, a pocket, a stepped shaft with a bore, a flanged
// hub (whole and webcut), the paper's Fig. 1 style part, a boss over a
// larger foot, round-over-square overlaps, a countersunk hole, an inclined
// top with a boss, an elbow with a boss. Each is all-hex, conformal, has no
// inverted element, a minimum scaled Jacobian of at least 0.3, a hex volume
// within 0.5 % of the solid's (the CAD volume: round faces are meshed by
// chords) and the same mesh, moved, after a rigid motion of the part.
#include "support/hex_mesh_check.h"
#include "support/rigid_motion.h"

#include "framework/geometry/occ/workbench.h"
#include "framework/pipeline/mesher.h"
#include "must_mesh_parts.h"
#include "plan_helpers.h"
#include "scheme_helpers.h"
#include "schemes/builtin_schemes.h"
#include "selector/select_schemes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>

namespace cooperage::cooper {
namespace {

using geom::Vec3;
using parts::Build;
using namespace parts;

using testing::builtin;

using testing::sized;

// Meshes `build` (shape "part", or several solids) and checks the mesh;
// returns it for further checks.
pipeline::MeshResult expect_must_mesh(const char* name, const Build& build, double size,
                                      size_t barrels = 0) {
  occ::Workbench wb;
  build(wb);
  const geom::Model model = wb.build_model();
  const auto registry = builtin();
  double solid = 0;
  for (const auto& v : model.volumes()) {
    solid += v.volume;
    const auto plan = plan_test::scheme_plan(*registry, model, v.id);
    EXPECT_TRUE(plan && plan->ok) << name << ": " << (plan ? plan->why : "no cooper");
    if (plan && plan->ok && barrels && model.volumes().size() == 1) {
      EXPECT_EQ(plan->tree.barrels.size(), barrels) << name << "\n" << describe_plan(*plan);
    }
  }
  pipeline::MeshResult r =
      pipeline::mesh_model(model, sized(size), *registry, selector::mesh_options());
  for (const auto& v : model.volumes()) EXPECT_EQ(r.plan.volumes.at(v.id).scheme, "cooper") << name;
  const testing::HexMeshSummary s = testing::check_hex_mesh(model, r.mesh);
  EXPECT_EQ(r.mesh.wedge_count(), 0u) << name;
  EXPECT_GE(s.min_sj, 0.3) << name;
  EXPECT_NEAR(s.volume, solid, 0.005 * solid) << name;
  std::printf(
      "[cooper must mesh] %s: %zu hexes, min scaled Jacobian %.4f, volume %.5f of %.5f (%+.3f "
      "%%)\n",
      name, s.hexes, s.min_sj, s.volume, solid, 100 * (s.volume - solid) / solid);
  ::testing::Test::RecordProperty(std::string(name) + "_min_scaled_jacobian",
                                  std::to_string(s.min_sj));
  return r;
}

// The same part after a rigid motion gives the moved mesh, node for node.
void expect_rotation_invariant(const char* name, const Build& build, double size, unsigned seed) {
  const auto motion = testing::RigidMotion::random(seed);
  occ::Workbench still, moved;
  build(still);
  build(moved);
  motion.apply(moved, "part");
  const geom::Model m0 = still.build_model(), m1 = moved.build_model();
  const auto registry = builtin();
  const auto r0 = pipeline::mesh_model(m0, sized(size), *registry, selector::mesh_options());
  const auto r1 = pipeline::mesh_model(m1, sized(size), *registry, selector::mesh_options());
  ASSERT_EQ(r0.mesh.node_count(), r1.mesh.node_count()) << name;
  for (const auto& v : m0.volumes())
    EXPECT_EQ(r0.mesh.volume(v.id).hexes, r1.mesh.volume(v.id).hexes) << name;
  const double worst = testing::moved_node_distance(r0.mesh, r1.mesh, motion);
  EXPECT_LT(worst, 1e-7) << name;
  std::printf("[cooper must mesh] %s moved (seed %u): worst node distance %.2e\n", name, seed,
              worst);
}

void check(const char* name, const Build& build, double size, unsigned seed, size_t barrels = 0) {
  expect_must_mesh(name, build, size, barrels);
  expect_rotation_invariant(name, build, size, seed);
}

TEST(CooperMustMesh, BlindHole) { check("blind_hole", blind_hole, 0.25, 101, 2); }
TEST(CooperMustMesh, BlindHolesFromBothEnds) {
  check("blind_holes_both_ends", blind_holes_both_ends, 0.25, 102, 3);
}
TEST(CooperMustMesh, CoaxialBlindHolesFromBothEnds) {
  check("blind_holes_coaxial", blind_holes_coaxial, 0.25, 103, 3);
}
// Found on occt_bm2_ec_lever-A (issue 15): without equal counts on the
// two rims, imprinting failed on the near-coincident loops.
TEST(CooperMustMesh, BlindHolesWhoseAxesAreAHairApart) {
  check("blind_holes_offset_axes", blind_holes_offset_axes, 0.25, 115, 3);
}
// From the plan => mesh campaign (issue 15): refused with an inverted hex
// at sizes 0.66 to 0.16 before a cut's faces of one surface were unified.
TEST(CooperMustMesh, OverlappingBlindHolesOfTwoDepths) {
  for (double size : {0.33, 0.25, 0.164})
    expect_must_mesh("overlapping_blind_holes", overlapping_blind_holes, size, 3);
  expect_rotation_invariant("overlapping_blind_holes", overlapping_blind_holes, 0.25, 117);
}
// Also from the lever: the prongs' virtual cap was one subcap with the
// second prong as a "hole", and imprinting failed.
TEST(CooperMustMesh, ForkOfTwoProngsOverAPlate) {
  check("fork_over_plate", fork_over_plate, 0.25, 116, 2);
}
TEST(CooperMustMesh, RectangularPocket) { check("pocket", pocket, 0.25, 104, 2); }
TEST(CooperMustMesh, SteppedShaftWithABore) { check("stepped_shaft", stepped_shaft, 0.25, 105, 3); }
TEST(CooperMustMesh, FlangedHub) { check("flanged_hub", flanged_hub, 0.25, 106, 2); }
TEST(CooperMustMesh, FlangedHubWebcutAtTheShoulder) {
  check("flanged_hub_webcut", flanged_hub_webcut, 0.25, 107);
}
TEST(CooperMustMesh, Fig1Part) { check("fig1_part", fig1_part, 0.25, 108); }
TEST(CooperMustMesh, BossOverALargerFoot) {
  check("boss_over_larger_foot", boss_over_larger_foot, 0.25, 109, 3);
}
TEST(CooperMustMesh, RoundBossPartlyOverASquareFoot) {
  for (double k : {0.8, 1.0, 1.2}) {
    const std::string name = "round_over_square_" + std::to_string(k).substr(0, 3);
    check(name.c_str(), round_over_square(k), 0.25, 110);
  }
}
TEST(CooperMustMesh, SquareBossPartlyOverARoundFoot) {
  for (double k : {0.8, 1.0, 1.2}) {
    const std::string name = "square_over_round_" + std::to_string(k).substr(0, 3);
    check(name.c_str(), square_over_round(k), 0.25, 111);
  }
}
TEST(CooperMustMesh, CountersunkHole) { check("countersunk_hole", countersunk_hole, 0.25, 112, 1); }
TEST(CooperMustMesh, InclinedTopWithABossAndAFoot) {
  check("inclined_top", inclined_top, 0.25, 113, 3);
}
TEST(CooperMustMesh, ElbowWithABossOnItsEndFace) {
  check("elbow_with_boss", elbow_with_boss, 0.25, 114, 2);
}

// A sweep that fails the way it was planned, at every size the run tries,
// is swept the other way at the size asked for (pipeline/finer_retry.h);
// without retries the planned way's error stands.
TEST(CooperMustMesh, ASweepFailingTheWayItWasPlannedIsSweptTheOtherWay) {
  occ::Workbench wb;
  bosses_over_a_through_hole(wb);
  const geom::Model model = wb.build_model();
  const auto registry = builtin();
  const auto plan = plan_test::scheme_plan(*registry, model, 1);
  ASSERT_TRUE(plan && plan->ok && plan->down);
  EXPECT_LT(plan->down->z(), -0.99);
  EXPECT_THROW(pipeline::mesh_model(model, sized(5.965), *registry, selector::mesh_options()),
               MeshingError);
  io::MeshSettings retried = sized(5.965);
  retried.finer_retries = 2;
  const pipeline::MeshResult r =
      pipeline::mesh_model(model, retried, *registry, selector::mesh_options());
  ASSERT_FALSE(r.warnings.empty());
  EXPECT_EQ(r.warnings.front().message.rfind(
                "meshed sweeping it the other way, along (0, 0, 1), at the size asked for "
                "(5.965); along (0, 0, -1) it failed at the size asked for and at smaller ones: ",
                0),
            0u)
      << r.warnings.front().message;
  const testing::HexMeshSummary s = testing::check_hex_mesh(model, r.mesh);
  EXPECT_EQ(r.mesh.wedge_count(), 0u);
  EXPECT_GE(s.min_sj, 0.3);  // 0.49 at this coarse size
  const double solid = model.volumes().front().volume;
  EXPECT_NEAR(s.volume, solid, 0.01 * solid);  // round faces meshed by chords
  std::printf(
      "[cooper must mesh] bosses_over_a_through_hole, swept the other way: %zu hexes, min "
      "scaled Jacobian %.4f, volume %.5f of %.5f\n",
      s.hexes, s.min_sj, s.volume, solid);
}

}  // namespace
}  // namespace cooperage::cooper
