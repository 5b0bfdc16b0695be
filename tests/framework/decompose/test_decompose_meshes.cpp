// Parts no single sweep covers, meshed all-hex from an element size alone
// through the whole pipeline (issue 17): the automatic decomposition cuts
// them, the pieces are imprinted and merged, and the mesh is checked for
// conformity, volume and quality against the geometry.
#include "framework/core/error.h"
#include "framework/io/journal_reader.h"
#include "framework/pipeline/mesher.h"
#include "schemes/builtin_schemes.h"
#include "selector/select_schemes.h"
#include "support/hex_mesh_check.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace cooperage::pipeline {
namespace {

namespace fs = std::filesystem;

io::Job example(const std::string& name) {
  io::Job job = io::read_journal(std::string(COOPERAGE_SOURCE_DIR) + "/examples/" + name);
  job.exports.clear();  // the tests write nothing
  return job;
}

io::Job test_journal(const std::string& name) {
  io::Job job = io::read_journal(std::string(COOPERAGE_TEST_DATA_DIR) + "/" + name);
  job.exports.clear();
  return job;
}

struct Meshed {
  RunResult run;
  testing::HexMeshSummary summary;
  double cad_volume = 0;
};

Meshed mesh_job(const io::Job& job, int threads = 0) {
  scheme::Registry registry;
  register_builtin_schemes(registry);
  Meshed m{run_job(job, registry, selector::mesh_options(3, threads)), {}, 0};
  m.summary = testing::check_hex_mesh(m.run.model, m.run.mesh.mesh);
  for (const auto& v : m.run.model.volumes()) m.cad_volume += v.volume;
  return m;
}

// Issue 17: all hex, min scaled Jacobian >= 0.3, volume within 1 %,
// conformal (check_hex_mesh), and cut at least once.
void expect_good(const Meshed& m, const std::string& what, double exact_volume = 0) {
  if (exact_volume > 0) {
    EXPECT_NEAR(m.cad_volume, exact_volume, 1e-6 * exact_volume) << what;
  }
  EXPECT_EQ(m.run.mesh.mesh.wedge_count(), 0u) << what;
  EXPECT_GT(m.summary.hexes, 0u) << what;
  EXPECT_GE(m.summary.min_sj, 0.3) << what;
  EXPECT_NEAR(m.summary.volume, m.cad_volume, 0.01 * m.cad_volume) << what;
  EXPECT_FALSE(m.run.decomposition.volumes.empty()) << what << " was not cut";
  EXPECT_GE(m.run.model.volumes().size(), 2u) << what;
}

TEST(DecomposeMeshes, Fig3aFromItsSizeAlone) {
  const Meshed m = mesh_job(example("fig3a_auto.xml"));
  expect_good(m, "fig3a_auto.xml", 34.0);
}

TEST(DecomposeMeshes, AnLBracketWithHolesInBothLegs) {
  const Meshed m = mesh_job(example("bracket_holes.xml"));
  expect_good(m, "bracket_holes.xml", 40.0 - 2.0 * M_PI * 0.36);
}

// A tilted ring torus: cut along a meridian plane through its own axis
// (fitted to the face, surface_fit.h), the halves sweep round it.
TEST(DecomposeMeshes, ARingTorusIsCutThroughItsAxis) {
  const Meshed m = mesh_job(test_journal("decompose/ring_torus.xml"));
  expect_good(m, "ring_torus.xml", 2 * M_PI * M_PI * 3.0);
  ASSERT_EQ(m.run.decomposition.volumes.size(), 1u);
  const auto& cuts = m.run.decomposition.volumes[0].cuts;
  ASSERT_EQ(cuts.size(), 1u);
  EXPECT_EQ(cuts[0].through, "plane through the axis of surface 1");
  // The plane holds the torus's axis: its centre and its direction.
  const geom::Vec3 centre(1, -2, 0.5), axis = geom::Vec3(0.2, 0.4, 1).normalized();
  EXPECT_NEAR(cuts[0].surface.direction.dot(axis), 0.0, 1e-9);
  EXPECT_NEAR(cuts[0].surface.direction.dot(centre - cuts[0].surface.origin), 0.0, 1e-9);
}

// Known limit (issue 17 report): every arm of the T sweeps from its boss
// towards the rest of the part, so each arm's many-to-one target is the cut
// face it shares with the next piece. Cooper now meshes such a shared target
// itself when the neighbour takes it as a source cap (the neighbour waits),
// but here the cut face is a side of the trunk piece, which needs its
// structured (submap) mesh there: "surface N is meshed by volume A (cooper)
// itself, and volume B (cooper) needs submap on it". Until the search finds
// cuts whose shared faces are caps on both sides, the tee is refused --
// clearly, naming the cuts tried and the piece's reason. Turn this into
// expect_good() when it meshes.
TEST(DecomposeMeshes, ATeeWithBossesOnItsThreeArmsIsRefusedSayingWhy) {
  try {
    mesh_job(test_journal("decompose/tee_bosses.xml"));
    FAIL() << "the tee meshed: make this test expect_good() (issue 17's must-mesh list)";
  } catch (const MeshingError& e) {
    const std::string what = e.what();
    EXPECT_EQ(e.code(), ErrorCode::NotApplicable) << what;
    EXPECT_NE(what.find("automatic decomposition tried"), std::string::npos) << what;
    // The pieces' conflict in the part's terms: pieces, not the part's
    // volumes, and their shared face is the cut.
    EXPECT_NE(what.find("the cut face is meshed by piece"), std::string::npos) << what;
    EXPECT_NE(what.find("itself, and piece"), std::string::npos) << what;
  }
}

TEST(DecomposeMeshes, TheSameCutsForARotatedAndMovedPart) {
  // A rigid motion of Fig. 3a: the same cut (through the same face) and the
  // same number of hexes.
  io::Job job = example("fig3a_auto.xml");
  const Meshed a = mesh_job(job);
  const std::string text =
      "<cooperage version=\"1\"><geometry>"
      "<brick name=\"block\" origin=\"0 0 0\" size=\"4 4 2\"/>"
      "<brick name=\"up\" origin=\"1 0.5 2\" size=\"1 1 1\"/>"
      "<brick name=\"out\" origin=\"4 2.5 0.5\" size=\"1 1 1\"/>"
      "<fuse name=\"part\" inputs=\"block up out\"/>"
      "<rotate shape=\"part\" origin=\"1 2 3\" axis=\"1 2 -0.5\" angle=\"37\"/>"
      "<translate shape=\"part\" by=\"10 -3 7\"/>"
      "</geometry><mesh size=\"0.25\"/></cooperage>";
  const fs::path file =
      fs::temp_directory_path() / ("cooperage_fig3a_moved_" + std::to_string(::getpid()) + ".xml");
  std::ofstream(file) << text;
  const Meshed b = mesh_job(io::read_journal(file.string()));
  fs::remove(file);
  ASSERT_EQ(a.run.decomposition.volumes.size(), 1u);
  ASSERT_EQ(b.run.decomposition.volumes.size(), 1u);
  const auto& ca = a.run.decomposition.volumes[0].cuts;
  const auto& cb = b.run.decomposition.volumes[0].cuts;
  ASSERT_EQ(ca.size(), cb.size());
  for (size_t k = 0; k < ca.size(); ++k) EXPECT_EQ(ca[k].through, cb[k].through);
  EXPECT_EQ(a.summary.hexes, b.summary.hexes);
  EXPECT_GE(b.summary.min_sj, 0.3);
}

TEST(DecomposeMeshes, TheSameCutsAndMeshForAnyThreadCount) {
  const io::Job job = example("fig3a_auto.xml");
  const Meshed one = mesh_job(job, 1), two = mesh_job(job, 2);
  const auto& a = one.run.decomposition.volumes;
  const auto& b = two.run.decomposition.volumes;
  ASSERT_EQ(a.size(), b.size());
  for (size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k].tried, b[k].tried);
    ASSERT_EQ(a[k].cuts.size(), b[k].cuts.size());
    for (size_t c = 0; c < a[k].cuts.size(); ++c)
      EXPECT_EQ(a[k].cuts[c].through, b[k].cuts[c].through);
  }
  ASSERT_EQ(one.run.mesh.mesh.node_count(), two.run.mesh.mesh.node_count());
  for (size_t n = 0; n < one.run.mesh.mesh.node_count(); ++n) {
    const int i = static_cast<int>(n);
    ASSERT_EQ(one.run.mesh.mesh.node(i), two.run.mesh.mesh.node(i)) << "node " << n;
  }
}

