// The pipeline under hostile or careless input (issue 21; issue 16 items 4
// and 5): size estimates refuse runaway meshes before any node exists, the
// meshed volume is compared with the CAD's, export targets are checked first
// and exports are all or nothing, an assembly gets a verdict per volume.
#include "framework/core/error.h"
#include "framework/geometry/occ/workbench.h"
#include "framework/io/journal_reader.h"
#include "framework/pipeline/measure_check.h"
#include "framework/pipeline/mesh_size.h"
#include "framework/pipeline/mesher.h"
#include "schemes/builtin_schemes.h"
#include "selector/select_schemes.h"

#include <Eigen/Geometry>
#include "journal_fixture.h"
#include "plans_like_map.h"
#include "support/mesh_checks.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <unistd.h>

namespace cooperage::pipeline {
namespace {

namespace fs = std::filesystem;
using geom::Vec3;

class Reliability : public testing::JournalFixture {
 protected:
  std::vector<std::string> files() const {
    std::vector<std::string> out;
    for (const auto& e : fs::directory_iterator(dir_))
      if (e.path().filename() != "job.xml") out.push_back(e.path().filename().string());
    std::sort(out.begin(), out.end());
    return out;
  }
  // The MeshingError run_job throws (or "" when it runs).
  std::string run_error(const io::Job& job, const MeshOptions& options = selector::mesh_options()) {
    try {
      run_job(job, registry_, options);
    } catch (const MeshingError& e) {
      EXPECT_NE(e.code(), ErrorCode::Internal) << e.what();
      return e.what();
    }
    return "";
  }
};

// ---- element estimate ----------------------------------------------------------

TEST(MeshSize, TheEstimateIsExactForAMappedBrick) {
  occ::Workbench wb;
  wb.brick("b", Vec3::Zero(), Vec3(2, 3, 4));
  const geom::Model m = wb.build_model();
  io::MeshSettings s;
  s.size = 0.5;
  const MeshSizeEstimate e = estimate_mesh_size(m, interval_goals(m, s), 3);
  // 4 x 6 x 8 = 192 hexes and 2 (4*6 + 4*8 + 6*8) = 208 quads.
  EXPECT_NEAR(e.elements, 192 + 208, 1e-6);
  EXPECT_EQ(e.largest.dim, 3);
  EXPECT_NEAR(e.largest_elements, 192, 1e-6);
}

TEST_F(Reliability, ATinySizeIsRefusedWithTheEstimateBeforeMeshing) {
  // The issue's case: size 1e-3 on a 40 mm part ran until killed.
  const io::Job job =
      journal(R"(  <geometry><brick name="b" origin="0 0 0" size="40 40 40"/></geometry>
  <mesh size="1e-3"/>
  <export file="out.exo"/>
)");
  const auto t0 = std::chrono::steady_clock::now();
  const std::string msg = run_error(job);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 10.0);
  EXPECT_NE(msg.find("the mesh would have about 6.4e+13 elements"), std::string::npos) << msg;
  EXPECT_NE(msg.find("GB; the limit is 2e+08"), std::string::npos) << msg;
  EXPECT_TRUE(files().empty());
}

TEST_F(Reliability, HardIntervalCountsThatOverflowAreRefused) {
  // The issue's case: 65,535 and 65,536 intervals on two curves of a brick
  // overflowed int in the map's TFI (a heap overflow under ASan).
  const io::Job job =
      journal(R"(  <geometry><brick name="b" origin="0 0 0" size="1 1 1"/></geometry>
  <mesh size="0.5"><curve id="1" intervals="65535"/><curve id="2" intervals="65536"/></mesh>
)");
  const std::string msg = run_error(job);
  EXPECT_NE(msg.find("the mesh would have about"), std::string::npos) << msg;
}

TEST_F(Reliability, TheLimitIsAnOptionAndAJournalAttribute) {
  const std::string body = R"(  <geometry><brick name="b" origin="0 0 0" size="2 3 4"/></geometry>
  <mesh size="0.5" max_elements="300"/>
)";
  EXPECT_NE(run_error(journal(body)).find("the limit is 3e+02"), std::string::npos);
  MeshOptions options = selector::mesh_options();
  options.max_elements = 1000;  // the command line's --max-elements wins
  EXPECT_EQ(run_error(journal(body), options), "");
}

// ---- volumes against the CAD ---------------------------------------------------

