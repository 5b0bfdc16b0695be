// build_decomposed_geometry (decomposed_geometry.h): when the pipeline cuts,
// when it does not, and what it says instead.
#include "framework/pipeline/decomposed_geometry.h"

#include "framework/core/error.h"
#include "framework/io/journal_reader.h"
#include "framework/pipeline/mesher.h"
#include "schemes/builtin_schemes.h"
#include "selector/select_schemes.h"

#include "journal_fixture.h"
#include "support/mixed_mesh_check.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace cooperage::pipeline {
namespace {

namespace fs = std::filesystem;

// Blacker 1996, Fig. 3a: no volume scheme applies to it whole.
const char* kFig3a = R"(  <geometry>
    <brick name="block" origin="0 0 0" size="4 4 2"/>
    <brick name="up" origin="1 0.5 2" size="1 1 1"/>
    <brick name="out" origin="4 2.5 0.5" size="1 1 1"/>
    <fuse name="part" inputs="block up out"/>
  </geometry>
)";

class DecomposedGeometry : public testing::JournalFixture {};

TEST_F(DecomposedGeometry, AMeshableModelIsNotCut) {
  const io::Job job =
      journal(R"(  <geometry><brick name="b" origin="0 0 0" size="2 1 1"/></geometry>
  <mesh size="0.25"/>
)");
  const auto g = build_decomposed_geometry(job, registry_, selector::planner());
  EXPECT_TRUE(g.decomposition.volumes.empty());
  EXPECT_EQ(g.decomposition.origin, std::vector<int>{1});
  EXPECT_EQ(g.model.volumes().size(), 1u);
}

TEST_F(DecomposedGeometry, OffLeavesTheVolumeToThePlanner) {
  const io::Job job = journal(std::string(kFig3a) + "  <mesh size=\"0.25\" decompose=\"off\"/>\n");
  EXPECT_EQ(job.mesh->decompose, io::Decompose::Off);
  const auto g = build_decomposed_geometry(job, registry_, selector::planner());
  EXPECT_TRUE(g.decomposition.volumes.empty());
  EXPECT_EQ(g.model.volumes().size(), 1u);
  EXPECT_THROW(selector::select_schemes(g.model, registry_, *job.mesh), MeshingError);
}

TEST_F(DecomposedGeometry, SurfaceMeshesAreNotDecomposed) {
  const io::Job job = journal(std::string(kFig3a) + "  <mesh size=\"0.25\"/>\n");
  const auto g = build_decomposed_geometry(job, registry_, selector::planner(), /*dim=*/2);
  EXPECT_TRUE(g.decomposition.volumes.empty());
  EXPECT_EQ(g.model.volumes().size(), 1u);
}

TEST_F(DecomposedGeometry, PerEntitySettingsStopItNamingTheSetting) {
  const io::Job job = journal(std::string(kFig3a) + R"(  <mesh size="0.25">
    <surface id="1" size="0.2"/>
  </mesh>
)");
  try {
    build_decomposed_geometry(job, registry_, selector::planner());
    FAIL() << "expected a refusal";
  } catch (const MeshingError& e) {
    EXPECT_EQ(e.code(), ErrorCode::NotApplicable);
    EXPECT_EQ(e.entity().id, 1);
    const std::string what = e.what();
    EXPECT_NE(what.find("job.xml:"), std::string::npos) << what;
    EXPECT_NE(what.find("<surface>"), std::string::npos) << what;
    EXPECT_NE(what.find("<webcut>"), std::string::npos) << what;
  }
}

// An element kind for every volume (<mesh elements>, `mesh --elements`)
// names no id: the volume is cut as in hexes, the pieces are planned and
// meshed in that kind, and the mesh fills the solid (4 x 4 x 2 and two unit
// bosses: 34). Given per volume id (<volume id="1" elements>), as the
// command line did, it stopped the decomposition.
TEST_F(DecomposedGeometry, AnElementKindForEveryVolumeIsThePiecesKind) {
  for (const char* kind : {"wedge", "mixed"}) {
    const io::Job job =
        journal(std::string(kFig3a) + "  <mesh size=\"0.25\" elements=\"" + kind + "\"/>\n");
    const auto g = build_decomposed_geometry(job, registry_, selector::planner());
    ASSERT_EQ(g.decomposition.volumes.size(), 1u) << kind;
    ASSERT_GE(g.model.volumes().size(), 2u) << kind;
    const MeshResult r = mesh_model(g.model, *job.mesh, registry_, selector::mesh_options());
    const cooperage::testing::MixedMeshSummary m =
        cooperage::testing::check_mixed_mesh(g.model, r.mesh);
    EXPECT_NEAR(m.volume, 34.0, 34.0 * 1e-9) << kind;
    if (std::string(kind) == "wedge") {
      EXPECT_EQ(m.hexes, 0u);
      EXPECT_GT(m.wedges, 0u);
    } else {
      EXPECT_GT(m.hexes, 0u);
    }
  }
}

TEST_F(DecomposedGeometry, APinnedSchemeIsLeftToThePlannerToRefuse) {
  const io::Job job = journal(std::string(kFig3a) + R"(  <mesh size="0.25">
    <volume id="1" scheme="cooper"/>
  </mesh>
)");
  const auto g = build_decomposed_geometry(job, registry_, selector::planner());
  EXPECT_TRUE(g.decomposition.volumes.empty());
  try {
    selector::select_schemes(g.model, registry_, *job.mesh);
    FAIL() << "expected the pin to be refused";
  } catch (const MeshingError& e) {
    EXPECT_NE(std::string(e.what()).find("pinned at"), std::string::npos) << e.what();
  }
}

TEST_F(DecomposedGeometry, AJournalsWebcutIsKept) {
  const io::Job job =
      journal(std::string(kFig3a).replace(
                  std::string(kFig3a).find("  </geometry>"), 0,
                  "    <webcut shape=\"part\" origin=\"0 2 0\" normal=\"0 1 0\"/>\n") +
              "  <mesh size=\"0.25\"/>\n");
  const auto g = build_decomposed_geometry(job, registry_, selector::planner());
  EXPECT_TRUE(g.decomposition.volumes.empty());
  EXPECT_EQ(g.model.volumes().size(), 2u);
}

TEST_F(DecomposedGeometry, WithoutASizeThicknessIsMeasuredAgainstAFortiethOfTheDiagonal) {
  const io::Job job = journal(std::string(kFig3a));
  const geom::Model m =
      build_decomposed_geometry(journal(std::string(kFig3a) + "  <mesh decompose=\"off\"/>\n"),
                                registry_, selector::planner())
          .model;
  io::MeshSettings none;
  EXPECT_NEAR(decomposition_size(none, m), m.box().diagonal() / 40.0, 1e-12);
  io::MeshSettings sized;
  sized.size = 0.3;
  EXPECT_DOUBLE_EQ(decomposition_size(sized, m), 0.3);
  EXPECT_FALSE(job.mesh);
}

TEST_F(DecomposedGeometry, TheJournalReaderRejectsAnUnknownValue) {
  EXPECT_THROW(journal(std::string(kFig3a) + "  <mesh size=\"0.25\" decompose=\"yes\"/>\n"),
               MeshingError);
}

}  // namespace
}  // namespace cooperage::pipeline
