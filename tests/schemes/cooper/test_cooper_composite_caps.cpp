// Cooper one-to-one with a composite source cap (Blacker 1996, sec. 4-5: one
// barrel whose cap consists of subcaps): a cap face with a hole loop filled
// by a coplanar face of the same volume (e.g. the face under a boss after a
// webcut, or the imprint of a smaller brick on a larger one). The subcaps
// are meshed by their own surface schemes, the union is swept to the single
// target face; the composite side is always the source.
#include "support/hex_mesh_check.h"
#include "support/mesh_checks.h"

#include "framework/geometry/occ/workbench.h"
#include "framework/pipeline/mesher.h"
#include "schemes/builtin_schemes.h"
#include "plan_helpers.h"
#include "scheme_helpers.h"
#include "schemes/cooper/cooper_scheme.h"
#include "selector/select_schemes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <memory>

namespace cooperage::cooper {
namespace {

using testing::builtin;

using testing::sized;

using Summary = testing::HexMeshSummary;

// The surface of `volume` with the given number of loops (the first one).
int surface_with_loops(const geom::Model& model, int volume, size_t loops) {
  for (int id : model.surfaces_of(volume)) {
    if (model.surface(id).loops.size() == loops) return id;
  }
  return 0;
}

// The surface shared by volumes 1 and 2.
int shared_surface(const geom::Model& model) {
  for (const auto& s : model.surfaces()) {
    if (s.volumes.size() == 2) return s.id;
  }
  return 0;
}

// Cylinder r 2 h 3 with a coaxial boss r 1 h 1.5, webcut at the boss's base:
// volume 1's top cap is the shoulder annulus plus the disk under the boss.
geom::Model webcut_boss() {
  occ::Workbench wb;
  wb.cylinder("body", {0, 0, 0}, {0, 0, 1}, 2.0, 3.0);
  wb.cylinder("boss", {0, 0, 3}, {0, 0, 1}, 1.0, 1.5);
  wb.fuse("part", {"body", "boss"});
  wb.webcut("part", {0, 0, 3}, {0, 0, 1});
  return wb.build_model();
}

// A 4 x 4 x 1 brick below a 2 x 2 x 1 brick inside its top face (imprinted
// and merged): volume 1's top cap is a face with a square hole plus the
// shared square.
geom::Model touching_bricks() {
  occ::Workbench wb;
  wb.brick("base", {0, 0, 0}, {4, 4, 1});
  wb.brick("top", {1, 1, 1}, {2, 2, 1});
  return wb.build_model();
}

TEST(CooperCompositeCaps, WebcutBossBodyClassifiesWithASubcap) {
  const geom::Model model = webcut_boss();
  ASSERT_EQ(model.volumes().size(), 2u);
  const auto registry = builtin();
  const int annulus = surface_with_loops(model, 1, 2);
  const int disk = shared_surface(model);
  ASSERT_NE(annulus, 0);
  ASSERT_NE(disk, 0);
  const VolumePlan c = plan_test::plan_with(model, 1, *registry);
  ASSERT_TRUE(c.ok) << c.why;
  ASSERT_TRUE(c.one_barrel());
  EXPECT_EQ(c.source, annulus);
  // One barrel whose upper cap has two subcaps: the annulus and the disk.
  const auto upper = plan_test::end_caps(c.tree.barrels.front().upper);
  EXPECT_EQ(upper, (std::vector<int>{std::min(annulus, disk), std::max(annulus, disk)}));
  ASSERT_TRUE(c.roles.scheme.count(disk));
  ASSERT_TRUE(c.roles.scheme.count(annulus));
  EXPECT_EQ(c.lattice.sides.size(), 1u);
  EXPECT_NE(c.why.find(std::to_string(disk)), std::string::npos) << c.why;
  // The roles mesh the subcap with its own surface scheme.
  const scheme::SurfaceRoles roles =
      registry->volume_scheme("cooper")->roles(scheme::VolumeView{model, 1, nullptr});
  EXPECT_EQ(roles.at(disk), c.roles.scheme.at(disk));
  EXPECT_EQ(roles.at(annulus), c.roles.scheme.at(annulus));
  EXPECT_EQ(roles.at(c.target), scheme::kMeshedByVolume);
}

TEST(CooperCompositeCaps, WebcutBossMeshesConformally) {
  const geom::Model model = webcut_boss();
  const auto registry = builtin();
  const pipeline::MeshResult r =
      pipeline::mesh_model(model, sized(0.25), *registry, selector::mesh_options());
  EXPECT_EQ(r.plan.volumes.at(1).scheme, "cooper");
  const Summary s = testing::check_hex_mesh(model, r.mesh);
  const double exact = model.volume(1).volume + model.volume(2).volume;
  EXPECT_NEAR(s.volume, exact, 0.02 * exact);  // chords of the circles
  EXPECT_GE(s.min_sj, 0.3);
  EXPECT_EQ(r.mesh.volumes().size(), 2u);
  std::printf("[cooper composite] webcut boss: %zu hexes, min scaled Jacobian %.4f\n", s.hexes,
              s.min_sj);
}

TEST(CooperCompositeCaps, TouchingBricksFlipSoTheCompositeIsTheSource) {
  const geom::Model model = touching_bricks();
  ASSERT_EQ(model.volumes().size(), 2u);
  const auto registry = builtin();
  const int holed = surface_with_loops(model, 1, 2);
  const int square = shared_surface(model);
  ASSERT_NE(holed, 0);
  ASSERT_NE(square, 0);
  const VolumePlan c = plan_test::plan_with(model, 1, *registry);
  ASSERT_TRUE(c.ok) << c.why;
  // The bottom face ties with the composite (one loop, four curves, same
  // area) and has the lower id, yet the composite is the source.
  EXPECT_EQ(c.source, holed);
  EXPECT_EQ(plan_test::end_caps(c.tree.barrels.front().upper).size(), 2u);
  EXPECT_TRUE(c.roles.scheme.count(square));
  EXPECT_EQ(c.lattice.sides.size(), 4u);
  const pipeline::MeshResult r =
      pipeline::mesh_model(model, sized(0.25), *registry, selector::mesh_options());
  EXPECT_EQ(r.plan.volumes.at(1).scheme, "cooper");
  const Summary s = testing::check_hex_mesh(model, r.mesh);
  EXPECT_NEAR(s.volume, 16.0 + 4.0, 20.0 * 1e-9);
  EXPECT_GE(s.min_sj, 0.99);
  std::printf("[cooper composite] touching bricks: %zu hexes, min scaled Jacobian %.4f\n", s.hexes,
              s.min_sj);
}

TEST(CooperCompositeCaps, HintsNamingTheSubcap) {
  const geom::Model model = touching_bricks();
  const auto registry = builtin();
  const int holed = surface_with_loops(model, 1, 2);
  const int square = shared_surface(model);
  // A source hint naming the subcap names its composite cap.
  SweepHints src;
  src.sources = {square};
  const VolumePlan a = plan_test::plan_with(model, 1, *registry, src);
  ASSERT_TRUE(a.ok) << a.why;
  EXPECT_EQ(a.source, holed);
  // A target hint naming the subcap names its composite cap too: the sweep
  // then meshes the shared subcap itself (the neighbour takes that mesh).
  SweepHints tgt;
  tgt.targets = {square};
  const VolumePlan b = plan_test::plan_with(model, 1, *registry, tgt);
  ASSERT_TRUE(b.ok) << b.why;
  EXPECT_EQ(b.target, holed);
  EXPECT_TRUE(std::count(b.roles.by_volume.begin(), b.roles.by_volume.end(), square)) << b.why;
  SweepHints host;
  host.targets = {holed};
  const VolumePlan h = plan_test::plan_with(model, 1, *registry, host);
  ASSERT_TRUE(h.ok) << h.why;
  EXPECT_EQ(h.target, holed);
}

TEST(CooperCompositeCaps, TwoSubcapsOnOneCap) {
  // A 6 x 4 x 1 brick with two small bricks on its top face: one composite
  // cap with two subcaps.
  occ::Workbench wb;
  wb.brick("base", {0, 0, 0}, {6, 4, 1});
  wb.brick("a", {1, 1, 1}, {1.5, 2, 1});
  wb.brick("b", {3.5, 1, 1}, {2, 2, 1});
  const geom::Model model = wb.build_model();
  ASSERT_EQ(model.volumes().size(), 3u);
  const auto registry = builtin();
  const VolumePlan c = plan_test::plan_with(model, 1, *registry);
  ASSERT_TRUE(c.ok) << c.why;
  EXPECT_EQ(c.source, surface_with_loops(model, 1, 3));
  EXPECT_EQ(plan_test::end_caps(c.tree.barrels.front().upper).size(), 3u);
  const pipeline::MeshResult r =
      pipeline::mesh_model(model, sized(0.25), *registry, selector::mesh_options());
  EXPECT_EQ(r.plan.volumes.at(1).scheme, "cooper");
  const Summary s = testing::check_hex_mesh(model, r.mesh);
  EXPECT_NEAR(s.volume, 24.0 + 3.0 + 4.0, 31.0 * 1e-9);
  EXPECT_GE(s.min_sj, 0.99);
}

TEST(CooperCompositeCaps, SubcapsOnBothEndsSharedWithNeighboursMeshInTurn) {
  // One small brick on top, one below: both caps of the base are composite,
  // and a subcap of each is a face of a neighbour. The base's sweep meshes
  // the subcap it ends on itself; the brick below takes that mesh as its
  // source cap, so it is meshed after the base (plan.waits_for).
  occ::Workbench wb;
  wb.brick("base", {0, 0, 0}, {6, 4, 1});
  wb.brick("a", {1, 1, 1}, {1.5, 2, 1});
  wb.brick("b", {3.5, 1, -1}, {2, 2, 1});
  const geom::Model model = wb.build_model();
  ASSERT_EQ(model.volumes().size(), 3u);
  const auto registry = builtin();
  const VolumePlan c = plan_test::plan_with(model, 1, *registry);
  ASSERT_TRUE(c.ok) << c.why;
  const pipeline::MeshResult r =
      pipeline::mesh_model(model, sized(0.25), *registry, selector::mesh_options());
  EXPECT_EQ(r.plan.volumes.at(1).scheme, "cooper");
  ASSERT_FALSE(r.plan.waits_for.empty());
  // Whoever waits, waits for a neighbour that shares a face with it.
  for (const auto& [v, others] : r.plan.waits_for) {
    for (int o : others) {
      bool shares = false;
      for (const auto& s : model.surfaces()) {
        shares = shares || (std::count(s.volumes.begin(), s.volumes.end(), v) &&
                            std::count(s.volumes.begin(), s.volumes.end(), o));
      }
      EXPECT_TRUE(shares) << v << " waits for " << o;
    }
  }
  // Conformal (every interior face shared by two hexes), all of the volume.
  const Summary s = testing::check_hex_mesh(model, r.mesh);
  EXPECT_NEAR(s.volume, 24.0 + 3.0 + 4.0, 31.0 * 1e-9);
  EXPECT_GE(s.min_sj, 0.99);
}

TEST(CooperCompositeCaps, ASubcapOfAnotherVolumeAlone) {
  // Volume 2 (the boss) is a plain one-to-one sweep: no subcaps.
  const geom::Model model = webcut_boss();
  const auto registry = builtin();
  const VolumePlan c = plan_test::plan_with(model, 2, *registry);
  ASSERT_TRUE(c.ok) << c.why;
  ASSERT_TRUE(c.one_barrel());
  EXPECT_EQ(plan_test::end_caps(c.tree.barrels.front().upper).size(), 1u);
  // Its cap shared with the body is the one meshed by its surface scheme.
  EXPECT_EQ(c.source, shared_surface(model));
}

}  // namespace
}  // namespace cooperage::cooper