TEST(MeasureCheck, ElementVolumesAreExact) {
  const std::array<Vec3, 8> cube{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0),
                                 Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(1, 1, 1), Vec3(0, 1, 1)};
  EXPECT_NEAR(hex_volume(cube), 1.0, 1e-14);
  // A twisted hex (top face turned): the trilinear volume is known in closed
  // form; here check against a fine midpoint sum of det J.
  std::array<Vec3, 8> twisted = cube;
  twisted[6] = Vec3(1.3, 1.2, 1.1);
  double reference = 0;
  const int n = 40;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        std::array<Vec3, 8> p = twisted;
        const double a = (i + 0.5) / n, b = (j + 0.5) / n, c = (k + 0.5) / n;
        const Vec3 du = (1 - b) * (1 - c) * (p[1] - p[0]) + b * (1 - c) * (p[2] - p[3]) +
                        (1 - b) * c * (p[5] - p[4]) + b * c * (p[6] - p[7]);
        const Vec3 dv = (1 - a) * (1 - c) * (p[3] - p[0]) + a * (1 - c) * (p[2] - p[1]) +
                        (1 - a) * c * (p[7] - p[4]) + a * c * (p[6] - p[5]);
        const Vec3 dw = (1 - a) * (1 - b) * (p[4] - p[0]) + a * (1 - b) * (p[5] - p[1]) +
                        a * b * (p[6] - p[2]) + (1 - a) * b * (p[7] - p[3]);
        reference += du.cross(dv).dot(dw) / (n * n * n);
      }
  EXPECT_NEAR(hex_volume(twisted), reference, 1e-4);
  // Randomly distorted hexes against the test support's independent
  // quadrature (Jacobian matrices from the shape function derivatives).
  std::mt19937 rng(20);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  for (int trial = 0; trial < 100; ++trial) {
    std::array<Vec3, 8> p = cube;
    for (Vec3& x : p) x += Vec3(jitter(rng), jitter(rng), jitter(rng));
    const double expected = cooperage::testing::hex_volume(p);
    EXPECT_NEAR(hex_volume(p), expected, 1e-12 * std::abs(expected) + 1e-15) << "trial " << trial;
  }
  const std::array<Vec3, 6> wedge{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0),
                                  Vec3(0, 0, 2), Vec3(1, 0, 2), Vec3(0, 1, 2)};
  EXPECT_NEAR(wedge_volume(wedge), 1.0, 1e-14);
  std::array<Vec3, 6> flipped = wedge;
  std::swap(flipped[1], flipped[2]);
  std::swap(flipped[4], flipped[5]);
  EXPECT_NEAR(wedge_volume(flipped), -1.0, 1e-14);
}

TEST_F(Reliability, CoarseRoundPartsPassTheVolumeCheck) {
  // A rod of radius 5 at size 5: its circles get few intervals, so its mesh
  // is a prism of 6 to 8 sides, up to 17 % short of the CAD's volume. The
  // faceting credit must account for that, and only for that.
  for (const char* size : {"5", "2.5", "1"}) {
    const io::Job job = journal(
        std::string(
            R"(  <geometry><cylinder name="rod" base="0 0 0" axis="0 0 1" radius="5" height="20"/></geometry>
  <mesh size=")") +
        size + "\"/>\n");
    const RunResult r = run_job(job, registry_, selector::mesh_options());
    ASSERT_EQ(r.mesh.measures.size(), 1u);
    const MeasureCheck& m = r.mesh.measures.front();
    EXPECT_LT(m.deviation(), 0.01) << "size " << size << ": mesh " << m.mesh << " + faceting "
                                   << m.faceting << " against " << m.cad;
    EXPECT_LT(m.mesh, m.cad) << "the facets lie inside the cylinder";
    EXPECT_FALSE(r.failed());
    // Not failed, but the person hears how much of the rod is missing when
    // it is more than 1 % (issue 16 item 4), and only then.
    const double raw = (m.cad - m.mesh) / m.cad;
    bool warned = false;
    for (const auto& w : r.mesh.warnings)
      warned = warned || w.message.find("below the CAD's") != std::string::npos;
    EXPECT_EQ(warned, raw > 0.01) << "size " << size << ": " << 100 * raw << " % short";
  }
}

TEST_F(Reliability, AWrongMeshFailsTheVolumeCheckNamingTheVolume) {
  // The check on its own: a brick mesh with every node pulled towards the
  // origin by 10 % covers 73 % of the CAD's volume.
  occ::Workbench wb;
  wb.brick("b", Vec3::Zero(), Vec3(2, 3, 4));
  const geom::Model m = wb.build_model();
  io::MeshSettings s;
  s.size = 1;
  MeshResult r = mesh_model(m, s, registry_, selector::mesh_options());
  ASSERT_EQ(r.measures.size(), 1u);
  EXPECT_LT(r.measures.front().deviation(), 1e-9);
  mesh::MeshDB shrunk = r.mesh;
  for (size_t i = 0; i < shrunk.node_count(); ++i) shrunk.mutable_node(static_cast<int>(i)) *= 0.9;
  const auto checks = compare_measures(m, shrunk);
  ASSERT_EQ(checks.size(), 1u);
  EXPECT_EQ(checks.front().entity.name(), "volume 1");
  EXPECT_NEAR(checks.front().deviation(), 1 - 0.729, 1e-9);
}

