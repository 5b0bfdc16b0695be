// A self-intersecting subcap from a CAD model (Blacker 1996, sec. 5.5,
// Fig. 18), meshed end to end. A 4 x 4 x 2 block with a boss [1,3] x [0,3]
// on top flush with the front wall (y = 0) and a foot [0,4] x [2,4] below
// flush with the left, right and back walls (volume 32 + 6 + 8 = 46). The
// block's barrel has a flush virtual subcap on both ends; projected, the
// boss's (ribbed to the front wall) pokes past the bottom's edge y = 2 into
// the foot's, so subtracting it from the bottom leaves a loop that crosses
// itself twice: n + 1 = 3 caps, the middle one an overlap subtracted from
// the boss piece and the foot (the hand-made test
// SelfIntersectingSubcapSplitsIntoNPlusOneLoops, from a model).
#include "support/hex_mesh_check.h"
#include "support/rigid_motion.h"

#include "framework/geometry/occ/workbench.h"
#include "framework/pipeline/mesher.h"
#include "plan_helpers.h"
#include "scheme_helpers.h"
#include "schemes/cooper/cooper_scheme.h"
#include "schemes/cooper/sweep_volume.h"
#include "schemes/map/surface_map.h"
#include "schemes/map/volume_map.h"
#include "schemes/pave/pave_2d.h"
#include "schemes/pave/pave_scheme.h"
#include "schemes/submap/submap_scheme.h"
#include "selector/select_schemes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <optional>

namespace cooperage::cooper {
namespace {

using testing::Pave2D;

std::unique_ptr<scheme::Registry> registry() {
  auto r = std::make_unique<scheme::Registry>();
  r->add(map::make_surface_map());
  r->add(submap::make_submap());
  r->add(map::make_volume_map());
  CooperOptions options;
  options.polygon_mesher = std::make_shared<Pave2D>();
  r->add(make_cooper(*r, options));
  return r;
}

void flush_boss_and_foot(occ::Workbench& wb) {
  wb.brick("b", {0, 0, 0}, {4, 4, 2});
  wb.brick("boss", {1, 0, 2}, {2, 3, 1});
  wb.brick("foot", {0, 2, -1}, {4, 2, 1});
  wb.fuse("part", {"b", "boss", "foot"});
}

const geom::Vec3 kUp(0, 0, 1);

// The job: a size, and a sweep direction hint on volume 1 when given.
io::MeshSettings job_along(double size, std::optional<geom::Vec3> direction = std::nullopt) {
  io::MeshSettings s;
  s.size = size;
  if (direction) {
    io::VolumeSetting v;
    v.id = 1;
    v.direction = direction;
    s.volumes.push_back(v);
  }
  return s;
}

// Along z: the boss's and the foot's barrels are open stepped segments (down
// and up) with flush virtual caps, meshed from the middle because their
// footprints cross; the block's barrel has subcaps on both ends.
TEST(CooperSelfIntersecting, FlushSubcapsOnBothEndsClassifyAlongTheAxis) {
  occ::Workbench wb;
  flush_boss_and_foot(wb);
  const geom::Model model = wb.build_model();
  ASSERT_NEAR(model.volume(1).volume, 46.0, 1e-6);
  const auto reg = registry();
  SweepHints along_z;
  along_z.direction = kUp;
  const VolumePlan m = plan_test::plan_with(model, 1, *reg, along_z);
  ASSERT_TRUE(m.ok) << m.why;
  ASSERT_TRUE(m.down.has_value());
  EXPECT_NEAR(m.down->z(), 1.0, 1e-9);  // the hint, sign included
  ASSERT_EQ(m.tree.barrels.size(), 3u);
  // The block's barrel has a virtual cap on both ends, each beside a real cap.
  const BarrelNode& middle = m.tree.barrels[1];
  EXPECT_EQ(plan_test::end_barrels(m, middle.upper, true).size(), 1u);
  EXPECT_EQ(plan_test::end_barrels(m, middle.lower, false).size(), 1u);
  EXPECT_EQ(imprint_operation(middle), "imprint");
  // Without a hint another axis works too.
  EXPECT_TRUE(plan_test::plan_with(model, 1, *reg).ok);
}

TEST(CooperSelfIntersecting, MeshesEndToEndThroughTheSelfIntersection) {
  occ::Workbench wb;
  flush_boss_and_foot(wb);
  const geom::Model model = wb.build_model();
  const auto reg = registry();
  const io::MeshSettings up = job_along(0.25, kUp);
  const auto r = pipeline::mesh_model(model, up, *reg, selector::mesh_options());
  EXPECT_EQ(r.plan.volumes.at(1).scheme, "cooper");
  const auto s = testing::check_hex_mesh(model, r.mesh);  // conformity, no inverted hex
  EXPECT_NEAR(s.volume, 46.0, 46.0 * 1e-6);
  EXPECT_GE(s.min_sj, 0.3);
  ::testing::Test::RecordProperty("hexes", std::to_string(s.hexes));
  ::testing::Test::RecordProperty("min_scaled_jacobian", std::to_string(s.min_sj));
  std::printf("[cooper 5.5] flush boss and foot: %zu hexes, min scaled Jacobian %.4f\n", s.hexes,
              s.min_sj);
  // The sec. 5.5 step ran: the barrel reports of the same sweep, replayed on
  // the meshed sides (cooper's own caps are meshed again, not read).
  const auto m = plan_test::scheme_plan(*reg, model, 1, &up);
  ASSERT_TRUE(m && m->ok);
  const Pave2D mesher;
  std::vector<BarrelReport> reports;
  const scheme::EntityMesh replay =
      sweep_volume(scheme::VolumeView{model, 1, &r.mesh}, *m, &mesher, &reports);
  EXPECT_EQ(replay.hexes.size(), s.hexes);
  size_t self_intersections = 0;
  for (const BarrelReport& b : reports) {
    self_intersections += static_cast<size_t>(
        std::count(b.imprint_steps.begin(), b.imprint_steps.end(), ImprintStep::SelfIntersect));
  }
  EXPECT_GE(self_intersections, 1u);
}

// Orientation insensitivity: a seeded rigid motion of the model (and of the
// direction hint) gives the moved mesh, node for node.
TEST(CooperSelfIntersecting, RigidMotionGivesTheMovedMesh) {
  const auto motion = testing::RigidMotion::random(15);
  occ::Workbench still, moved;
  flush_boss_and_foot(still);
  flush_boss_and_foot(moved);
  motion.apply(moved, "part");
  const geom::Model m0 = still.build_model(), m1 = moved.build_model();
  const geom::Vec3 up = motion.apply(kUp) - motion.apply(geom::Vec3::Zero());
  const auto reg = registry();
  const auto r0 = pipeline::mesh_model(m0, job_along(0.25, kUp), *reg, selector::mesh_options());
  const auto r1 = pipeline::mesh_model(m1, job_along(0.25, up), *reg, selector::mesh_options());
  ASSERT_EQ(r0.mesh.node_count(), r1.mesh.node_count());
  EXPECT_EQ(r0.mesh.volume(1).hexes, r1.mesh.volume(1).hexes);
  const double worst = testing::moved_node_distance(r0.mesh, r1.mesh, motion);
  EXPECT_LT(worst, 1e-7);
  std::printf("[cooper 5.5] moved (seed 15): %zu hexes, worst node distance %.2e\n",
              r0.mesh.volume(1).hexes.size(), worst);
}

}  // namespace
}  // namespace cooperage::cooper
