// Caps on periodic faces (loop_nodes.cpp, slab_regions.cpp, weld_seams.cpp):
// a ring whose four faces are all conical bands, each one CAD loop through
// its seam. Refused before ("two outer cycles of side faces bound one
// region"); now one barrel from one band to the opposite one, the target's
// seam taking the images of the source seam's nodes.
#include "support/hex_mesh_check.h"

#include "framework/geometry/occ/workbench.h"
#include "framework/pipeline/mesher.h"
#include "plan_helpers.h"
#include "schemes/builtin_schemes.h"
#include "schemes/cooper/loop_nodes.h"
#include "selector/select_schemes.h"

#include <gtest/gtest.h>

#include <cmath>

namespace cooperage::cooper {
namespace {

// The quadrilateral (r, z) = (50, 0), (60, 5), (55, 15), (45, 10) revolved
// about z: its area 125 and centroid r = 52.5 give the volume by Pappus.
geom::Model conical_ring() {
  occ::Workbench wb;
  wb.revolve("ring", {{50, 0, 0}, {60, 0, 5}, {55, 0, 15}, {45, 0, 10}}, {0, 0, 0}, {0, 0, 1}, 360);
  return wb.build_model();
}

TEST(CooperSeams, ARingOfConicalBandsSweepsFromOneBandToTheOpposite) {
  const geom::Model model = conical_ring();
  const double exact = 2 * M_PI * 52.5 * 125.0;
  ASSERT_NEAR(model.volume(1).volume, exact, 1e-6 * exact);
  for (const auto& s : model.surfaces()) EXPECT_NE(single_seam(s), 0) << "surface " << s.id;
  scheme::Registry registry;
  register_builtin_schemes(registry);
  const VolumePlan plan = plan_test::plan_with(model, 1, registry);
  ASSERT_TRUE(plan.ok) << plan.why;
  EXPECT_TRUE(plan.one_barrel());
  ASSERT_EQ(plan.roles.by_volume.size(), 1u);  // the target, meshed by the sweep
  io::MeshSettings settings;
  settings.size = 3.0;
  const pipeline::MeshResult r =
      pipeline::mesh_model(model, settings, registry, selector::mesh_options());
  EXPECT_EQ(r.plan.volumes.at(1).scheme, "cooper");
  // Conformal, every boundary quad a hex face, no two nodes at one place
  // (the target seam's nodes are the swept ones, none left beside them).
  const testing::HexMeshSummary s = testing::check_hex_mesh(model, r.mesh);
  EXPECT_GT(s.hexes, 0u);
  EXPECT_NEAR(s.volume, exact, 0.01 * exact);
  EXPECT_GE(s.min_sj, 0.9);  // a swept band of nearly parallel cones (measured 0.997)
  std::size_t used = 0;
  std::vector<char> in_hex(r.mesh.node_count(), 0);
  for (const auto& [id, v] : r.mesh.volumes()) {
    for (const mesh::Hex& h : v.hexes) {
      for (int n : h) in_hex[static_cast<std::size_t>(n)] = 1;
    }
  }
  for (char c : in_hex) used += c;
  EXPECT_EQ(used, r.mesh.node_count()) << "nodes outside every hex";
}

}  // namespace
}  // namespace cooperage::cooper
