// The selector's paving of map/submap faces that starve a thin face's
// curves (selector/starved_curves.h), checked on the surface mesh it leads
// to, against the same selection without it.
#include "framework/geometry/occ/workbench.h"
#include "schemes/builtin_schemes.h"
#include "selector/select_schemes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

namespace cooperage::selector {
namespace {

// A square boss fused on a block, its wall 0.05 from the block's edge: the
// block's top face is 0.05 wide there, so curve sizing asks the boss's
// bottom edge and the block's top edge for small intervals (32 and 44 at
// size 1), but the boss's mapped walls and top tie the bottom edge to
// edges that ask 4, and the block's mapped side and bottom tie its top
// edge to the far one. Held at a quarter and at under half their goals,
// the thin strip's two sides do not match and the top face gets triangles
// of 0.15 (the pattern of real-cad gmsh_Kurbelwelle's 0.05 crescent). The
// faces holding those curves are paved instead, the change is explained,
// and the surface mesh is all quads of at least 0.2, within 1 % of the
// area.
TEST(StarvedCurves, MapFacesHoldingAThinFacesCurvesFarBelowTheirGoalsArePaved) {
  occ::Workbench bench;
  bench.brick("block", {0, 0, 0}, {10, 10, 3});
  bench.brick("boss", {3, 0.05, 3}, {4, 4, 2});
  bench.fuse("part", {"block", "boss"});
  const geom::Model model = bench.build_model();
  scheme::Registry registry;
  register_builtin_schemes(registry);
  io::MeshSettings settings;
  settings.size = 1;
  const auto mesh_with = [&](bool pave_starved, Selection& selection) {
    SelectOptions options;
    options.dim = 2;
    options.refuse_per_volume = true;
    options.pave_starved_curves = pave_starved;
    selection = select_schemes(model, registry, settings, options);
    pipeline::MeshOptions mesh = mesh_options(2);
    mesh.planner = [options](const geom::Model& m, const scheme::Registry& r,
                             const io::MeshSettings& s,
                             int) { return select_schemes(m, r, s, options).plan(); };
    return pipeline::mesh_model(model, settings, registry, mesh);
  };
  const auto worst = [](const pipeline::MeshResult& r) {
    double min = 1;
    for (const auto& b : r.quality.blocks) min = std::min(min, b.find("scaled_jacobian")->min);
    return min;
  };
  const auto triangles = [&](const pipeline::MeshResult& r) {
    size_t n = 0;
    for (const auto& s : model.surfaces()) n += r.mesh.surface(s.id).tris.size();
    return n;
  };

  Selection before, after;
  const pipeline::MeshResult held = mesh_with(false, before);
  EXPECT_TRUE(before.relaxations.empty());
  EXPECT_TRUE(triangles(held) > 0 || worst(held) < 0.2) << worst(held);

  const pipeline::MeshResult freed = mesh_with(true, after);
  ASSERT_FALSE(after.relaxations.empty());
  for (const std::string& r : after.relaxations) {
    EXPECT_NE(r.find(" -> pave (curve "), std::string::npos) << r;
    EXPECT_NE(r.find(" held it at "), std::string::npos) << r;
  }
  int paved = 0;
  for (const Choice& c : after.surfaces) {
    if (c.reason.rfind("paved instead of ", 0) == 0) ++paved;
  }
  EXPECT_EQ(static_cast<size_t>(paved), after.relaxations.size());
  EXPECT_EQ(triangles(freed), 0u);
  EXPECT_GE(worst(freed), 0.2);
  for (const pipeline::MeasureCheck& m : freed.measures)
    EXPECT_LT(m.deviation(), 0.01) << m.entity.name();
  // Deterministic: the same changes again.
  Selection again;
  mesh_with(true, again);
  EXPECT_EQ(again.relaxations, after.relaxations);
}

}  // namespace
}  // namespace cooperage::selector
