// The cooper scheme end to end on models from the CAD backend: plates with
// holes, a curved axis, differently sized caps, orientation insensitivity,
// barrel uniqueness, rejections, applicable() both ways and roles().
#include "support/mesh_checks.h"
#include "support/rigid_motion.h"

#include "framework/core/error.h"
#include "framework/geometry/occ/workbench.h"
#include "must_mesh_parts.h"
#include "framework/pipeline/mesher.h"
#include "schemes/builtin_schemes.h"
#include "plan_helpers.h"
#include "scheme_helpers.h"
#include "schemes/cooper/cooper_scheme.h"
#include "schemes/map/surface_map.h"
#include "schemes/map/volume_map.h"
#include "schemes/submap/submap_scheme.h"
#include "selector/select_schemes.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <memory>
#include <random>

namespace cooperage::cooper {
namespace {

using geom::Vec3;
using testing::hex_face_counts;
using testing::hex_points;
using testing::hex_volume;

// The built-in registry: hints reach cooper through the job's settings.
using testing::builtin;

// Job settings with sweep hints on volume 1.
io::MeshSettings hinted(std::vector<int> sources, std::vector<int> targets = {}) {
  io::MeshSettings s;
  io::VolumeSetting v;
  v.id = 1;
  v.sources = std::move(sources);
  v.targets = std::move(targets);
  s.volumes.push_back(v);
  return s;
}

// Every built-in scheme but cooper, so a test can add its own instance.
void register_all_but_cooper(scheme::Registry& registry) {
  registry.add(map::make_surface_map());
  registry.add(submap::make_submap());
  registry.add(map::make_volume_map());
}

const pipeline::MeshOptions kOptions = selector::mesh_options();

io::MeshSettings cooper_job(double size, bool pin_cooper = false) {
  io::MeshSettings s;
  s.size = size;
  if (pin_cooper) {
    io::VolumeSetting v;
    v.id = 1;
    v.scheme = "cooper";
    s.volumes.push_back(v);
  }
  return s;
}

double total_hex_volume(const mesh::MeshDB& db) {
  double v = 0;
  for (const auto& [id, vol] : db.volumes()) {
    for (const auto& h : vol.hexes) v += hex_volume(hex_points(db, h));
  }
  return v;
}

double min_scaled_jacobian(const mesh::MeshDB& db) {
  double m = 1;
  for (const auto& [id, vol] : db.volumes()) {
    for (const auto& h : vol.hexes)
      m = std::min(m, testing::hex_scaled_jacobian(hex_points(db, h)));
  }
  return m;
}

// Every hex face used once or twice; the faces used once are exactly the
// surface quads (single-volume models).
void expect_conformal(const mesh::MeshDB& db) {
  const auto faces = hex_face_counts(db);
  size_t boundary = 0;
  for (const auto& [fk, n] : faces) {
    ASSERT_LE(n, 2);
    if (n == 1) ++boundary;
  }
  size_t quads = 0;
  for (const auto& [sid, s] : db.surfaces()) {
    for (const auto& q : s.quads) {
      auto it = faces.find(testing::face_key(q));
      ASSERT_NE(it, faces.end()) << "a quad of surface " << sid << " is no hex face";
      EXPECT_EQ(it->second, 1) << "surface " << sid;
      ++quads;
    }
  }
  EXPECT_EQ(boundary, quads);
  EXPECT_EQ(testing::duplicate_node_pairs(db, 1e-9), 0);
}

// 10 x 4 x 2 plate with three 1 x 1 square holes (volume 74).
void plate_with_square_holes(occ::Workbench& wb) {
  std::vector<std::vector<Vec3>> holes;
  for (double x0 : {1.5, 4.5, 7.5}) {
    holes.push_back({{x0, 1.5, 0}, {x0 + 1, 1.5, 0}, {x0 + 1, 2.5, 0}, {x0, 2.5, 0}});
  }
  wb.prism("plate", {{0, 0, 0}, {10, 0, 0}, {10, 4, 0}, {0, 4, 0}}, holes, {0, 0, 2});
}

// Curves parallel to z (the linking curves of an extrusion along z).
int layers_along_z(const geom::Model& model, const mesh::MeshDB& db) {
  for (const auto& c : model.curves()) {
    const Vec3 a = model.vertex(c.start_vertex).point;
    const Vec3 b = model.vertex(c.end_vertex).point;
    if ((a - b).head<2>().norm() < 1e-9 && std::abs(a.z() - b.z()) > 1e-9) {
      return static_cast<int>(db.curve_nodes(c.id).size()) - 1;
    }
  }
  return -1;
}

TEST(Cooper, PlateWithThreeSquareHolesSweepsExactly) {
  occ::Workbench wb;
  plate_with_square_holes(wb);
  const geom::Model model = wb.build_model();
  const auto registry = builtin();
  const pipeline::MeshResult r = pipeline::mesh_model(model, cooper_job(0.5), *registry, kOptions);
  ASSERT_EQ(r.plan.volumes.at(1).scheme, "cooper");
  const VolumePlan c = plan_test::plan_with(model, 1, *registry);
  ASSERT_TRUE(c.ok) << c.why;
  EXPECT_EQ(c.lattice.sides.size(), 4u + 3u * 4u);
  EXPECT_TRUE(c.one_barrel());
  EXPECT_EQ(c.roles.scheme.at(c.source), "submap");
  const int layers = layers_along_z(model, r.mesh);
  ASSERT_GT(layers, 0);
  EXPECT_EQ(r.mesh.hex_count(),
            r.mesh.surface(c.source).quads.size() * static_cast<size_t>(layers));
  EXPECT_EQ(r.mesh.surface(c.target).quads.size(), r.mesh.surface(c.source).quads.size());
  EXPECT_NEAR(total_hex_volume(r.mesh), 74.0, 74.0 * 1e-6);
  expect_conformal(r.mesh);
  const double sj = min_scaled_jacobian(r.mesh);
  EXPECT_GT(sj, 0.5);
  RecordProperty("min_scaled_jacobian", std::to_string(sj));
}

TEST(Cooper, PlateWithCircularHolesNeedsPave) {
  occ::Workbench wb;
  parts::plate_three_round_holes(wb);
  const geom::Model model = wb.build_model();
  const auto registry = builtin();
  if (!registry->surface_scheme("pave")) {
    const scheme::Applicability a =
        registry->volume_scheme("cooper")->applicable(scheme::VolumeView{model, 1, nullptr});
    EXPECT_FALSE(a.ok);
    EXPECT_NE(a.why.find("needs pave, which is not available"), std::string::npos) << a.why;
    GTEST_SKIP() << "no pave scheme registered: " << a.why;
  }
  const pipeline::MeshResult r = pipeline::mesh_model(model, cooper_job(0.4), *registry, kOptions);
  EXPECT_EQ(r.plan.volumes.at(1).scheme, "cooper");
  expect_conformal(r.mesh);
  EXPECT_GT(min_scaled_jacobian(r.mesh), 0.2);
  // The holes are meshed by chords: the hex volume exceeds the solid's a little.
  EXPECT_NEAR(total_hex_volume(r.mesh), model.volume(1).volume, 0.02 * model.volume(1).volume);
}

// Rectangle 2..4 x 0..2 (x, z) with a square hole, revolved 90 degrees about z.
void ring_sector_with_hole(occ::Workbench& wb) {
  wb.revolve("outer", {{2, 0, 0}, {4, 0, 0}, {4, 0, 2}, {2, 0, 2}}, {0, 0, 0}, {0, 0, 1}, 90);
  wb.revolve("inner", {{2.6, 0, 0.6}, {3.4, 0, 0.6}, {3.4, 0, 1.4}, {2.6, 0, 1.4}}, {0, 0, 0},
             {0, 0, 1}, 90);
  wb.cut("sector", {"outer", "inner"});
}

TEST(Cooper, CurvedAxisSweepGoesAroundTheArc) {
  occ::Workbench wb;
  ring_sector_with_hole(wb);
  const geom::Model model = wb.build_model();
  const auto registry = builtin();
  const pipeline::MeshResult r = pipeline::mesh_model(model, cooper_job(0.2), *registry, kOptions);
  ASSERT_EQ(r.plan.volumes.at(1).scheme, "cooper");
  const VolumePlan c = plan_test::plan_with(model, 1, *registry);
  ASSERT_TRUE(c.ok) << c.why;
  EXPECT_EQ(model.surface(c.source).loops.size(), 2u);  // the end faces are the caps
  expect_conformal(r.mesh);
  const double pi = 3.14159265358979323846;
  const double exact = pi / 4 * (16 - 4) * 2 - pi / 4 * (3.4 * 3.4 - 2.6 * 2.6) * 0.8;
  EXPECT_NEAR(total_hex_volume(r.mesh), exact, exact * 5e-3);  // arcs meshed by chords
  const double sj = min_scaled_jacobian(r.mesh);
  EXPECT_GT(sj, 0.5);
  RecordProperty("min_scaled_jacobian", std::to_string(sj));
}

// A right triangle (r 5..10 at z = 0, apex at r 5, z 5) revolved by more
// than half a turn: no straight axis sweeps it (the section ends in an
// edge), so it is swept round from one end wall to the other, whose ring
// centres lie beside each other or behind the way the ribs leave. The
// barrel's chart must face the source the way the ribs leave it (on main
// the chart across the centres gave every hex of layer 0 inside out).
TEST(Cooper, ASweepRoundMoreThanHalfATurnKeepsItsElementsRightSideOut) {
  const double pi = 3.14159265358979323846;
  for (const double turn : {190.0, 210.0, 270.0}) {
    occ::Workbench wb;
    wb.revolve("ring", {{5, 0, 0}, {10, 0, 0}, {5, 0, 5}}, {0, 0, 0}, {0, 0, 1}, turn);
    const geom::Model model = wb.build_model();
    const auto registry = builtin();
    const pipeline::MeshResult r =
        pipeline::mesh_model(model, cooper_job(0.5), *registry, kOptions);
    ASSERT_EQ(r.plan.volumes.at(1).scheme, "cooper") << turn;
    expect_conformal(r.mesh);
    EXPECT_GT(min_scaled_jacobian(r.mesh), 0.1) << turn;
    // Pappus: the triangle's area 12.5 times the path of its centroid (r 20/3).
    const double exact = 12.5 * (20.0 / 3.0) * turn * pi / 180.0;
    EXPECT_NEAR(total_hex_volume(r.mesh), exact, 0.01 * exact) << turn;
  }
}

// A 6 x 4 x 2 plate with a square hole whose +x side is sloped (x = 6 at z = 0
// to x = 5 at z = 2): caps of different size (volume 48 - 2 - 4 = 42).
void sloped_plate(occ::Workbench& wb) {
  wb.prism("plate", {{0, 0, 0}, {6, 0, 0}, {6, 4, 0}, {0, 4, 0}},
           {{{2, 1.5, 0}, {3, 1.5, 0}, {3, 2.5, 0}, {2, 2.5, 0}}}, {0, 0, 2});
  wb.brick("cutter", {6, -1, -5}, {10, 6, 10});
  wb.rotate("cutter", {6, 0, 0}, {0, 1, 0}, -std::atan(0.5) * 180 / 3.14159265358979323846);
  wb.cut("sloped", {"plate", "cutter"});
}

TEST(Cooper, DifferentlySizedCapsWithSlopedSide) {
  occ::Workbench wb;
  sloped_plate(wb);
  const geom::Model model = wb.build_model();
  ASSERT_NEAR(model.volume(1).volume, 42.0, 1e-6);
  const auto registry = builtin();
  const pipeline::MeshResult r = pipeline::mesh_model(model, cooper_job(0.25), *registry, kOptions);
  ASSERT_EQ(r.plan.volumes.at(1).scheme, "cooper");
  const VolumePlan c = plan_test::plan_with(model, 1, *registry);
  ASSERT_TRUE(c.ok) << c.why;
  EXPECT_GT(model.surface(c.source).area,
            model.surface(c.target).area);  // larger cap is the source
  expect_conformal(r.mesh);
  EXPECT_NEAR(total_hex_volume(r.mesh), 42.0, 42.0 * 1e-6);
  const double sj = min_scaled_jacobian(r.mesh);
  EXPECT_GT(sj, 0.3);
  RecordProperty("min_scaled_jacobian", std::to_string(sj));
}

// The planar end face of the 90-degree revolve lying in the plane y = 0.
int end_face_at_angle_zero(const geom::Model& model) {
  for (const auto& s : model.surfaces()) {
    if (s.geometry->type() == geom::SurfaceType::Plane && s.box.size().y() < 1e-6) return s.id;
  }
  return 0;
}

TEST(Cooper, RigidTransformGivesTheTransformedMesh) {
  const auto motion = testing::RigidMotion::random(1996);
  auto build = [&](bool moved) {
    occ::Workbench wb;
    wb.revolve("q", {{2, 0, 0}, {4, 0, 0}, {4, 0, 2}, {2, 0, 2}}, {0, 0, 0}, {0, 0, 1}, 90);
    if (moved) {
      motion.apply(wb, "q");
    }
    return wb.build_model();
  };
  const geom::Model m0 = build(false), m1 = build(true);
  // Sweep around the arc: the source hint names the end face at angle 0.
  const int end_face = end_face_at_angle_zero(m0);
  ASSERT_GT(end_face, 0);
  io::MeshSettings settings = hinted({end_face});
  settings.size = 0.25;
  settings.volumes.front().scheme = "cooper";
  const auto registry = builtin();
  const pipeline::MeshResult r0 = pipeline::mesh_model(m0, settings, *registry, kOptions);
  const pipeline::MeshResult r1 = pipeline::mesh_model(m1, settings, *registry, kOptions);
  ASSERT_EQ(r0.plan.volumes.at(1).scheme, "cooper");
  EXPECT_EQ(
      plan_test::plan_with(m0, 1, *registry, SweepHints{{end_face}, {}, std::nullopt, {}}).source,
      end_face);
  ASSERT_EQ(r0.mesh.node_count(), r1.mesh.node_count());
  ASSERT_EQ(r0.mesh.hex_count(), r1.mesh.hex_count());
  EXPECT_EQ(r0.mesh.volume(1).hexes, r1.mesh.volume(1).hexes);
  const double worst = testing::moved_node_distance(r0.mesh, r1.mesh, motion);
  EXPECT_LT(worst, 1e-9 * 10);  // 1e-9 relative to the model size (~10)
}

TEST(Cooper, PermutedFaceOrderGivesTheSameBarrelsAndMesh) {
  occ::Workbench wb;
  plate_with_square_holes(wb);
  const geom::Model model = wb.build_model();
  geom::Model permuted = model;
  auto& shell = permuted.mutable_volume(1).shells.front();
  std::mt19937 rng(42);
  std::shuffle(shell.begin(), shell.end(), rng);
  const auto registry = builtin();
  const VolumePlan c0 = plan_test::plan_with(model, 1, *registry);
  const VolumePlan c1 = plan_test::plan_with(permuted, 1, *registry);
  ASSERT_TRUE(c0.ok && c1.ok);
  EXPECT_EQ(c0.source, c1.source);
  EXPECT_EQ(c0.target, c1.target);
  EXPECT_EQ(c0.lattice.sides, c1.lattice.sides);
  const pipeline::MeshResult r0 = pipeline::mesh_model(model, cooper_job(0.5), *registry, kOptions);
  const pipeline::MeshResult r1 =
      pipeline::mesh_model(permuted, cooper_job(0.5), *registry, kOptions);
  EXPECT_EQ(r0.mesh.volume(1).hexes, r1.mesh.volume(1).hexes);
}

TEST(Cooper, SphereIsRejectedWithAReasonAndNotMeshed) {
  occ::Workbench wb;
  wb.sphere("s", {0, 0, 0}, 1);
  const geom::Model model = wb.build_model();
  const auto registry = builtin();
  const scheme::Applicability a =
      registry->volume_scheme("cooper")->applicable(scheme::VolumeView{model, 1, nullptr});
  EXPECT_FALSE(a.ok);
  EXPECT_NE(a.why.find("a sweep needs at least 3"), std::string::npos) << a.why;
  try {
    pipeline::mesh_model(model, cooper_job(0.3), *registry, kOptions);
    FAIL() << "a sphere was meshed";
  } catch (const MeshingError& e) {
    EXPECT_EQ(e.code(), ErrorCode::NotApplicable);
    EXPECT_NE(std::string(e.what()).find("cooper"), std::string::npos) << e.what();
  }
}

TEST(Cooper, BrickWithBossesOnAdjacentSidesIsRejected) {
  occ::Workbench wb;
  wb.brick("b", {0, 0, 0}, {4, 4, 4});
  wb.brick("top", {1, 1, 4}, {1, 1, 1});
  wb.brick("side", {4, 1, 1}, {1, 1, 1});
  wb.fuse("part", {"b", "top", "side"});
  const geom::Model model = wb.build_model();
  const auto registry = builtin();
  const scheme::Applicability a =
      registry->volume_scheme("cooper")->applicable(scheme::VolumeView{model, 1, nullptr});
  EXPECT_FALSE(a.ok);
  EXPECT_NE(a.why.find("volume 1"), std::string::npos) << a.why;
  RecordProperty("why", a.why);
  try {
    pipeline::mesh_model(model, cooper_job(0.5), *registry, kOptions);
    FAIL() << "two sweep directions were meshed";
  } catch (const MeshingError& e) {
    EXPECT_EQ(e.code(), ErrorCode::NotApplicable) << e.what();
  }
}

TEST(Cooper, ApplicableBothWaysAndRoles) {
  occ::Workbench wb;
  plate_with_square_holes(wb);
  const geom::Model model = wb.build_model();
  const auto registry = builtin();
  const scheme::VolumeScheme* cooper = registry->volume_scheme("cooper");
  const scheme::VolumeView view{model, 1, nullptr};
  const scheme::Applicability a = cooper->applicable(view);
  ASSERT_TRUE(a.ok) << a.why;
  EXPECT_GT(a.score, 0);
  const VolumePlan c = plan_test::plan_with(model, 1, *registry);
  const scheme::SurfaceRoles roles = cooper->roles(view);
  EXPECT_EQ(roles.size(), model.surfaces().size());
  EXPECT_EQ(roles.at(c.source), "submap");
  EXPECT_EQ(roles.at(c.target), scheme::kMeshedByVolume);
  for (int s : c.lattice.sides) EXPECT_EQ(roles.at(s), "submap");
  // A registry without submap cannot give sides.
  scheme::Registry bare;
  bare.add(make_cooper(bare));
  const scheme::Applicability no = bare.volume_scheme("cooper")->applicable(view);
  EXPECT_FALSE(no.ok);
  EXPECT_NE(no.why.find("submap"), std::string::npos) << no.why;
  // A brick is a one-barrel sweep as well (the volume map is preferred).
  occ::Workbench wb2;
  wb2.brick("b", {0, 0, 0}, {1, 2, 3});
  const geom::Model brick = wb2.build_model();
  EXPECT_TRUE(cooper->applicable(scheme::VolumeView{brick, 1, nullptr}).ok);
  const pipeline::MeshResult r =
      pipeline::mesh_model(brick, cooper_job(0.5, true), *registry, kOptions);
  EXPECT_EQ(r.mesh.hex_count(), 2u * 4u * 6u);
  EXPECT_NEAR(total_hex_volume(r.mesh), 6.0, 1e-9);
  expect_conformal(r.mesh);
}

TEST(Cooper, HintsAreObeyedOrRejectedWithAReason) {
  occ::Workbench wb;
  wb.revolve("q", {{2, 0, 0}, {4, 0, 0}, {4, 0, 2}, {2, 0, 2}}, {0, 0, 0}, {0, 0, 1}, 90);
  const geom::Model model = wb.build_model();
  scheme::Registry registry;
  register_all_but_cooper(registry);
  auto owned = std::make_unique<CooperScheme>(registry);
  const CooperScheme* cooper = owned.get();
  registry.add(std::move(owned));
  // Hints are the job's settings, handed to the scheme through the view.
  io::MeshSettings job;
  const scheme::Settings settings = scheme::Settings::of(job);
  const scheme::VolumeView view{model, 1, nullptr, &settings};
  const auto set_hints = [&](std::vector<int> sources, std::vector<int> targets) {
    job = hinted(std::move(sources), std::move(targets));
  };
  // Unhinted: the larger annular faces are the caps (a sweep along z).
  const VolumePlan free = plan_test::plan_with(model, 1, registry);
  ASSERT_TRUE(free.ok) << free.why;
  EXPECT_NEAR(model.surface(free.source).box.size().z(), 0, 1e-6);
  // A hinted source is obeyed: the sweep goes around the arc.
  const int end_face = end_face_at_angle_zero(model);
  set_hints({end_face}, {});
  const scheme::SurfaceRoles roles = cooper->roles(view);
  EXPECT_EQ(roles.at(end_face), "map");
  const VolumePlan arc =
      plan_test::plan_with(model, 1, registry, SweepHints{{end_face}, {}, {}, {}});
  ASSERT_TRUE(arc.ok) << arc.why;
  EXPECT_EQ(arc.source, end_face);
  EXPECT_EQ(roles.at(arc.target), scheme::kMeshedByVolume);
  EXPECT_EQ(model.surface(arc.target).geometry->type(), geom::SurfaceType::Plane);
  io::MeshSettings run = job;
  run.size = 0.25;
  run.volumes.front().scheme = "cooper";
  const pipeline::MeshResult r = pipeline::mesh_model(model, run, registry, kOptions);
  EXPECT_GT(min_scaled_jacobian(r.mesh), 0.5);
  expect_conformal(r.mesh);
  // A hinted target alone fixes the source too.
  set_hints({}, {end_face});
  EXPECT_EQ(cooper->roles(view).at(end_face), scheme::kMeshedByVolume);
  // Two sources: part II.
  set_hints({arc.source, arc.target}, {});
  const scheme::Applicability two = cooper->applicable(view);
  EXPECT_FALSE(two.ok);
  EXPECT_NE(two.why.find("hinted source surface"), std::string::npos) << two.why;
  // A hinted target that no one-barrel sweep from that source reaches.
  set_hints({arc.source}, {arc.lattice.sides.front()});
  const scheme::Applicability bad = cooper->applicable(view);
  EXPECT_FALSE(bad.ok);
  EXPECT_NE(bad.why.find("volume 1"), std::string::npos) << bad.why;
  // A surface of another entity.
  set_hints({999}, {});
  EXPECT_FALSE(cooper->applicable(view).ok);
  job = {};
  EXPECT_TRUE(cooper->applicable(view).ok);
}

TEST(Cooper, DirectionHintChoosesTheCaps) {
  occ::Workbench wb;
  wb.brick("b", {0, 0, 0}, {1, 2, 3});
  const geom::Model model = wb.build_model();
  const auto registry = builtin();
  for (const Vec3& d : {Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, -1)}) {
    const VolumePlan c = plan_test::plan_with(model, 1, *registry, SweepHints{{}, {}, d, {}});
    ASSERT_TRUE(c.ok) << c.why;
    const Vec3 n = model.surface(c.source).geometry->project(Vec3(0.5, 1, 1.5)).normal;
    EXPECT_NEAR(std::abs(n.dot(d)), 1.0, 1e-9) << c.why;
  }
}

}  // namespace
}  // namespace cooperage::cooper
