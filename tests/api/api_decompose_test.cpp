// cooperage::Options::decompose, ::finer_retries and ::min_scaled_jacobian:
// mesh_file() cuts a part no scheme takes whole (the paper's Fig. 3a: bosses
// that project in different directions) unless told not to, and reports the
// cuts; a floor on the scaled Jacobian is a failing quality check.
#include <cooperage/cooperage.h>

#include "framework/core/error.h"
#include "framework/geometry/occ/workbench.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <unistd.h>

namespace cooperage {
namespace {

namespace fs = std::filesystem;

// A 4 x 4 x 2 block with a boss on top of its front half and one on the
// +x face of its back half (volume 34), as a STEP file.
std::string fig3a_step() {
  occ::Workbench wb;
  wb.brick("block", {0, 0, 0}, {4, 4, 2});
  wb.brick("up", {1, 0.5, 2}, {1, 1, 1});
  wb.brick("out", {4, 2.5, 0.5}, {1, 1, 1});
  wb.fuse("part", {"block", "up", "out"});
  const fs::path path =
      fs::temp_directory_path() / ("cooperage-api-fig3a-" + std::to_string(::getpid()) + ".step");
  wb.write(path.string());
  return path.string();
}

TEST(ApiDecompose, APartNoSchemeTakesWholeIsCutByDefault) {
  const std::string step = fig3a_step();
  const Result r = mesh_file(step, 0.25);
  fs::remove(step);
  ASSERT_EQ(r.decomposition.volumes.size(), 1u);
  EXPECT_GE(r.decomposition.volumes.front().cuts.size(), 1u);
  EXPECT_GE(r.model.volumes().size(), 2u);
  double hexes = 0;
  for (const auto& v : r.model.volumes())
    hexes += static_cast<double>(r.mesh.volume(v.id).hexes.size());
  EXPECT_GT(hexes, 0);
}

// Options::elements is every volume's kind, so the pieces of the cut are
// wedges too (it used to be set per volume id, which stopped the cut).
TEST(ApiDecompose, ElementsAreThoseOfThePieces) {
  const std::string step = fig3a_step();
  Options o;
  o.elements = io::ElementKind::Wedge;
  const Result r = mesh_file(step, 0.25, o);
  fs::remove(step);
  ASSERT_EQ(r.decomposition.volumes.size(), 1u);
  ASSERT_GE(r.model.volumes().size(), 2u);
  for (const auto& v : r.model.volumes()) {
    EXPECT_TRUE(r.mesh.volume(v.id).hexes.empty()) << "volume " << v.id;
    EXPECT_FALSE(r.mesh.volume(v.id).wedges.empty()) << "volume " << v.id;
  }
}

TEST(ApiDecompose, OffRefusesThePartNamingTheVolume) {
  const std::string step = fig3a_step();
  Options o;
  o.decompose = io::Decompose::Off;
  try {
    mesh_file(step, 0.25, o);
    ADD_FAILURE() << "no error";
  } catch (const MeshingError& e) {
    EXPECT_EQ(e.code(), ErrorCode::NotApplicable) << e.what();
    EXPECT_NE(std::string(e.what()).find("volume 1"), std::string::npos) << e.what();
  }
  fs::remove(step);
}

TEST(ApiDecompose, FinerRetriesOutOfRangeIsAnInputError) {
  Options o;
  o.finer_retries = 5;
  try {
    mesh_file(std::string(COOPERAGE_SOURCE_DIR) + "/examples/part.step", 2.0, o);
    ADD_FAILURE() << "no error";
  } catch (const MeshingError& e) {
    EXPECT_EQ(e.code(), ErrorCode::InvalidInput);
    EXPECT_NE(std::string(e.what()).find("Options::finer_retries must be 0 to 4, got 5"),
              std::string::npos)
        << e.what();
  }
}

// examples/part.step at size 2 has hexes from 0.79 to 0.9999: a floor of
// 0 passes, one of 0.9999 fails the check (no retry asked); out of [-1, 1]
// is an input error naming the option.
TEST(ApiDecompose, MinScaledJacobianIsAFailingQualityCheck) {
  const std::string part = std::string(COOPERAGE_SOURCE_DIR) + "/examples/part.step";
  Options o;
  o.min_scaled_jacobian = 0.0;
  EXPECT_FALSE(mesh_file(part, 2.0, o).quality.failed());
  o.min_scaled_jacobian = 0.9999;
  o.finer_retries = 0;
  const Result strict = mesh_file(part, 2.0, o);
  EXPECT_TRUE(strict.quality.failed());
  ASSERT_EQ(strict.quality.checks.size(), 1u);
  EXPECT_GT(strict.quality.checks.front().violations, 0u);
  o.min_scaled_jacobian = 2.0;
  try {
    mesh_file(part, 2.0, o);
    ADD_FAILURE() << "no error";
  } catch (const MeshingError& e) {
    EXPECT_EQ(e.code(), ErrorCode::InvalidInput);
    EXPECT_NE(
        std::string(e.what()).find("Options::min_scaled_jacobian must be from -1 to 1, got 2"),
        std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace cooperage
