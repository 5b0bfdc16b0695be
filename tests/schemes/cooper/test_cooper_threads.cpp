// One volume meshed on one thread and on two: the same mesh bit for bit
// (node coordinates, element connectivity, the volume and quality sums),
// since every parallel step writes fixed slots or sums fixed chunks in a
// fixed order (issue 20). The parts are large enough that each parallel
// loop splits into several chunks.
#include "must_mesh_parts.h"
#include "support/mesh_checks.h"

#include "framework/geometry/occ/workbench.h"
#include "framework/pipeline/mesher.h"
#include "schemes/builtin_schemes.h"
#include "selector/select_schemes.h"

#include <gtest/gtest.h>

#include <cstring>
#include <thread>

namespace cooperage::cooper {
namespace {

pipeline::MeshResult mesh_on(int threads, const geom::Model& model, double size) {
  scheme::Registry registry;
  register_builtin_schemes(registry);
  pipeline::MeshOptions options = selector::mesh_options();
  options.threads = threads;
  io::MeshSettings settings;
  settings.size = size;
  return pipeline::mesh_model(model, settings, registry, options);
}

void expect_same_bits(const pipeline::MeshResult& a, const pipeline::MeshResult& b) {
  ASSERT_EQ(a.mesh.node_count(), b.mesh.node_count());
  EXPECT_EQ(0, std::memcmp(a.mesh.coords().data(), b.mesh.coords().data(),
                           a.mesh.node_count() * sizeof(geom::Vec3)));
  ASSERT_EQ(a.mesh.volumes().size(), b.mesh.volumes().size());
  for (const auto& [id, v] : a.mesh.volumes()) {
    EXPECT_EQ(v.hexes, b.mesh.volume(id).hexes) << "volume " << id;
    EXPECT_EQ(v.wedges, b.mesh.volume(id).wedges) << "volume " << id;
  }
  for (const auto& [id, s] : a.mesh.surfaces()) {
    EXPECT_EQ(s.quads, b.mesh.surface(id).quads) << "surface " << id;
    EXPECT_EQ(s.tris, b.mesh.surface(id).tris) << "surface " << id;
  }
  ASSERT_EQ(a.measures.size(), b.measures.size());
  for (size_t i = 0; i < a.measures.size(); ++i) {
    // Bit for bit, not to a tolerance: the sums are taken in a fixed order.
    EXPECT_EQ(0, std::memcmp(&a.measures[i].mesh, &b.measures[i].mesh, sizeof(double)));
    EXPECT_EQ(0, std::memcmp(&a.measures[i].faceting, &b.measures[i].faceting, sizeof(double)));
  }
}

void check_threads(const geom::Model& model, double size, size_t min_hexes) {
  if (std::thread::hardware_concurrency() < 2) GTEST_SKIP() << "one hardware thread only";
  const pipeline::MeshResult one = mesh_on(1, model, size);
  const pipeline::MeshResult two = mesh_on(2, model, size);
  ASSERT_GE(one.mesh.hex_count(), min_hexes) << "too small to split the parallel loops";
  // Conformal: every hex face used once or twice, the faces used once are
  // the surface quads, no two nodes coincide.
  size_t boundary = 0, quads = 0;
  for (const auto& [face, uses] : testing::hex_face_counts(one.mesh)) {
    ASSERT_LE(uses, 2);
    boundary += uses == 1 ? 1 : 0;
  }
  for (const auto& [sid, s] : one.mesh.surfaces()) quads += s.quads.size();
  EXPECT_EQ(boundary, quads);
  EXPECT_EQ(testing::duplicate_node_pairs(one.mesh, 1e-9), 0);
  // The meshed volume, credited for the facets of the curved faces, is the
  // solid's: the parallel hand-over lost or duplicated no element.
  for (const auto& m : one.measures) EXPECT_LT(m.deviation(), 1e-3) << m.entity.name();
  expect_same_bits(one, two);
}

TEST(CooperThreads, PlateWithRoundHolesIsTheSameOnOneAndTwoThreads) {
  occ::Workbench wb;
  parts::plate_three_round_holes(wb);
  check_threads(wb.build_model(), 0.12, 30000);
}

TEST(CooperThreads, ManyToOneFlangedHubIsTheSameOnOneAndTwoThreads) {
  occ::Workbench wb;
  parts::flanged_hub(wb);
  check_threads(wb.build_model(), 0.08, 20000);
}

}  // namespace
}  // namespace cooperage::cooper
