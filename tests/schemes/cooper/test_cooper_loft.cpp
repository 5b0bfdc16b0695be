// cooper on lofted solids: a twisted sweep (the sides are twisted ruled
// faces) and a loft between differently sized caps mesh with good elements;
// a tetrahedron is rejected with reasons and nothing is meshed.
#include "support/mesh_checks.h"

#include "framework/core/error.h"
#include "framework/geometry/occ/workbench.h"
#include "framework/pipeline/mesher.h"
#include "schemes/builtin_schemes.h"
#include "selector/select_schemes.h"

#include <gtest/gtest.h>

#include <cmath>

namespace cooperage::cooper {
namespace {

using geom::Vec3;

const scheme::Registry& registry() {
  static const scheme::Registry& r = *[] {
    auto* reg = new scheme::Registry;  // lives for the whole test run
    register_builtin_schemes(*reg);
    return reg;
  }();
  return r;
}

io::MeshSettings cooper_pinned(double size) {
  io::MeshSettings s;
  s.size = size;
  s.finer_retries = 0;  // the scheme at this size, not a retry at a finer one
  io::VolumeSetting v;
  v.id = 1;
  v.scheme = "cooper";
  s.volumes.push_back(v);
  return s;
}

std::vector<Vec3> square(double half, double z, double turn_deg) {
  std::vector<Vec3> pts;
  const double t = turn_deg * M_PI / 180;
  for (auto [x, y] : {std::pair{-half, -half}, {half, -half}, {half, half}, {-half, half}}) {
    pts.push_back(Vec3(x * std::cos(t) - y * std::sin(t), x * std::sin(t) + y * std::cos(t), z));
  }
  return pts;
}

struct Measures {
  double min_sj = 1, volume = 0;
  size_t hexes = 0;
};

Measures measure(const mesh::MeshDB& db) {
  Measures m;
  for (const auto& [id, v] : db.volumes()) {
    for (const auto& h : v.hexes) {
      const auto p = testing::hex_points(db, h);
      m.min_sj = std::min(m.min_sj, testing::hex_scaled_jacobian(p));
      m.volume += testing::hex_volume(p);
      ++m.hexes;
    }
  }
  return m;
}

TEST(CooperLoft, TwistedSweepKeepsGoodElementsAndTheVolume) {
  // A unit square turned 60 degrees over a height of 3: twisted ruled sides.
  occ::Workbench bench;
  bench.loft("twist", {square(0.5, 0, 0), square(0.5, 3, 60)});
  const geom::Model model = bench.build_model();
  const auto r =
      pipeline::mesh_model(model, cooper_pinned(0.1), registry(), selector::mesh_options());
  EXPECT_EQ(r.plan.volumes.at(1).scheme, "cooper");
  const Measures m = measure(r.mesh);
  EXPECT_GT(m.min_sj, 0.5);
  // Ruled sides are bilinear patches, which trilinear hexes follow closely.
  EXPECT_NEAR(m.volume, model.volume(1).volume, 1e-3 * model.volume(1).volume);
  for (const auto& [fk, n] : testing::hex_face_counts(r.mesh)) ASSERT_LE(n, 2);
  EXPECT_EQ(testing::duplicate_node_pairs(r.mesh, 1e-9), 0);
}

TEST(CooperLoft, LoftBetweenDifferentlySizedCapsMeshes) {
  // A frustum of a square pyramid: caps 2 x 2 and 1 x 1, sloped sides.
  occ::Workbench bench;
  bench.loft("frustum", {square(1.0, 0, 0), square(0.5, 2, 0)});
  const geom::Model model = bench.build_model();
  const auto r =
      pipeline::mesh_model(model, cooper_pinned(0.1), registry(), selector::mesh_options());
  const Measures m = measure(r.mesh);
  EXPECT_GT(m.min_sj, 0.5);
  EXPECT_NEAR(m.volume, model.volume(1).volume, 1e-9 * model.volume(1).volume);
}

TEST(CooperLoft, TetrahedronIsRejectedWithReasonsAndNothingIsMeshed) {
  occ::Workbench bench;
  bench.loft("tet", {{Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0, 3, 0)}, {Vec3(0.5, 0.5, 4)}});
  const geom::Model model = bench.build_model();
  const scheme::Applicability a =
      registry().volume_scheme("cooper")->applicable(scheme::VolumeView{model, 1, nullptr});
  EXPECT_FALSE(a.ok);
  EXPECT_FALSE(a.why.empty());
  io::MeshSettings settings;
  settings.size = 0.5;
  try {
    pipeline::mesh_model(model, settings, registry(), selector::mesh_options());
    FAIL() << "a tetrahedron was meshed";
  } catch (const MeshingError& e) {
    EXPECT_EQ(e.code(), ErrorCode::NotApplicable);
    EXPECT_NE(std::string(e.what()).find("cooper:"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace cooperage::cooper
