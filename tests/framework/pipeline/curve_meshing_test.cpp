// Curve meshing: spacing fractions by reasoning, nodes on the true curve at
// the requested arc lengths.
#include "framework/core/error.h"
#include "framework/geometry/occ/workbench.h"
#include "framework/mesh/curve_spacing.h"
#include "framework/pipeline/mesh_curves.h"

#include <gtest/gtest.h>

#include <cmath>

namespace cooperage::pipeline {
namespace {

using mesh::CurveSpacing;

TEST(CurveSpacing, UniformIsEvenlySpaced) {
  const auto s = mesh::spacing_fractions(4, 2.0, {});
  ASSERT_EQ(s.size(), 5u);
  for (int i = 0; i <= 4; ++i) EXPECT_DOUBLE_EQ(s[i], i / 4.0);
}

TEST(CurveSpacing, GeometricRatioGrowsIntervalsByTheRatio) {
  CurveSpacing sp;
  sp.kind = CurveSpacing::Kind::Geometric;
  sp.ratio = 2.0;
  const auto s = mesh::spacing_fractions(3, 7.0, sp);  // 1 + 2 + 4 = 7
  EXPECT_NEAR(s[1], 1.0 / 7, 1e-15);
  EXPECT_NEAR(s[2], 3.0 / 7, 1e-15);
  EXPECT_DOUBLE_EQ(s[3], 1.0);
  sp.reverse = true;
  const auto r = mesh::spacing_fractions(3, 7.0, sp);  // 4 + 2 + 1
  EXPECT_NEAR(r[1], 4.0 / 7, 1e-15);
  EXPECT_NEAR(r[2], 6.0 / 7, 1e-15);
}

TEST(CurveSpacing, FirstSizeDecidesTheRatio) {
  CurveSpacing sp;
  sp.kind = CurveSpacing::Kind::Geometric;
  sp.first_size = 1.0;
  const auto s = mesh::spacing_fractions(3, 7.0, sp);  // must find ratio 2
  EXPECT_NEAR(s[1] * 7.0, 1.0, 1e-9);
  EXPECT_NEAR((s[2] - s[1]) / s[1], 2.0, 1e-6);
}

TEST(CurveSpacing, DualBiasIsSymmetric) {
  CurveSpacing sp;
  sp.kind = CurveSpacing::Kind::Dual;
  sp.ratio = 1.5;
  const auto s = mesh::spacing_fractions(6, 1.0, sp);
  for (size_t i = 0; i < s.size(); ++i) EXPECT_NEAR(s[i], 1.0 - s[s.size() - 1 - i], 1e-14);
  EXPECT_NEAR((s[2] - s[1]) / s[1], 1.5, 1e-12);
}

TEST(CurveSpacing, ImpossibleRequestsAreErrors) {
  CurveSpacing sp;
  sp.kind = CurveSpacing::Kind::Geometric;
  sp.first_size = 10.0;  // longer than the curve
  EXPECT_THROW(mesh::spacing_fractions(3, 7.0, sp), MeshingError);
  EXPECT_THROW(mesh::spacing_fractions(0, 7.0, {}), MeshingError);
  sp.first_size.reset();
  sp.ratio = -1;
  EXPECT_THROW(mesh::spacing_fractions(3, 7.0, sp), MeshingError);
}

TEST(MeshCurves, NodesLieOnTheCircleAtEqualArcLengths) {
  occ::Workbench bench;
  bench.cylinder("c", {0, 0, 0}, {0, 0, 1}, 2.0, 1.0);
  const geom::Model model = bench.build_model();
  std::map<int, int> intervals;
  for (const auto& c : model.curves()) intervals[c.id] = 12;
  mesh::MeshDB db;
  mesh_curves(model, intervals, io::MeshSettings{}, db);
  for (const auto& c : model.curves()) {
    const auto& chain = db.curve_nodes(c.id);
    ASSERT_EQ(chain.size(), 13u);
    EXPECT_EQ(chain.front(), db.vertex_node(c.start_vertex));
    EXPECT_EQ(chain.back(), db.vertex_node(c.end_vertex));
    if (c.geometry->type() != geom::CurveType::Circle) continue;
    for (size_t i = 0; i + 1 < chain.size(); ++i) {
      const auto& a = db.node(chain[i]);
      const auto& b = db.node(chain[i + 1]);
      EXPECT_NEAR(std::hypot(a.x(), a.y()), 2.0, 1e-9);                  // on the circle
      EXPECT_NEAR((a - b).norm(), 2 * 2.0 * std::sin(M_PI / 12), 1e-7);  // equal chords
    }
  }
  // One node per vertex, n - 1 per curve: nothing duplicated.
  EXPECT_EQ(db.node_count(), model.vertices().size() + 11 * model.curves().size());
}

}  // namespace
}  // namespace cooperage::pipeline
