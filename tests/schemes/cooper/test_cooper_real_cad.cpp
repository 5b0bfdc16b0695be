// Cooper on real CAD made by other people (../shared/real-cad, PROVENANCE.md
// there; never copied into the repository): volumes whose plan was accepted
// and whose meshing then failed (issue 15). Skipped, saying so, when the
// folder is absent.
#include "framework/pipeline/build_geometry.h"
#include "framework/pipeline/decomposed_geometry.h"
#include "framework/pipeline/model_job.h"
#include "framework/pipeline/mesher.h"
#include "schemes/builtin_schemes.h"
#include "selector/select_schemes.h"

#include "support/real_cad.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>
#include <set>
#include <cstdio>
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

// occt_bm2_ec_lever-A: its cylindrical wall (surface 4) meets the plane
// wall y = 0.12 (surface 6) tangentially at a cusp, and a slot wall runs
// 0.1 mm beside it; the plan was accepted and imprinting then failed
// ("barrel 2 ... subcap imprinting failed", then barrel 7 on the slivers).
// Now the plan refuses, naming the two faces, and meshing at D/40 reports
// the same reason.
TEST(CooperRealCad, LeverWithACuspIsRefusedAtPlanAndAtMesh) {
  const std::string path = real_cad("occt_bm2_ec_lever-A.stp");
  if (!fs::exists(path))
    GTEST_SKIP() << path << " is absent (the shared real-CAD folder is not here)";
  const geom::Model model = pipeline::load_any(path);
  ASSERT_EQ(model.volumes().size(), 1u);
  const std::string reason = "side surfaces 4 and 6 meet tangentially along curve 22";
  scheme::Registry registry;
  register_builtin_schemes(registry);
  const scheme::Applicability a =
      registry.volume_scheme("cooper")->applicable(scheme::VolumeView{model, 1, nullptr});
  EXPECT_FALSE(a.ok);
  EXPECT_NE(a.why.find(reason), std::string::npos) << a.why;
  io::MeshSettings settings;
  settings.size = model.box().diagonal() / 40.0;
  pipeline::MeshOptions options = selector::mesh_options();
  options.threads = 1;
  try {
    pipeline::mesh_model(model, settings, registry, options);
    FAIL() << "meshed the lever";
  } catch (const MeshingError& e) {
    EXPECT_NE(std::string(e.what()).find(reason), std::string::npos) << e.what();
  }
}

// pyocc_face_recognition_sample_part (issue 17's must-mesh list). Main at
// b8654cb cut it twice (x = 153, y = -20) and the piece holding the cusps
// the cut leaves at the pocket's fillets inverted a hex at sizes 6.5-10.5
// ("barrel 2 (sides 8, 9, 10, 11): hex 71 ..."). With the knife-edge
// refusal the decomposition cuts a third time (z = 185), and that piece (a
// 5 mm strip over an overhang) failed imprinting from 10 up while the
// strip's wall was graded differently on its two ends (see
// test_side_curves_along.cpp). Every size meshes now: all hex, min scaled
// Jacobian at least 0.2, the volume within 0.5 % of the CAD's.
TEST(CooperRealCad, PyoccFaceRecognitionMeshesAtEverySize) {
  const std::string path = real_cad("pyocc_face_recognition_sample_part.stp");
  if (!fs::exists(path))
    GTEST_SKIP() << path << " is absent (the shared real-CAD folder is not here)";
  scheme::Registry registry;
  register_builtin_schemes(registry);
  for (double size : {5.0, 7.0, 8.0, 9.0, 10.23, 12.0}) {
    // As `cooperage mesh F --size S`: the automatic decomposition first.
    pipeline::ModelJobOptions job_options;
    job_options.size = size;
    const io::Job job = pipeline::model_job(path, job_options);
    const geom::Model model =
        pipeline::build_decomposed_geometry(job, registry, selector::planner()).model;
    const io::MeshSettings& settings = *job.mesh;
    pipeline::MeshOptions options = selector::mesh_options();
    options.threads = 1;
    pipeline::MeshResult r;
    try {
      r = pipeline::mesh_model(model, settings, registry, options);
    } catch (const MeshingError& e) {
      ADD_FAILURE() << "size " << size << ": " << e.what();
      continue;
    }
    double cad = 0, mesh = 0;
    for (const auto& m : r.measures) {
      cad += m.cad;
      mesh += m.mesh;
    }
    EXPECT_NEAR(mesh, cad, 0.005 * cad) << "size " << size;
    EXPECT_NEAR(cad, 3063600.76, 1.0) << "size " << size;  // the pieces fill the part
    double worst = 1;
    size_t hexes = 0;
    for (const auto& b : r.quality.blocks) {
      if (b.dim != 3) continue;
      EXPECT_EQ(b.type, quality::ElementType::Hex) << "size " << size;
      const auto* sj = b.find("scaled_jacobian");
      ASSERT_NE(sj, nullptr);
      worst = std::min(worst, sj->min);
      hexes += b.count;
    }
    EXPECT_GT(hexes, 0u) << "size " << size;
    EXPECT_GE(worst, 0.2) << "size " << size;
    std::printf("[cooper real CAD] pyocc size %g: %zu hexes, min scaled Jacobian %.4f\n", size,
                hexes, worst);
  }
}

