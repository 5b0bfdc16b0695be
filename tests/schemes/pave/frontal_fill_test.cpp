// Tests of the frontal point placement (schemes/pave/frontal_fill.h) through
// constrained_delaunay: on a square whose loop spacing equals the size, rows
// of right triangles must fill the square exactly as the lattice of that
// spacing (an independent expectation: it is the only point set at spacing
// h whose triangles are all right isosceles with legs h), and graded sizes
// must follow the loops, not the rows.
#include "schemes/pave/cdt_2d.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <utility>

namespace cooperage::pave::detail {
namespace {

using V2 = Eigen::Vector2d;

CdtInput loop_input(const std::vector<V2>& pts, double size) {
  CdtInput in;
  std::vector<int> loop;
  for (const V2& p : pts) {
    loop.push_back(static_cast<int>(in.points.size()));
    in.points.push_back(p);
    in.sizes.push_back(size);
  }
  in.loops = {loop};
  in.frontal = true;
  return in;
}

std::vector<V2> square_loop(int per_side, double side) {
  std::vector<V2> pts;
  const V2 corners[4] = {{0, 0}, {side, 0}, {side, side}, {0, side}};
  for (int s = 0; s < 4; ++s) {
    for (int i = 0; i < per_side; ++i)
      pts.push_back(corners[s] + (corners[(s + 1) % 4] - corners[s]) * (double(i) / per_side));
  }
  return pts;
}

double area2(const V2& a, const V2& b, const V2& c) {
  return (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
}

TEST(PaveFrontalFill, SquareAtItsSpacingBecomesTheLattice) {
  for (int n : {4, 7, 12}) {
    SCOPED_TRACE(n);
    const double h = 1.0 / n;
    const Triangulation2D t = constrained_delaunay(loop_input(square_loop(n, 1.0), h));
    // Every point on the lattice of spacing h, each lattice point once.
    std::set<std::pair<long, long>> seen;
    for (const V2& p : t.points) {
      const double i = p.x() / h, j = p.y() / h;
      EXPECT_NEAR(i, std::round(i), 1e-9) << p.transpose();
      EXPECT_NEAR(j, std::round(j), 1e-9) << p.transpose();
      EXPECT_TRUE(seen.insert({std::lround(i), std::lround(j)}).second)
          << "duplicate " << p.transpose();
    }
    EXPECT_EQ(t.points.size(), static_cast<size_t>((n + 1) * (n + 1)));
    // Hence two right isosceles triangles per lattice cell.
    ASSERT_EQ(t.tris.size(), static_cast<size_t>(2 * n * n));
    for (const auto& tr : t.tris)
      EXPECT_NEAR(area2(t.points[tr[0]], t.points[tr[1]], t.points[tr[2]]), h * h, 1e-12);
  }
}

TEST(PaveFrontalFill, RotatedSquareGivesTheRotatedLattice) {
  const int n = 6;
  const double angle = 0.7, h = 1.0 / n;
  const Eigen::Rotation2Dd rot(angle);
  std::vector<V2> pts = square_loop(n, 1.0);
  for (V2& p : pts) p = rot * p + V2(3.0, -2.0);
  const Triangulation2D t = constrained_delaunay(loop_input(pts, h));
  EXPECT_EQ(t.points.size(), static_cast<size_t>((n + 1) * (n + 1)));
  for (const V2& p : t.points) {
    const V2 q = rot.inverse() * (p - V2(3.0, -2.0)) / h;
    EXPECT_NEAR(q.x(), std::round(q.x()), 1e-9);
    EXPECT_NEAR(q.y(), std::round(q.y()), 1e-9);
  }
}

TEST(PaveFrontalFill, SizesGradeBetweenLoopsInsteadOfFollowingTheRows) {
  // An 8 x 8 square at spacing 1 around a hole of radius 1 at spacing 1/8.
  CdtInput in = loop_input(square_loop(8, 8.0), 1.0);
  std::vector<int> hole;
  const int m = 50;
  for (int k = 0; k < m; ++k) {
    const double a = -2.0 * M_PI * k / m;  // clockwise
    hole.push_back(static_cast<int>(in.points.size()));
    in.points.push_back(V2(4.0 + std::cos(a), 4.0 + std::sin(a)));
    in.sizes.push_back(2.0 * M_PI / m);
  }
  in.loops.push_back(hole);
  const Triangulation2D t = constrained_delaunay(in);
  // Carrying the hole's size outward would put ~(8^2 - pi) / (h^2 / 2)
  // triangles at h = 0.126: ~7,000; a graded fill needs a few hundred.
  EXPECT_LT(t.tris.size(), 800u);
  double area = 0;
  for (const auto& tr : t.tris) {
    const double a = 0.5 * area2(t.points[tr[0]], t.points[tr[1]], t.points[tr[2]]);
    EXPECT_GT(a, 0);
    area += a;
  }
  const double polygon_hole = 0.5 * m * std::sin(2.0 * M_PI / m);
  EXPECT_NEAR(area, 64.0 - polygon_hole, 1e-9);
}

}  // namespace
}  // namespace cooperage::pave::detail
