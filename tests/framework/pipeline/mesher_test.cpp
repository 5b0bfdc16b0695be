// The pipeline end to end on models from the CAD backend, checked against
// geometry: counts, volumes, conformity, transformation invariance.
#include "support/mesh_checks.h"
#include "support/rigid_motion.h"

#include "framework/core/error.h"

#include "framework/geometry/occ/workbench.h"
#include "framework/pipeline/mesher.h"
#include "pipeline_helpers.h"
#include "schemes/builtin_schemes.h"
#include "selector/select_schemes.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <random>

namespace cooperage::pipeline {
namespace {

using geom::Vec3;
using testing::duplicate_node_pairs;
using testing::hex_face_counts;
using testing::hex_points;
using testing::hex_scaled_jacobian;
using testing::hex_volume;

using testing::builtin_registry;
using testing::sized;

const MeshOptions kOptions = selector::mesh_options();

double total_hex_volume(const mesh::MeshDB& db) {
  double v = 0;
  for (const auto& [id, vol] : db.volumes()) {
    for (const auto& h : vol.hexes) v += hex_volume(hex_points(db, h));
  }
  return v;
}

// Every hex face is used once (boundary) or twice (interior); the faces used
// once are exactly the quads of surfaces that bound one volume, and the quads
// of a surface shared by two volumes are faces used twice.
void expect_conformal(const geom::Model& model, const mesh::MeshDB& db) {
  const auto faces = hex_face_counts(db);
  std::map<testing::FaceKey, int> boundary;
  for (const auto& [fk, n] : faces) {
    ASSERT_LE(n, 2);
    if (n == 1) boundary[fk] = 1;
  }
  size_t surface_quads_on_boundary = 0;
  for (const auto& [sid, s] : db.surfaces()) {
    const bool shared = model.surface(sid).volumes.size() == 2;
    for (const auto& q : s.quads) {
      const auto key = testing::face_key(q);
      auto it = faces.find(key);
      ASSERT_NE(it, faces.end()) << "surface " << sid << " quad is no hex face";
      EXPECT_EQ(it->second, shared ? 2 : 1) << "surface " << sid;
      if (!shared) ++surface_quads_on_boundary;
    }
  }
  EXPECT_EQ(boundary.size(), surface_quads_on_boundary);
}

TEST(Mesher, Brick2x3x4AtHalfGivesExactCountsVolumeAndConformity) {
  occ::Workbench bench;
  bench.brick("b", {0, 0, 0}, {2, 3, 4});
  const geom::Model model = bench.build_model();
  const MeshResult r = mesh_model(model, sized(0.5), builtin_registry(), kOptions);
  EXPECT_EQ(r.plan.volumes.at(1).scheme, "map");
  EXPECT_EQ(r.mesh.hex_count(), 4u * 6u * 8u);
  EXPECT_NEAR(total_hex_volume(r.mesh), 24.0, 1e-9);
  EXPECT_EQ(r.mesh.node_count(), 5u * 7u * 9u);
  EXPECT_EQ(duplicate_node_pairs(r.mesh, 1e-9), 0);
  expect_conformal(model, r.mesh);
  for (const auto& h : r.mesh.volume(1).hexes) {
    EXPECT_NEAR(hex_scaled_jacobian(hex_points(r.mesh, h)), 1.0, 1e-12);
  }
}

TEST(Mesher, QuarterAnnulusExtrudedMeshesByVolumeMapWithGoodQuality) {
  // Inner radius 1, outer 2, a quarter turn, height 1: two planar ends, two
  // planar cuts, two cylindrical faces: a curved six-sided volume.
  occ::Workbench bench;
  bench.revolve("q", {{1, 0, 0}, {2, 0, 0}, {2, 0, 1}, {1, 0, 1}}, {0, 0, 0}, {0, 0, 1}, 90);
  const geom::Model model = bench.build_model();
  ASSERT_EQ(model.surfaces().size(), 6u);
  const MeshResult r = mesh_model(model, sized(0.2), builtin_registry(), kOptions);
  EXPECT_EQ(r.plan.volumes.at(1).scheme, "map");
  double min_sj = 1;
  for (const auto& h : r.mesh.volume(1).hexes) {
    min_sj = std::min(min_sj, hex_scaled_jacobian(hex_points(r.mesh, h)));
  }
  EXPECT_GT(min_sj, 0.5);
  // Exact volume pi/4 (2^2 - 1^2) * 1; the mesh's chords cut the outer arc
  // and bulge past the inner one, so allow the chordal error of size 0.2.
  EXPECT_NEAR(total_hex_volume(r.mesh), M_PI * 3.0 / 4.0, 0.02);
  expect_conformal(model, r.mesh);
  // Boundary nodes lie on their surfaces.
  for (size_t n = 0; n < r.mesh.node_count(); ++n) {
    const auto owner = r.mesh.owner(static_cast<int>(n));
    if (owner.dim != 2) continue;
    const auto proj = model.surface(owner.id).geometry->project(r.mesh.node(static_cast<int>(n)));
    EXPECT_LT(proj.distance, 1e-7);
  }
}

TEST(Mesher, TwoMergedBricksShareTheNodesOfTheirCommonFace) {
  occ::Workbench bench;
  bench.brick("a", {0, 0, 0}, {1, 1, 1});
  bench.brick("b", {1, 0, 0}, {1, 1, 1});
  const geom::Model model = bench.build_model();
  ASSERT_EQ(model.volumes().size(), 2u);
  const MeshResult r = mesh_model(model, sized(0.25), builtin_registry(), kOptions);
  EXPECT_EQ(r.mesh.hex_count(), 2u * 64u);
  EXPECT_EQ(r.mesh.node_count(), 9u * 5u * 5u);
  EXPECT_EQ(duplicate_node_pairs(r.mesh, 1e-9), 0);
  EXPECT_NEAR(total_hex_volume(r.mesh), 2.0, 1e-9);
  expect_conformal(model, r.mesh);
}

TEST(Mesher, RigidTransformGivesTheTransformedMesh) {
  const auto motion = testing::RigidMotion::random(2024);
  auto build = [&](bool moved) {
    occ::Workbench bench;
    bench.revolve("q", {{1, 0, 0}, {2, 0, 0}, {2, 0, 1}, {1, 0, 1}}, {0, 0, 0}, {0, 0, 1}, 90);
    if (moved) {
      motion.apply(bench, "q");
    }
    return bench.build_model();
  };
  const geom::Model m0 = build(false), m1 = build(true);
  const MeshResult r0 = mesh_model(m0, sized(0.25), builtin_registry(), kOptions);
  const MeshResult r1 = mesh_model(m1, sized(0.25), builtin_registry(), kOptions);
  ASSERT_EQ(r0.mesh.node_count(), r1.mesh.node_count());
  ASSERT_EQ(r0.mesh.hex_count(), r1.mesh.hex_count());
  EXPECT_EQ(r0.mesh.volume(1).hexes, r1.mesh.volume(1).hexes);  // same connectivity
  const double worst = testing::moved_node_distance(r0.mesh, r1.mesh, motion);
  EXPECT_LT(worst, 1e-9 * 10);  // 1e-9 relative to the model size (~10)
}

TEST(Mesher, SphereHasNoApplicableSchemeAndSaysWhy) {
  occ::Workbench bench;
  bench.sphere("s", {0, 0, 0}, 1);
  const geom::Model model = bench.build_model();
  try {
    mesh_model(model, sized(0.2), builtin_registry(), kOptions);
    FAIL() << "a sphere was meshed";
  } catch (const MeshingError& e) {
    EXPECT_EQ(e.code(), ErrorCode::NotApplicable);
    EXPECT_EQ(e.entity().dim, 3);
    EXPECT_NE(std::string(e.what()).find("map"), std::string::npos) << e.what();
  }
}

TEST(Mesher, SameInputSameMeshForAnyThreadCount) {
  occ::Workbench bench;
  bench.brick("a", {0, 0, 0}, {1, 1, 1});
  bench.brick("b", {1, 0, 0}, {1, 1, 1});
  bench.brick("c", {0, 1, 0}, {1, 1, 1});
  const geom::Model model = bench.build_model();
  MeshOptions one = selector::mesh_options(3, 1);
  MeshOptions many = selector::mesh_options(3, 4);
  const MeshResult a = mesh_model(model, sized(0.2), builtin_registry(), one);
  const MeshResult b = mesh_model(model, sized(0.2), builtin_registry(), many);
  ASSERT_EQ(a.mesh.node_count(), b.mesh.node_count());
  for (size_t n = 0; n < a.mesh.node_count(); ++n) {
    EXPECT_EQ(a.mesh.node(static_cast<int>(n)), b.mesh.node(static_cast<int>(n)));
  }
  for (const auto& [id, v] : a.mesh.volumes()) EXPECT_EQ(v.hexes, b.mesh.volume(id).hexes);
}

}  // namespace
}  // namespace cooperage::pipeline
