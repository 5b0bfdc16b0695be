// One cooper instance, many jobs: the scheme keeps no per-job state (the
// sweep hints and element kind of a volume are the job's scheme::Settings;
// its plan is the selector's), so two jobs with different hints and element
// kinds, one after the other or at the same time, each get their own mesh.
#include "support/hex_mesh_check.h"

#include "framework/geometry/occ/workbench.h"
#include "framework/pipeline/mesher.h"
#include "schemes/builtin_schemes.h"
#include "schemes/cooper/cooper_scheme.h"
#include "selector/select_schemes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <thread>

namespace cooperage::cooper {
namespace {

using geom::Vec3;

io::MeshSettings job(io::ElementKind elements, const Vec3& direction) {
  io::MeshSettings s;
  s.size = 0.5;
  s.finer_retries = 0;  // the scheme at this size, not a retry at a finer one
  io::VolumeSetting v;
  v.id = 1;
  v.scheme = "cooper";
  v.elements = elements;
  v.direction = direction;
  s.volumes.push_back(v);
  return s;
}

// The normal of the sweep's source cap, from the plan the run carried.
Vec3 source_normal(const geom::Model& model, const pipeline::MeshResult& r) {
  const auto* p = dynamic_cast<const CooperPlan*>(r.plan.volumes.at(1).data.get());
  if (!p || !p->plan.ok || p->plan.source == 0) return Vec3::Zero();
  const geom::Surface& s = model.surface(p->plan.source);
  return s.geometry->project(0.5 * (s.box.min + s.box.max)).normal;
}

void expect_same_mesh(const mesh::MeshDB& a, const mesh::MeshDB& b, const char* what) {
  ASSERT_EQ(a.node_count(), b.node_count()) << what;
  EXPECT_EQ(a.volume(1).hexes, b.volume(1).hexes) << what;
  EXPECT_EQ(a.volume(1).wedges, b.volume(1).wedges) << what;
  for (int n = 0; n < static_cast<int>(a.node_count()); ++n) {
    ASSERT_EQ(a.node(n), b.node(n)) << what << ": node " << n;
  }
}

TEST(CooperJobs, OneInstanceServesJobsWithDifferentHintsAndElementKinds) {
  occ::Workbench wb;
  wb.brick("b", {0, 0, 0}, {1, 2, 3});
  const geom::Model model = wb.build_model();
  scheme::Registry registry;
  register_builtin_schemes(registry);
  const io::MeshSettings hexes_along_x = job(io::ElementKind::Hex, Vec3(1, 0, 0));
  const io::MeshSettings wedges_along_z = job(io::ElementKind::Wedge, Vec3(0, 0, 1));
  const pipeline::MeshOptions options = selector::mesh_options(3, 1);

  const pipeline::MeshResult a = pipeline::mesh_model(model, hexes_along_x, registry, options);
  const pipeline::MeshResult b = pipeline::mesh_model(model, wedges_along_z, registry, options);
  const pipeline::MeshResult a_again =
      pipeline::mesh_model(model, hexes_along_x, registry, options);

  // Job a: hexes, swept along x (2 x 4 x 6 at size 0.5), filling the brick.
  EXPECT_NEAR(std::abs(source_normal(model, a).x()), 1.0, 1e-9);
  EXPECT_TRUE(a.mesh.volume(1).wedges.empty());
  EXPECT_EQ(a.mesh.hex_count(), 48u);
  EXPECT_NEAR(testing::check_hex_mesh(model, a.mesh).volume, 6.0, 1e-9);
  // Job b: wedges, swept along z (6 layers), on the same scheme instance.
  EXPECT_NEAR(std::abs(source_normal(model, b).z()), 1.0, 1e-9);
  EXPECT_EQ(b.mesh.hex_count(), 0u);
  ASSERT_FALSE(b.mesh.volume(1).wedges.empty());
  EXPECT_EQ(b.mesh.volume(1).wedges.size() % 6, 0u);
  // Job b left nothing behind for a's second run.
  expect_same_mesh(a.mesh, a_again.mesh, "hex job after the wedge job");

  // At the same time, in two threads: the same meshes.
  pipeline::MeshResult a_parallel, b_parallel;
  std::thread ta(
      [&] { a_parallel = pipeline::mesh_model(model, hexes_along_x, registry, options); });
  std::thread tb(
      [&] { b_parallel = pipeline::mesh_model(model, wedges_along_z, registry, options); });
  ta.join();
  tb.join();
  expect_same_mesh(a.mesh, a_parallel.mesh, "hex job in parallel");
  expect_same_mesh(b.mesh, b_parallel.mesh, "wedge job in parallel");
}

}  // namespace
}  // namespace cooperage::cooper
