// Footprints that share part of an edge across a barrel (issue 15, the
// campaign's case 8110): the cooper plan refuses them, naming the curves,
// so that plan and mesh agree; decompose="auto" cuts the part into pieces
// that mesh, all-hex, conformal, filling the part's volume.
#include "support/hex_mesh_check.h"

#include "framework/core/error.h"
#include "framework/io/journal_reader.h"
#include "framework/pipeline/build_geometry.h"
#include "framework/pipeline/decomposed_geometry.h"
#include "framework/pipeline/mesher.h"
#include "schemes/builtin_schemes.h"
#include "selector/select_schemes.h"

#include <gtest/gtest.h>

#include <string>

namespace cooperage::cooper {
namespace {

const std::string kJournal =
    std::string(COOPERAGE_SOURCE_DIR) + "/tests/schemes/cooper/data/cooper_shared_edge_stretch.xml";

// The refusal: the two curves, at plan time and when meshing.
TEST(CooperSharedEdge, PlanAndMeshRefuseTheSameWay) {
  io::Job job = io::read_journal(kJournal);
  ASSERT_TRUE(job.mesh.has_value());
  job.mesh->decompose = io::Decompose::Off;
  const geom::Model model = pipeline::build_geometry(job);
  scheme::Registry registry;
  register_builtin_schemes(registry);
  std::string at_plan, at_mesh;
  try {
    selector::SelectOptions options;
    options.check_intervals = true;
    selector::select_schemes(model, registry, *job.mesh, options);
  } catch (const MeshingError& e) {
    at_plan = e.what();
  }
  try {
    pipeline::mesh_model(model, *job.mesh, registry, selector::mesh_options());
  } catch (const MeshingError& e) {
    at_mesh = e.what();
  }
  EXPECT_NE(at_plan.find("run on one line along the sweep over part of their length"),
            std::string::npos)
      << at_plan;
  EXPECT_NE(at_mesh.find("run on one line along the sweep over part of their length"),
            std::string::npos)
      << at_mesh;
  EXPECT_EQ(at_mesh.find("imprinting failed"), std::string::npos) << at_mesh;
}

TEST(CooperSharedEdge, AutomaticDecompositionMeshesIt) {
  const io::Job job = io::read_journal(kJournal);
  scheme::Registry registry;
  register_builtin_schemes(registry);
  const geom::Model model =
      pipeline::build_decomposed_geometry(job, registry, selector::planner()).model;
  EXPECT_GT(model.volumes().size(), 1u);  // cut
  const auto r = pipeline::mesh_model(model, *job.mesh, registry, selector::mesh_options());
  const auto s = testing::check_hex_mesh(model, r.mesh);  // conformal across the cuts
  EXPECT_NEAR(s.volume, 53.5, 53.5 * 1e-6);
  EXPECT_GE(s.min_sj, 0.3);
}

}  // namespace
}  // namespace cooperage::cooper
