// The walls between a sweep's caps have their nodes on the caps' levels
// (level_spacing.h): with several barrels on one cap stack, a wall from the
// top to the bottom runs past a blind hole's floor and a counterbore's
// steps without a vertex there; spaced by its own size function its rings
// of ribs lay off those levels, the virtual caps were warped and the
// hexes under the floors sheared (gmsh_918_pump_carter_sup, issue 15).
#include "support/hex_mesh_check.h"

#include "framework/core/error.h"
#include "framework/geometry/occ/workbench.h"
#include "framework/pipeline/mesher.h"
#include "schemes/builtin_schemes.h"
#include "selector/select_schemes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <string>
#include <vector>

namespace cooperage::cooper {
namespace {

// tests/schemes/cooper/data/cooper_levels_lug_counterbore.xml: a 200 x 120
// x 56 block, blind holes (radius 3.4) from the top to z = 31, a bore
// (radius 20) counterbored to z = 12 (radius 28) and z = 17 (radius 40),
// and a lug (radius 9) whose wall runs 2 below the block: that small step
// grades the walls' curves.
geom::Model lug_counterbore() {
  occ::Workbench wb;
  wb.brick("block", {-60, -60, 0}, {200, 120, 56});
  wb.cylinder("lug", {140, -60, -2}, {0, 0, 1}, 9, 58);
  wb.cylinder("counterbore", {0, 0, 17}, {0, 0, 1}, 40, 50);
  wb.cylinder("step", {0, 0, 12}, {0, 0, 1}, 28, 10);
  wb.cylinder("bore", {0, 0, -5}, {0, 0, 1}, 20, 30);
  wb.cylinder("h1", {80, 30, 31}, {0, 0, 1}, 3.4, 30);
  wb.cylinder("h2", {-45, -45, 31}, {0, 0, 1}, 3.4, 30);
  wb.cylinder("h3", {110, -40, 31}, {0, 0, 1}, 3.4, 30);
  wb.fuse("body", {"block", "lug"});
  wb.cut("part", {"body", "counterbore", "step", "bore", "h1", "h2", "h3"});
  return wb.build_model();
}

// On main the hexes under the floors sheared (min scaled Jacobian 0.064 at
// size 8); now the wall x = -60 has a row of nodes on every cap level (the
// floors at 31, the steps at 17 and 12), and the mesh is good.
TEST(CooperLevelSpacing, WallRowsLieOnTheCapsLevels) {
  const geom::Model model = lug_counterbore();
  ASSERT_EQ(model.volumes().size(), 1u);
  const double exact = 200.0 * 120 * 56 + M_PI * 81 * 58 - M_PI * 81 * 56 * 0.25 -
                       M_PI * (40 * 40 * 39 + 28 * 28 * 5 + 20 * 20 * 12) -
                       3 * M_PI * 3.4 * 3.4 * 25;
  scheme::Registry registry;
  register_builtin_schemes(registry);
  for (double size : {8.0, 11.0, 14.0}) {
    io::MeshSettings settings;
    settings.size = size;
    pipeline::MeshOptions options = selector::mesh_options();
    options.threads = 1;
    pipeline::MeshResult res;
    try {
      res = pipeline::mesh_model(model, settings, registry, options);
    } catch (const MeshingError& e) {
      ADD_FAILURE() << "size " << size << ": " << e.what();
      continue;
    }
    EXPECT_EQ(res.plan.volumes.at(1).scheme, "cooper") << size;
    const testing::HexMeshSummary s = testing::check_hex_mesh(model, res.mesh);
    EXPECT_NEAR(s.volume, exact, 0.005 * exact) << size;
    EXPECT_GE(s.min_sj, 0.3) << size;
    std::set<long> rows;  // z of the nodes on the wall x = -60, in 1e-6 (a level within 1e-4 of the
                          // size: the size functions step over short ramps)
    for (size_t i = 0; i < res.mesh.node_count(); ++i) {
      const geom::Vec3& p = res.mesh.node(static_cast<int>(i));
      if (std::abs(p.x() + 60) < 1e-6) rows.insert(std::lround(p.z() * 1e6));
    }
    for (double level : {31.0, 17.0, 12.0}) {
      bool on = false;
      for (long z : rows) on = on || std::abs(z * 1e-6 - level) < 1e-4 * size;
      std::string have;
      for (long z : rows) have += " " + std::to_string(z * 1e-6);
      EXPECT_TRUE(on) << "size " << size << ": no row of the wall at z = " << level << ":" << have;
    }
    std::printf("[cooper levels] lug and counterbore, size %g: %zu hexes, min SJ %.4f\n", size,
                s.hexes, s.min_sj);
  }
}

/// The heights of the mesh's nodes on the vertical line through (x, y).
std::vector<double> heights_on(const mesh::MeshDB& mesh, double x, double y) {
  std::vector<double> z;
  for (size_t i = 0; i < mesh.node_count(); ++i) {
    const geom::Vec3& p = mesh.node(static_cast<int>(i));
    if (std::abs(p.x() - x) < 1e-6 && std::abs(p.y() - y) < 1e-6) z.push_back(p.z());
  }
  std::sort(z.begin(), z.end());
  return z;
}

bool has_height(const std::vector<double>& z, double level, double tol) {
  return std::any_of(z.begin(), z.end(), [&](double h) { return std::abs(h - level) < tol; });
}

std::string text(const std::vector<double>& z) {
  std::string out;
  for (double h : z) out += " " + std::to_string(h);
  return out;
}

/// Cooper's mesh of `model` at `size`, one thread, checked (check_hex_mesh).
pipeline::MeshResult swept_at(const geom::Model& model, double size) {
  scheme::Registry registry;
  register_builtin_schemes(registry);
  io::MeshSettings settings;
  settings.size = size;
  settings.finer_retries = 0;  // at the size asked, or not at all
  pipeline::MeshOptions options = selector::mesh_options();
  options.threads = 1;
  pipeline::MeshResult res = pipeline::mesh_model(model, settings, registry, options);
  EXPECT_EQ(res.plan.volumes.at(1).scheme, "cooper");
  const testing::HexMeshSummary s = testing::check_hex_mesh(model, res.mesh);
  const double exact = model.volume(1).volume;
  EXPECT_NEAR(s.volume, exact, 0.01 * exact);
  EXPECT_GE(s.min_sj, 0.2);
  std::printf("[cooper levels] size %g: %zu hexes, min SJ %.4f\n", size, s.hexes, s.min_sj);
  return res;
}

// A lug on the wall x = 48.99 whose cone's rim (z = 10.69) is not a cap
// level, 13.2 below a pocket's floor (23.91), at size 16.375 (the plan =>
// mesh campaign, fuzz/parity_campaign.py --seed 10 case 169). The counts put
// the rim on the floor's layer; that layer then tilted down across the 6.7
// wide wall beside the lug, and the wall's quad at the rim folded with all
// four corners on its boundary ("the lattice fill gives an inverted quad").
// The ring is now preferably a layer from the level (barrel_constraints.h),
// and the wall's edge has a row at the rim's height and one at the floor's.
TEST(CooperLevelSpacing, ALugsRimALayerBelowAPocketsFloorKeepsTheWallFlat) {
  occ::Workbench wb;
  wb.brick("block", {0, 0, 0}, {48.99, 38.6, 36.9});
  wb.brick("pocket", {33.5, 23.9, 23.91}, {8.32, 4.1, 49.89});
  wb.cylinder("lug", {48.99, 12.7, 10.69}, {0, 0, 1}, 6.03, 26.21);
  wb.cone("under", {48.99, 12.7, 7.82}, {0, 0, 1}, 2.48, 6.03, 2.87);
  wb.cylinder("hole", {21.81, 32.08, 7.51}, {0, 0, 1}, 3.13, 66.29);
  wb.cylinder("foot", {12.94, 13.58, -32.51}, {0, 0, 1}, 7.81, 32.51);
  wb.fuse("body", {"block", "lug", "under", "foot"});
  wb.cut("part", {"body", "pocket", "hole"});
  const geom::Model model = wb.build_model();
  ASSERT_EQ(model.volumes().size(), 1u);
  const double size = 16.375;
  pipeline::MeshResult res;
  ASSERT_NO_THROW(res = swept_at(model, size));
  const std::vector<double> z = heights_on(res.mesh, 48.99, 0.0);
  for (double level : {10.69, 23.91})
    EXPECT_TRUE(has_height(z, level, 1e-3 * size)) << "no row at z = " << level << ":" << text(z);
}

}  // namespace
}  // namespace cooperage::cooper
