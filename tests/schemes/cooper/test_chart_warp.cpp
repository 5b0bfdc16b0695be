// A barrel's lower end warped onto its upper end's chart along the ribs
// (schemes/cooper/chart_warp.h): ribbed nodes land on their partners, the
// rest follow the nearest ribs, and the inverse takes a point of the upper
// chart back to where it lies on the lower end.
#include "schemes/cooper/chart_warp.h"

#include "support/hex_mesh_check.h"
#include "support/rigid_motion.h"

#include "framework/geometry/occ/workbench.h"
#include "framework/pipeline/mesher.h"
#include "plan_helpers.h"
#include "schemes/builtin_schemes.h"
#include "selector/select_schemes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

namespace cooperage::cooper {
namespace {

using Vec2 = ChartWarp::Vec2;

// Ribs round a circle of radius 2 whose lower nodes sit `shift` radians
// round from their partners (a hole whose two rims are split at different
// vertices), and a square of radius 5 whose ribs agree.
std::vector<std::pair<Vec2, Vec2>> twisted_hole_ribs(double shift) {
  std::vector<std::pair<Vec2, Vec2>> ribs;
  const int n = 12;
  for (int k = 0; k < n; ++k) {
    const double a = 2 * M_PI * k / n;
    ribs.push_back(
        {{2 * std::cos(a + shift), 2 * std::sin(a + shift)}, {2 * std::cos(a), 2 * std::sin(a)}});
  }
  for (int i = -1; i <= 1; ++i) {
    for (int j = -1; j <= 1; ++j) {
      if (i || j) ribs.push_back({Vec2(5.0 * i, 5.0 * j), Vec2(5.0 * i, 5.0 * j)});
    }
  }
  return ribs;
}

TEST(ChartWarp, RibsThatAgreeLeaveEveryPositionAsItIs) {
  const ChartWarp warp(twisted_hole_ribs(0));
  EXPECT_FALSE(warp.active());
  const Vec2 p(0.3, -3.1);
  EXPECT_EQ(warp.forward(p), p);
  EXPECT_EQ(warp.inverse(p), p);
}

TEST(ChartWarp, RibbedNodesLandOnTheirPartnersAndTheRestFollow) {
  const double shift = 0.2;  // 0.4 of an interval
  const auto ribs = twisted_hole_ribs(shift);
  const ChartWarp warp(ribs);
  ASSERT_TRUE(warp.active());
  for (const auto& [q, p] : ribs) EXPECT_LT((warp.forward(q) - p).norm(), 1e-12);
  // A node just outside the hole, where a foot's rim leaves it: turned back
  // by nearly the ribs' twist (the nearest ribs dominate), while a node at
  // the square's ribs barely moves.
  const double a = 0.5;
  const Vec2 near_hole(2.2 * std::cos(a + shift), 2.2 * std::sin(a + shift));
  const Vec2 moved = warp.forward(near_hole);
  const double turned = std::atan2(near_hole.y(), near_hole.x()) - std::atan2(moved.y(), moved.x());
  EXPECT_GT(turned, 0.6 * shift);
  EXPECT_LT(turned, 1.1 * shift);
  const Vec2 near_square(4.9, 4.9);
  EXPECT_LT((warp.forward(near_square) - near_square).norm(), 0.05);
  // The inverse takes forward's images back.
  for (const Vec2& q : {near_hole, near_square, Vec2(3.5, -1.0), Vec2(-2.6, 2.4)})
    EXPECT_LT((warp.inverse(warp.forward(q)) - q).norm(), 1e-6) << q.transpose();
}

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

TEST(CooperChartWarp, AHoleWhoseRibsTwistBetweenABossAndAFootIsImprinted) {
  occ::Workbench wb;
  hole_through_boss_and_foot(wb);
  const geom::Model model = wb.build_model();
  const double solid = model.volume(1).volume;
  for (const double size : {0.8194, 0.41}) {
    const pipeline::MeshResult r = mesh_at(model, size);
    EXPECT_EQ(r.plan.volumes.at(1).scheme, "cooper");
    EXPECT_TRUE(r.warnings.empty()) << r.warnings.front().message;
    // Conformal, nothing inverted (check_hex_mesh), no wedge; the hole's
    // and the round faces' chords keep the volume within 1 %.
    const testing::HexMeshSummary s = testing::check_hex_mesh(model, r.mesh);
    EXPECT_EQ(r.mesh.wedge_count(), 0u);
    EXPECT_NEAR(s.volume, solid, 0.01 * solid) << size;
    std::printf("[chart warp] size %.4g: %zu hexes, min scaled Jacobian %.3f, volume %+.3f %%\n",
                size, s.hexes, s.min_sj, 100 * (s.volume - solid) / solid);
  }
}

TEST(CooperChartWarp, TheWarpedImprintIsRotationInvariant) {
  const auto motion = testing::RigidMotion::random(118);
  occ::Workbench still, moved;
  hole_through_boss_and_foot(still);
  hole_through_boss_and_foot(moved);
  motion.apply(moved, "part");
  const pipeline::MeshResult r0 = mesh_at(still.build_model(), 0.8194);
  const pipeline::MeshResult r1 = mesh_at(moved.build_model(), 0.8194);
  ASSERT_EQ(r0.mesh.node_count(), r1.mesh.node_count());
  EXPECT_LT(testing::moved_node_distance(r0.mesh, r1.mesh, motion), 1e-7);
}

}  // namespace
}  // namespace cooperage::cooper
