// The run's quality report takes cooper's per-element scaled Jacobians from
// its inversion check instead of computing them again (issue 20). The
// report must be the same, bit for bit, as the one computed from the mesh:
// the check's values are taken on exactly the coordinates the mesh ends up
// with, in the MeshDB's element order.
#include "framework/geometry/occ/workbench.h"
#include "framework/pipeline/mesher.h"
#include "framework/pipeline/quality_report.h"
#include "framework/quality/hex_metrics.h"
#include "framework/quality/wedge_metrics.h"
#include "must_mesh_parts.h"
#include "schemes/builtin_schemes.h"
#include "schemes/cooper/sweep_barrel.h"
#include "selector/select_schemes.h"

#include <gtest/gtest.h>

#include <cstring>

namespace cooperage::cooper {
namespace {

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

void expect_same_report(const pipeline::QualityReport& a, const pipeline::QualityReport& b,
                        const std::string& name) {
  ASSERT_EQ(a.blocks.size(), b.blocks.size()) << name;
  for (size_t k = 0; k < a.blocks.size(); ++k) {
    const auto* x = a.blocks[k].find("scaled_jacobian");
    const auto* y = b.blocks[k].find("scaled_jacobian");
    ASSERT_TRUE(x && y) << name;
    EXPECT_EQ(x->count, y->count) << name;
    EXPECT_TRUE(same_bits(x->min, y->min)) << name << " " << x->min << " " << y->min;
    EXPECT_TRUE(same_bits(x->mean, y->mean)) << name << " " << x->mean << " " << y->mean;
    EXPECT_TRUE(same_bits(x->max, y->max)) << name;
    EXPECT_TRUE(same_bits(x->median, y->median)) << name;
    EXPECT_EQ(x->histogram, y->histogram) << name;
    EXPECT_EQ(x->inverted, y->inverted) << name;
  }
}

struct Meshed {
  geom::Model model;
  pipeline::MeshResult run;
};

// Builds the part and meshes it as a run does (its report from cooper's
// values).
Meshed mesh_part(const parts::Build& build, double size,
                 const pipeline::MeshOptions& options = selector::mesh_options()) {
  occ::Workbench wb;
  build(wb);
  Meshed out;
  out.model = wb.build_model();
  scheme::Registry registry;
  register_builtin_schemes(registry);
  io::MeshSettings settings;
  settings.size = size;
  out.run = pipeline::mesh_model(out.model, settings, registry, options);
  return out;
}

// Compares the run's report with the one computed from the finished mesh.
void expect_carried_equals_recomputed(const std::string& name, const parts::Build& build,
                                      double size) {
  const Meshed m = mesh_part(build, size);
  ASSERT_GT(m.run.mesh.hex_count() + m.run.mesh.wedge_count(), 0u) << name;
  expect_same_report(m.run.quality, pipeline::assess_quality(m.run.mesh, m.model, {}), name);
}

TEST(CooperQualityCarried, ReportFromTheCheckEqualsTheRecomputedOne) {
  expect_carried_equals_recomputed("plate_three_round_holes", parts::plate_three_round_holes, 0.3);
  for (const auto& [name, build] : parts::all())
    expect_carried_equals_recomputed(name, build, 0.25);
}

// The values come from the sweep's check: one per hex, then per wedge, each
// the metric of that element on the points handed back.
TEST(CooperQualityCarried, SweepHandsBackEveryElementsValue) {
  SweepInput in;  // a 2 x 1 cap: one quad and two triangles, 3 layers, skewed
  in.layers = 3;
  in.boundary = 6;
  in.loop_starts = {0};
  in.source = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {0, 1, 0}};
  in.quads = {{0, 1, 4, 5}};
  in.tris = {{1, 2, 3}, {1, 3, 4}};
  in.cap_nodes = 6;
  for (int r = 0; r < 6; ++r) {
    for (int j = 0; j <= 3; ++j)
      in.ribs.push_back(in.source[static_cast<size_t>(r)] + Vec3(0.1 * j * j, 0, j));
  }
  const SweepResult r = sweep_barrel(in);
  ASSERT_TRUE(r.ok) << r.why;
  ASSERT_FALSE(r.smoothed);
  ASSERT_EQ(r.hexes.size(), 3u);
  ASSERT_EQ(r.wedges.size(), 6u);
  ASSERT_EQ(r.scaled_jacobian.size(), 9u);
  double worst = 1.0;
  for (size_t e = 0; e < 9; ++e) {
    double sj;
    if (e < 3) {
      quality::HexNodes h;
      for (size_t c = 0; c < 8; ++c) h[c] = r.points[static_cast<size_t>(r.hexes[e][c])];
      sj = quality::hex_scaled_jacobian(h);
    } else {
      quality::WedgeNodes w;
      for (size_t c = 0; c < 6; ++c) w[c] = r.points[static_cast<size_t>(r.wedges[e - 3][c])];
      sj = quality::wedge_scaled_jacobian(w);
    }
    EXPECT_TRUE(same_bits(sj, r.scaled_jacobian[e])) << "element " << e;
    worst = std::min(worst, sj);
  }
  EXPECT_LT(worst, 1.0);  // the skew makes the values differ from the ideal
  EXPECT_TRUE(same_bits(worst, r.min_scaled_jacobian));
}

// Known values are taken only when there is one per element.
TEST(CooperQualityCarried, KnownValuesAreTakenOnlyWhenComplete) {
  const Meshed m = mesh_part(parts::blind_hole, 0.3);
  const geom::Model& model = m.model;
  const pipeline::MeshResult& run = m.run;
  const int id = run.mesh.volumes().begin()->first;
  const size_t hexes = run.mesh.volume(id).hexes.size();
  ASSERT_GT(hexes, 1u);
  pipeline::KnownScaledJacobians known;
  known.hexes[id].assign(hexes, 0.5);
  const auto taken = pipeline::assess_quality(run.mesh, model, {}, &known);
  EXPECT_EQ(taken.blocks.front().find("scaled_jacobian")->min, 0.5);
  known.hexes[id].pop_back();
  expect_same_report(pipeline::assess_quality(run.mesh, model, {}, &known),
                     pipeline::assess_quality(run.mesh, model, {}), "incomplete");
}

// A journal's checks are evaluated by the run's one report (MeshOptions::
// quality_checks), the scaled Jacobian taken from cooper: their outcomes
// are those of a report computed afresh from the finished mesh.
TEST(CooperQualityCarried, JournalChecksCountTheSameOnTheCarriedValues) {
  std::vector<io::QualityCheck> checks(3);
  checks[0].metric = "scaled_jacobian";
  checks[0].min = 0.97;  // some hexes of the holes' rings fall below
  checks[0].action = io::QualityCheck::Action::Fail;
  checks[1].metric = "scaled_jacobian";
  checks[1].min = 0.0;
  checks[2].metric = "skew";
  checks[2].max = 0.1;
  pipeline::MeshOptions options = selector::mesh_options();
  options.quality_checks = checks;
  const Meshed m = mesh_part(parts::plate_three_round_holes, 0.3, options);
  const geom::Model& model = m.model;
  const pipeline::MeshResult& run = m.run;
  const pipeline::QualityReport fresh = pipeline::assess_quality(run.mesh, model, checks);
  expect_same_report(run.quality, fresh, "with checks");
  ASSERT_EQ(run.quality.checks.size(), 3u);
  for (size_t c = 0; c < 3; ++c) {
    EXPECT_EQ(run.quality.checks[c].violations, fresh.checks[c].violations) << "check " << c;
    EXPECT_EQ(run.quality.checks[c].failed, fresh.checks[c].failed) << "check " << c;
  }
  EXPECT_GT(run.quality.checks[0].violations, 0u);  // the check has something to count
  EXPECT_TRUE(run.quality.failed());
  EXPECT_EQ(run.quality.checks[1].violations, 0u);
  ASSERT_EQ(run.quality.blocks.front().metrics.size(), 2u);  // scaled_jacobian, skew
}

}  // namespace
}  // namespace cooperage::cooper