// gmsh_918_pump_carter_sup: a pump cover (one volume, 119 faces) swept in
// seven barrels down its bolt lugs' walls: blind holes from the top, three
// counterbored bores, a flange below, lugs with conical undersides. Its plan
// was accepted and its sweep inverted a hex at D/40 and D/80 (issue 15):
// the walls were spaced by their own size functions, so a ring of ribs lay
// 17 mm off the level of the blind holes' floors; a lug's top rim was
// spaced evenly while its foot ends on two levels, so its ribs ran 5 mm
// sideways; the imprinted nodes of a virtual cap next to a cone lay on its
// end's mean plane, below the cone. Then D/45 to D/75 still inverted a hex:
// a subcap meshed by the polygon mesher at a lower end (a lug's cone, the
// bottom face) was put back by the barrel's least-squares map alone, its
// nodes next to the boundary off the boundary's own positions (min corner
// sine -0.42 on a cone, -0.69 on the bottom at D/60). Now the boundary's
// residuals are carried inside: all hex, min scaled Jacobian at least 0.09
// from D/40 to D/100, the volume within 1 % of the CAD's.
TEST(CooperRealCad, PumpCoverMeshesFromD40ToD80) {
  const std::string path = real_cad("gmsh_918_pump_carter_sup.stp");
  if (!fs::exists(path))
    GTEST_SKIP() << path << " is absent (the shared real-CAD folder is not here)";
  scheme::Registry registry;
  register_builtin_schemes(registry);
  const geom::Model model = pipeline::load_any(path);
  for (double div : {40.0, 50.0, 60.0, 70.0, 80.0}) {
    io::MeshSettings settings;
    settings.size = model.box().diagonal() / div;
    pipeline::MeshOptions options = selector::mesh_options();
    options.threads = 1;
    pipeline::MeshResult r;
    try {
      r = pipeline::mesh_model(model, settings, registry, options);
    } catch (const MeshingError& e) {
      ADD_FAILURE() << "D/" << div << ": " << e.what();
      continue;
    }
    ASSERT_EQ(r.plan.volumes.count(1), 1u);
    EXPECT_EQ(r.plan.volumes.at(1).scheme, "cooper");
    double cad = 0, mesh = 0;
    for (const auto& m : r.measures) {
      cad += m.cad;
      mesh += m.mesh;
    }
    EXPECT_NEAR(mesh, cad, 0.01 * cad) << "D/" << div;
    size_t hexes = 0;
    for (const auto& b : r.quality.blocks) {
      if (b.dim != 3) continue;
      EXPECT_EQ(b.type, quality::ElementType::Hex) << "D/" << div;
      const auto* sj = b.find("scaled_jacobian");
      ASSERT_NE(sj, nullptr);
      EXPECT_GE(sj->min, 0.05) << "D/" << div;
      hexes += b.count;
      std::printf("[cooper real CAD] pump cover D/%g: %zu hexes, min scaled Jacobian %.4f\n", div,
                  b.count, sj->min);
    }
    EXPECT_GT(hexes, 0u) << "D/" << div;
  }
}

