// Carrying a boundary's residuals inside a cap mesh (Blacker 1996, sec.
// 6.1): a subcap meshed in its barrel's chart and put back onto its end by
// the least-squares map alone missed its own boundary where the end is no
// affine image of the chart, and the nodes next to the boundary folded over
// it (gmsh_918_pump_carter_sup, issue 15: a lug's cone and the bottom).
#include "schemes/cooper/residual_field.h"
#include "schemes/cooper/smooth_cap.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace cooperage::cooper {
namespace {

// An n x n grid of unit quads in z = 0 centred on the origin, boundary
// nodes first (counter-clockwise from a corner), then the interior.
struct ResidualGrid {
  static constexpr int n = 6;
  std::vector<Vec3> points;
  std::vector<mesh::Quad> quads;
  std::size_t boundary = 0;
  ResidualGrid() {
    std::vector<int> id((n + 1) * (n + 1), -1);
    auto at = [&](int i, int j) { return Vec3(i - n / 2.0, j - n / 2.0, 0.0); };
    auto take = [&](int i, int j) {
      int& k = id[static_cast<std::size_t>(j * (n + 1) + i)];
      if (k < 0) {
        k = static_cast<int>(points.size());
        points.push_back(at(i, j));
      }
    };
    for (int i = 0; i < n; ++i) take(i, 0);
    for (int j = 0; j < n; ++j) take(n, j);
    for (int i = n; i > 0; --i) take(i, n);
    for (int j = n; j > 0; --j) take(0, j);
    boundary = points.size();
    for (int j = 1; j < n; ++j)
      for (int i = 1; i < n; ++i) take(i, j);
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        auto v = [&](int a, int b) { return id[static_cast<std::size_t>(b * (n + 1) + a)]; };
        quads.push_back({v(i, j), v(i + 1, j), v(i + 1, j + 1), v(i, j + 1)});
      }
    }
  }
};

// The end the grid is put back onto: inclined (z rises with x, as on a
// cone's flank) and its top edge pushed in by up to 1.8 intervals in the
// middle, which no affine map explains.
Vec3 end_shape(const Vec3& x) {
  const double half = ResidualGrid::n / 2.0;
  const double push =
      x.y() > 0 ? 1.8 * (x.y() / half) * (1.0 - (x.x() / half) * (x.x() / half)) : 0;
  return Vec3(x.x(), x.y() - push, 0.4 * x.x());
}

TEST(ResidualField, BoundaryResidualsKeepTheNodesInsideTheirBoundary) {
  const ResidualGrid g;
  std::vector<Vec3> boundary_at;
  for (std::size_t k = 0; k < g.boundary; ++k) boundary_at.push_back(end_shape(g.points[k]));
  // The map alone (here the identity: the affine part is nil) leaves the
  // row under the pushed-in edge above it: those quads fold.
  std::vector<Vec3> map_only = g.points;
  for (std::size_t k = 0; k < g.boundary; ++k) map_only[k] = boundary_at[k];
  const double folded = min_quad_corner_quality(map_only, g.quads, Vec3::UnitZ());
  EXPECT_LT(folded, 0.0);
  const std::vector<Vec3> placed = with_boundary_residuals(g.points, g.points, boundary_at);
  ASSERT_EQ(placed.size(), g.points.size());
  for (std::size_t k = 0; k < g.boundary; ++k) EXPECT_EQ(placed[k], boundary_at[k]) << k;
  const double worst = min_quad_corner_quality(placed, g.quads, Vec3::UnitZ());
  EXPECT_GT(worst, 0.3);
  std::printf("[cooper residuals] pushed-in edge: min corner sine %.4f by the map, %.4f carried\n",
              folded, worst);
  // Every interior node follows the inclined end (within the span of z on
  // the boundary's nodes near it), not the chart's plane.
  for (std::size_t i = g.boundary; i < placed.size(); ++i) {
    EXPECT_NEAR(placed[i].z(), 0.4 * placed[i].x(), 0.5) << i;
  }
}

TEST(ResidualField, AMapThatExplainsTheBoundaryMovesNothing) {
  const ResidualGrid g;
  // A rotation and shift: the mapped boundary is the boundary itself.
  auto map = [](const Vec3& x) {
    return Vec3(0.8 * x.x() - 0.6 * x.y() + 2.0, 0.6 * x.x() + 0.8 * x.y(), x.z() - 1.0);
  };
  std::vector<Vec3> mapped, boundary_at;
  for (const Vec3& x : g.points) mapped.push_back(map(x));
  for (std::size_t k = 0; k < g.boundary; ++k) boundary_at.push_back(mapped[k]);
  const std::vector<Vec3> placed = with_boundary_residuals(g.points, mapped, boundary_at);
  for (std::size_t i = 0; i < placed.size(); ++i) EXPECT_EQ(placed[i], mapped[i]) << i;
}

// Several fields in one pass over the weights (the layers of a barrel,
// issue 20) and one field at a time (apply) both give the Shepard mean of
// the boundary values (weights 1 / distance^3, the header's definition),
// computed here directly.
TEST(ResidualField, SeveralFieldsAtOnceEqualOneAtATime) {
  const ResidualGrid g;
  const ResidualField field(g.points, g.boundary);
  const Eigen::Index b = static_cast<Eigen::Index>(g.boundary);
  Eigen::MatrixXd r(b, 6);
  for (Eigen::Index k = 0; k < b; ++k) {
    const Vec3& x = g.points[static_cast<std::size_t>(k)];
    r.row(k) << x.x() * x.y(), std::sin(x.x()), 0.3, x.y() * x.y(), -x.x(), std::cos(x.y());
  }
  auto shepard = [&](std::size_t i, Eigen::Index column) {
    double sum = 0, wsum = 0;
    for (Eigen::Index k = 0; k < b; ++k) {
      const double d = (g.points[i] - g.points[static_cast<std::size_t>(k)]).norm();
      const double w = 1.0 / (d * d * d);
      sum += w * r(k, column);
      wsum += w;
    }
    return sum / wsum;
  };
  const Eigen::MatrixXd inside = field.interior(r);
  ASSERT_EQ(inside.rows(), static_cast<Eigen::Index>(g.points.size() - g.boundary));
  ASSERT_EQ(inside.cols(), 6);
  for (int f = 0; f < 2; ++f) {
    std::vector<Vec3> boundary_r(g.boundary), out;
    for (Eigen::Index k = 0; k < b; ++k)
      boundary_r[static_cast<std::size_t>(k)] = r.block<1, 3>(k, 3 * f).transpose();
    field.apply(boundary_r, out);
    for (std::size_t k = 0; k < g.boundary; ++k) EXPECT_EQ(out[k], boundary_r[k]);
    for (std::size_t i = g.boundary; i < g.points.size(); ++i) {
      const Eigen::Index row = static_cast<Eigen::Index>(i - g.boundary);
      for (int d = 0; d < 3; ++d) {
        const double expected = shepard(i, 3 * f + d);
        EXPECT_NEAR(inside(row, 3 * f + d), expected, 1e-13) << i;
        EXPECT_NEAR(out[i][d], expected, 1e-13) << i;
      }
    }
  }
  // A constant residual is carried unchanged (the weights sum to one).
  for (Eigen::Index row = 0; row < inside.rows(); ++row) EXPECT_NEAR(inside(row, 2), 0.3, 1e-14);
}

}  // namespace
}  // namespace cooperage::cooper
