// Real CAD parts made by other people (../shared/real-cad, PROVENANCE.md
// there) meshed by `cooperage mesh`'s job at D/40 (D the bounding-box
// diagonal): issue 17's list. Skipped, saying so, when the folder is absent.
#include "framework/pipeline/build_geometry.h"
#include "framework/pipeline/mesher.h"
#include "framework/pipeline/model_job.h"
#include "schemes/builtin_schemes.h"
#include "selector/select_schemes.h"
#include "support/hex_mesh_check.h"

#include "support/real_cad.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace cooperage::pipeline {
namespace {

namespace fs = std::filesystem;

using testing::real_cad;

class DecomposeRealCad : public ::testing::TestWithParam<const char*> {};

TEST_P(DecomposeRealCad, MeshesAllHexAtADiagonalOverForty) {
  const std::string path = real_cad(GetParam());
  if (!fs::exists(path))
    GTEST_SKIP() << path << " is absent (the shared real-CAD folder is not here)";
  const geom::Model part = load_any(path);
  const double size = part.box().diagonal() / 40.0;
  double exact = 0;
  for (const auto& v : part.volumes()) exact += v.volume;
  ModelJobOptions options;
  options.size = size;
  const io::Job job = model_job(path, options);
  scheme::Registry registry;
  register_builtin_schemes(registry);
  const RunResult r = run_job(job, registry, selector::mesh_options());
  const testing::HexMeshSummary s = testing::check_hex_mesh(r.model, r.mesh.mesh);
  double cad = 0;
  for (const auto& v : r.model.volumes()) cad += v.volume;
  EXPECT_EQ(r.mesh.mesh.wedge_count(), 0u);
  EXPECT_GE(s.min_sj, 0.3);
  EXPECT_NEAR(cad, exact, 1e-6 * exact);  // the pieces fill the part
  EXPECT_NEAR(s.volume, exact, 0.01 * exact);
  EXPECT_FALSE(r.decomposition.volumes.empty()) << "not cut";
  EXPECT_GE(r.model.volumes().size(), 2u);
}

INSTANTIATE_TEST_SUITE_P(Issue17, DecomposeRealCad,
                         // Not yet (bench/RESULTS.md, "Automatic decomposition"):
                         // gmsh_Angled.step (no cut leaves pieces cooper takes:
                         // faces with 18-40 degree corners cannot be sides) and
                         // occt_bm2_ec_lever-A.stp (cooper accepts it whole, then
                         // fails imprinting subcaps; nothing is left to cut);
                         // pyocc_face_recognition_sample_part.stp (cut in three
                         // pieces; it meshed before the interval goals became
                         // whole numbers, now a piece's barrel 2 gets an inverted
                         // hex after the least-squares projection: cooper's
                         // projection, not the cuts).
                         // occt_OCC2368.stp: a solid of revolution with a
                         // concave blend, cut along a meridian plane as the
                         // last resort; the halves sweep round the axis.
                         ::testing::Values("occt_xr1-tc-lbr.stp", "occt_OCC2368.stp"),
                         [](const ::testing::TestParamInfo<const char*>& param) {
                           std::string n = param.param;
                           for (char& c : n)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return n;
                         });

}  // namespace
}  // namespace cooperage::pipeline