// gmsh_as1-tu-203 at D/40 as `cooperage mesh` runs it (decomposed into 20
// volumes). Bolt heads whose underside rim a bracket's edge splits into
// three curves were counted as imprinted by their own top (two samplings
// of one circle, 0.036 apart at radius 7.5), so two sweeps meshed the
// underside and the brackets' feet (volumes 10, 19) were refused; the
// plate's failure (a hex inverted where the nuts straddle the feet's
// edges) took volumes 7, 9, 16, 18 with it: 13 of 20 meshed. Now 19 do:
// only the plate is refused, because the feet's undersides (surfaces 103,
// 115) are imprinted by both sweeps, the bolt heads' outlines from above
// and the nuts' from below, which no choice of roles resolves. The
// volumes that mesh are all hex, conformal among themselves, within
// 0.5 % of their CAD volumes, with min scaled Jacobian at least 0.2.
TEST(CooperRealCad, AssemblyAs1MeshesEveryVolumeButThePlate) {
  const std::string path = real_cad("gmsh_as1-tu-203.stp");
  if (!fs::exists(path))
    GTEST_SKIP() << path << " is absent (the shared real-CAD folder is not here)";
  scheme::Registry registry;
  register_builtin_schemes(registry);
  pipeline::ModelJobOptions job_options;
  job_options.size = pipeline::load_any(path).box().diagonal() / 40;  // 263.7 / 40
  const io::Job job = pipeline::model_job(path, job_options);
  const geom::Model model =
      pipeline::build_decomposed_geometry(job, registry, selector::planner()).model;
  ASSERT_EQ(model.volumes().size(), 20u);
  pipeline::MeshOptions options = selector::mesh_options();
  options.allow_partial = true;
  options.threads = 1;
  const pipeline::MeshResult r = pipeline::mesh_model(model, *job.mesh, registry, options);
  int meshed = 0;
  for (const auto& v : r.verdicts) {
    if (v.entity.dim != 3) continue;
    const bool ok = v.state == pipeline::Verdict::State::Meshed;
    meshed += ok ? 1 : 0;
    if (!ok) {
      // The plate: the underside of a foot is imprinted by both sweeps.
      EXPECT_NE(v.reason.find("would be meshed by both"), std::string::npos) << v.reason;
      // What to do names the limit, not a cut (no cut resolves it).
      EXPECT_NE(v.hint.find("cannot yet take the imprints of two sweeps"), std::string::npos)
          << v.hint;
      EXPECT_EQ(model.volume(v.entity.id).shells.front().size(), 38u) << v.reason;
    }
  }
  EXPECT_EQ(meshed, 19);
  for (const auto& m : r.measures) {
    if (m.entity.dim == 3) {
      EXPECT_LT(m.deviation(), 0.005) << m.mesh << " vs " << m.cad;
    }
  }
  // The feet (16 surfaces each) have a bolt head's rim tangent to their
  // edge (the head centred 7.5 from x = 55): their top face has corners of
  // 0 degrees there, which bound a hex's quality, not the sweep (min SJ
  // 0.04 at D/40; --dim 2 gives 0.08 on that face). Positive there, at
  // least 0.2 everywhere else.
  double worst = 1, worst_foot = 1;
  size_t hexes = 0;
  for (const auto& b : r.quality.blocks) {
    if (b.dim != 3) continue;
    EXPECT_EQ(b.type, quality::ElementType::Hex);
    const auto* sj = b.find("scaled_jacobian");
    ASSERT_NE(sj, nullptr);
    const bool foot = model.volume(b.id).shells.front().size() == 16;
    (foot ? worst_foot : worst) = std::min(foot ? worst_foot : worst, sj->min);
    hexes += b.count;
  }
  EXPECT_GE(worst, 0.2);
  EXPECT_GT(worst_foot, 0.0);
  // Conformal: no hex face is used by more than two hexes, and a face used
  // by one lies on a surface, never inside the assembly.
  std::map<std::array<int, 4>, int> faces;
  static const int kSide[6][4] = {{0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6},
                                  {0, 4, 7, 3}, {0, 3, 2, 1}, {4, 5, 6, 7}};
  for (const auto& [id, v] : r.mesh.volumes()) {
    for (const auto& h : v.hexes) {
      for (const auto& f : kSide) {
        std::array<int, 4> key{h[f[0]], h[f[1]], h[f[2]], h[f[3]]};
        std::sort(key.begin(), key.end());
        ++faces[key];
      }
    }
  }
  std::set<std::array<int, 4>> on_surfaces;
  for (const auto& [id, s] : r.mesh.surfaces()) {
    for (auto q : s.quads) {
      std::sort(q.begin(), q.end());
      on_surfaces.insert(q);
    }
  }
  int inner_once = 0, thrice = 0;
  for (const auto& [key, n] : faces) {
    thrice += n > 2 ? 1 : 0;
    inner_once += n == 1 && !on_surfaces.count(key) ? 1 : 0;
  }
  EXPECT_EQ(thrice, 0);
  EXPECT_EQ(inner_once, 0);
  std::printf(
      "[cooper real CAD] as1-tu-203 D/40: %d of 20 volumes, %zu hexes, min SJ %.4f (feet %.4f)\n",
      meshed, hexes, worst, worst_foot);
}

}  // namespace
}  // namespace cooperage::cooper