TEST_F(Reliability, ASurfaceMeshIsComparedByArea) {
  // A plate with a round hole meshed as surfaces: chords of the hole and
  // facets of the cylinder wall are credited; the result is within 1 %.
  const io::Job job = journal(R"(  <geometry>
    <brick name="b" origin="0 0 0" size="10 6 1"/>
    <cylinder name="h" base="5 3 -1" axis="0 0 1" radius="1.5" height="3"/>
    <cut name="p" inputs="b h"/>
  </geometry>
  <mesh size="0.8"/>
)");
  MeshOptions options = selector::mesh_options(2);
  const RunResult r = run_job(job, registry_, options);
  ASSERT_FALSE(r.mesh.measures.empty());
  for (const MeasureCheck& m : r.mesh.measures) {
    EXPECT_EQ(m.entity.dim, 2);
    EXPECT_LT(m.deviation(), 0.01)
        << m.entity.name() << ": " << m.mesh << " + " << m.faceting << " against " << m.cad;
  }
}

TEST_F(Reliability, CoarseFacetsOfADoublyCurvedFaceAreCreditedAndAWrongOneIsNot) {
  // A ball's surface at coarse sizes: the facets' shortfall (3-8 %) is
  // credited to within 1 % (the earlier slope formula over-credited coarse
  // facets and failed good meshes of B-spline faces); the same mesh
  // shrunk by 10 % towards the centre (81 % of the area) is not excused,
  // because its nodes are off the surface. (Coarser still -- 20 triangles
  // at size 3 -- the credit leaves 5 % and the run fails its check.)
  for (const char* size : {"1.5", "1", "0.7"}) {
    const io::Job job =
        journal(std::string(R"(  <geometry><sphere name="s" center="0 0 0" radius="5"/></geometry>
  <mesh size=")") +
                size + "\"/>\n");
    const RunResult r = run_job(job, registry_, selector::mesh_options(2));
    ASSERT_FALSE(r.mesh.measures.empty()) << size;
    double mesh = 0, credited = 0, cad = 0;
    for (const MeasureCheck& m : r.mesh.measures) {
      mesh += m.mesh;
      credited += m.mesh + m.faceting;
      cad += m.cad;
    }
    EXPECT_NEAR(cad, 4 * M_PI * 25, 1e-6 * cad);
    EXPECT_LT(mesh, cad) << size;
    EXPECT_LT(std::abs(credited - cad) / cad, 0.01)
        << "size " << size << ": " << mesh << " credited to " << credited << " against " << cad;
    mesh::MeshDB shrunk = r.mesh.mesh;
    for (size_t i = 0; i < shrunk.node_count(); ++i)
      shrunk.mutable_node(static_cast<int>(i)) *= 0.9;
    for (const MeasureCheck& m : compare_measures(r.model, shrunk)) {
      EXPECT_GT(m.deviation(), 0.05) << "size " << size << ", " << m.entity.name();
    }
  }
}

// ---- exports -----------------------------------------------------------------------

TEST_F(Reliability, ExportTargetsAreCheckedBeforeTheGeometryIsBuilt) {
  const std::string body = R"(  <geometry><brick name="b" origin="0 0 0" size="1 1 1"/></geometry>
  <mesh size="0.5"/>
  <export file="good.vtu"/>
  <export file="missing/out.exo"/>
)";
  const std::string msg = run_error(journal(body));
  EXPECT_NE(msg.find("job.xml:5: <export>: the directory"), std::string::npos) << msg;
  EXPECT_NE(msg.find("does not exist"), std::string::npos) << msg;
  EXPECT_TRUE(files().empty()) << "the first export must not be written";
  fs::create_directories(dir_ / "out.exo");
  const std::string dir_msg =
      run_error(journal(R"(  <geometry><brick name="b" origin="0 0 0" size="1 1 1"/></geometry>
  <mesh size="0.5"/>
  <export file="a.vtu"/>
  <export file="out.exo"/>
)"));
  EXPECT_NE(dir_msg.find("job.xml:5: <export>:"), std::string::npos) << dir_msg;
  EXPECT_NE(dir_msg.find("is a directory"), std::string::npos) << dir_msg;
  EXPECT_EQ(files(), std::vector<std::string>{"out.exo"});
}