TEST(DecomposeMeshes, OffRefusesThePartNamingTheSchemes) {
  io::Job job = example("fig3a_auto.xml");
  job.mesh->decompose = io::Decompose::Off;
  try {
    mesh_job(job);
    FAIL() << "expected a refusal";
  } catch (const MeshingError& e) {
    EXPECT_EQ(e.code(), ErrorCode::NotApplicable);
    EXPECT_EQ(e.entity().id, 1);
  }
}

TEST(DecomposeMeshes, APinnedWebcutIsRespectedAndNothingMoreIsCut) {
  const Meshed m = mesh_job(example("fig3a_webcut.xml"));
  EXPECT_TRUE(m.run.decomposition.volumes.empty());
  EXPECT_EQ(m.run.model.volumes().size(), 2u);
  EXPECT_GE(m.summary.min_sj, 0.3);
}

TEST(DecomposeMeshes, PerEntitySettingsStopTheDecompositionWithAReason) {
  io::Job job = example("fig3a_auto.xml");
  io::SurfaceSetting s;
  s.id = 1;
  s.sizing.size = 0.2;
  s.where = {"job.xml", 12, "surface"};
  job.mesh->surfaces.push_back(s);
  try {
    mesh_job(job);
    FAIL() << "expected a refusal";
  } catch (const MeshingError& e) {
    EXPECT_EQ(e.code(), ErrorCode::NotApplicable);
    EXPECT_NE(std::string(e.what()).find("job.xml:12"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace cooperage::pipeline
