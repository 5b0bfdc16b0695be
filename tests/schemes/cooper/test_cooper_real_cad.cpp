// Cooper on real CAD made by other people (../shared/real-cad, PROVENANCE.md
// there; never copied into the repository): volumes whose plan was accepted
// and whose meshing then failed (issue 15). Skipped, saying so, when the
// folder is absent.
#include "framework/pipeline/build_geometry.h"
#include "framework/pipeline/mesher.h"
#include "schemes/builtin_schemes.h"
#include "selector/select_schemes.h"

#include "support/real_cad.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace cooperage::cooper {
namespace {

namespace fs = std::filesystem;

using testing::real_cad;

// gmsh_as1-tu-203's plate (volume 11 of 18, not decomposed): two blocks on
// its top, six nuts below, two straddling each block's edge. Imprinting
// refused it ("no imprinting step applies to the unmatched subcaps: upper
// 6, lower 4, 16, 22"); the blocks' footprints reach the underside only as
// paths between two nuts' outlines. At D/100 the plate meshes: all hex, min
// scaled Jacobian at least 0.3, its volume within 0.5 % of the CAD's. (At
// D/80 its min scaled Jacobian is 0.27, and at D/40 its sweep still inverts
// a hex: the straddle is 2.5 wide, the size 6.6.)
TEST(CooperRealCad, PlateWithNutsAcrossTheBlocksEdgesMeshes) {
  const std::string path = real_cad("gmsh_as1-tu-203.stp");
  if (!fs::exists(path))
    GTEST_SKIP() << path << " is absent (the shared real-CAD folder is not here)";
  const geom::Model model = pipeline::load_any(path);
  ASSERT_EQ(model.volumes().size(), 18u);
  io::MeshSettings settings;
  settings.size = model.box().diagonal() / 100.0;
  scheme::Registry registry;
  register_builtin_schemes(registry);
  pipeline::MeshOptions options = selector::mesh_options();
  options.allow_partial = true;  // volumes 10 and 18 have no scheme, uncut
  options.threads = 1;
  const pipeline::MeshResult r = pipeline::mesh_model(model, settings, registry, options);
  constexpr int kPlate = 11;
  EXPECT_EQ(r.plan.volumes.at(kPlate).scheme, "cooper");
  bool meshed = false;
  for (const auto& v : r.verdicts) {
    if (v.entity.id == kPlate) {
      meshed = v.state == pipeline::Verdict::State::Meshed;
      EXPECT_TRUE(meshed) << v.reason;
    }
  }
  ASSERT_TRUE(meshed);
  bool measured = false;
  for (const auto& m : r.measures) {
    if (m.entity.id != kPlate) continue;
    measured = true;
    EXPECT_LT(m.deviation(), 0.005) << m.mesh << " vs " << m.cad;
  }
  EXPECT_TRUE(measured);
  bool hexes = false;
  for (const auto& b : r.quality.blocks) {
    if (b.dim != 3 || b.id != kPlate) continue;
    hexes = b.type == quality::ElementType::Hex && b.count > 0;
    const auto* sj = b.find("scaled_jacobian");
    ASSERT_NE(sj, nullptr);
    std::printf("[cooper real CAD] as1-tu-203 plate: %zu hexes, min scaled Jacobian %.4f\n",
                b.count, sj->min);
    EXPECT_GE(sj->min, 0.3);
  }
  EXPECT_TRUE(hexes);
}

}  // namespace
}  // namespace cooperage::cooper