TEST_F(Reliability, TwoExportsOfOneFileAreRefused) {
  const std::string msg =
      run_error(journal(R"(  <geometry><brick name="b" origin="0 0 0" size="1 1 1"/></geometry>
  <mesh size="0.5"/>
  <export file="a.vtu"/>
  <export file="./a.vtu"/>
)"));
  EXPECT_NE(msg.find("job.xml:5: <export>: \"./a.vtu\" is the same file as the export at line 4"),
            std::string::npos)
      << msg;
}

TEST_F(Reliability, ThreadsAreCappedAtTheHardwareCount) {
  // The issue's case: threads="2147483647" ran out of memory in TBB.
  MeshOptions options = selector::mesh_options();
  options.threads = 1 << 30;
  const std::string body = R"(  <geometry><brick name="b" origin="0 0 0" size="1 1 1"/></geometry>
  <mesh size="0.5"/>
)";
  EXPECT_EQ(run_error(journal(body), options), "");
}

// A volume scheme that accepts what the volume map accepts and then fails
// while meshing, as cooper does on the parts of the plan => mesh campaign
// it cannot mesh yet.
class AcceptsThenFails final : public testing::PlansLikeMap {
 public:
  using PlansLikeMap::PlansLikeMap;
  std::string_view name() const override { return "accepts_then_fails"; }
  scheme::EntityMesh mesh(const scheme::VolumeView& view,
                          const scheme::Settings& /*settings*/) const override {
    throw MeshingError(ErrorCode::MeshingFailed, EntityRef::volume(view.volume_id),
                       "hex 3 of layer 0 is inverted");
  }
};

// A scheme that fails on a volume it accepted gives no advice of its own;
// the error then says what may help, with the size to try (half the
// volume's own) in the journal's words.
TEST_F(Reliability, AVolumeItsSchemeFailedOnSaysWhatSizeToTry) {
  registry_.add(std::make_unique<AcceptsThenFails>(*registry_.volume_scheme("map")));
  try {
    run_job(journal(R"(  <geometry><brick name="b" origin="0 0 0" size="4 4 4"/></geometry>
  <mesh size="1" finer_retries="0"><volume id="1" size="0.8" scheme="accepts_then_fails"/></mesh>
  <export file="out.vtu"/>
)"),
            registry_, selector::mesh_options());
    ADD_FAILURE() << "no error";
  } catch (const MeshingError& e) {
    EXPECT_NE(std::string(e.what()).find("hex 3 of layer 0 is inverted"), std::string::npos)
        << e.what();
    EXPECT_NE(e.hint().find("<volume id=\"1\" size=\"0.4\"/>"), std::string::npos) << e.hint();
  }
  EXPECT_TRUE(files().empty());
}

// ---- assemblies: a verdict per volume -----------------------------------------------

const char* kBrickAndPinnedCylinder = R"(  <geometry>
    <brick name="box" origin="0 0 0" size="2 2 2"/>
    <cylinder name="rod" base="10 0 0" axis="0 0 1" radius="1" height="2"/>
  </geometry>
  <mesh size="0.5"><volume id="2" scheme="map"/></mesh>
  <export file="out.vtu"/>
)";

TEST_F(Reliability, AnAssemblyReportsEveryVolumeAndWritesNothingByDefault) {
  try {
    run_job(journal(kBrickAndPinnedCylinder), registry_, selector::mesh_options());
    ADD_FAILURE() << "no error";
  } catch (const IncompleteMesh& e) {
    ASSERT_EQ(e.verdicts().size(), 2u);
    EXPECT_EQ(e.verdicts()[0].state, Verdict::State::Meshed);
    EXPECT_EQ(e.verdicts()[1].state, Verdict::State::Refused);
    EXPECT_EQ(std::string(e.what()).rfind("volume 2: ", 0), 0u) << e.what();
    EXPECT_NE(e.hint().find("1 of 2 volumes could not be meshed; --allow-partial writes the 1"),
              std::string::npos)
        << e.hint();
    // What to do about the refused volume follows the count.
    const std::string own = "; for volume 2: " + e.verdicts()[1].hint;
    EXPECT_FALSE(e.verdicts()[1].hint.empty());
    EXPECT_NE(e.hint().find(own), std::string::npos) << e.hint();
  }
  EXPECT_TRUE(files().empty());
}

TEST_F(Reliability, AllowPartialWritesTheVolumesThatMeshed) {
  MeshOptions options = selector::mesh_options();
  options.allow_partial = true;
  const RunResult r = run_job(journal(kBrickAndPinnedCylinder), registry_, options);
  EXPECT_TRUE(r.failed()) << "a partial run exits 1";
  ASSERT_EQ(r.written.size(), 1u);
  EXPECT_EQ(r.mesh.mesh.volumes().size(), 1u);
  EXPECT_EQ(r.mesh.mesh.volumes().begin()->first, 1);
  EXPECT_EQ(r.mesh.mesh.hex_count(), 64u);
  // Only the brick's nodes and surfaces are left: 5^3 nodes, 6 x 16 quads.
  EXPECT_EQ(r.mesh.mesh.node_count(), 125u);
  EXPECT_EQ(r.mesh.mesh.quad_count(), 96u);
}

}  // namespace
}  // namespace cooperage::pipeline
