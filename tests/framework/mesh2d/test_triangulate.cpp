#include <Eigen/Geometry>
#include <chrono>
#include <cstdio>

#include "framework/core/error.h"
#include "mesh2d_checks.h"

namespace cooperage::mesh2d::test {
namespace {

using V = Eigen::Vector2d;

// An 8 x 8 square: bottom spacing 1/8, top spacing 1, sides graded by 1.3.
std::vector<V> graded_square() {
  std::vector<double> ys{0.0};
  for (double h = 0.125; ys.back() + h < 8.0 - 0.4 * std::min(1.0, h * 1.3);) {
    ys.push_back(ys.back() + h);
    h = std::min(1.0, h * 1.3);
  }
  std::vector<V> loop;
  for (int i = 0; i < 64; ++i) loop.emplace_back(i * 0.125, 0.0);
  for (double y : ys) loop.emplace_back(8.0, y);
  for (int i = 0; i < 8; ++i) loop.emplace_back(8.0 - i, 8.0);
  loop.emplace_back(0.0, 8.0);
  for (size_t k = ys.size(); k-- > 1;) loop.emplace_back(0.0, ys[k]);
  return loop;
}

TEST(Mesh2dTriangulate, SquareQuality) {
  const Loops loops{subdivide({V(0, 0), V(10, 0), V(10, 10), V(0, 10)}, 1.0)};
  const Triangulation2D t = triangulate(loops);
  expect_valid(loops, t);
  EXPECT_GE(min_angle_deg(t), 25.0);
  EXPECT_GT(t.points.size(), loops[0].size());
  std::printf("[mesh2d] square: %zu triangles, min angle %.2f deg\n", t.triangles.size(),
              min_angle_deg(t));
}

TEST(Mesh2dTriangulate, CdtOnlyKeepsPoints) {
  const Loops loops{subdivide({V(0, 0), V(4, 0), V(4, 1), V(1, 1), V(1, 4), V(0, 4)}, 0.5)};
  RefineOptions opt;
  opt.refine = false;
  const Triangulation2D t = triangulate(loops, opt);
  expect_valid(loops, t);
  EXPECT_EQ(t.points.size(), loops[0].size());
}

TEST(Mesh2dTriangulate, LShapeAndAnnulus) {
  const Loops l{subdivide({V(0, 0), V(4, 0), V(4, 1), V(1, 1), V(1, 4), V(0, 4)}, 0.25)};
  const Triangulation2D tl = triangulate(l);
  expect_valid(l, tl);
  EXPECT_GE(min_angle_deg(tl), 25.0);
  const Loops ring{circle(V(0, 0), 5.0, 64, true), circle(V(0, 0), 2.0, 48, false)};
  const Triangulation2D tr = triangulate(ring);
  expect_valid(ring, tr);
  EXPECT_GE(min_angle_deg(tr), 25.0);
  std::printf("[mesh2d] L-shape min angle %.2f, annulus min angle %.2f\n", min_angle_deg(tl),
              min_angle_deg(tr));
}

TEST(Mesh2dTriangulate, GradedSpacing1To8) {
  const Loops loops{graded_square()};
  const Triangulation2D t = triangulate(loops);
  expect_valid(loops, t);
  EXPECT_GE(min_angle_deg(t), 25.0);
  std::printf("[mesh2d] graded 1:8: %zu triangles, min angle %.2f deg\n", t.triangles.size(),
              min_angle_deg(t));
}

TEST(Mesh2dTriangulate, RotatedInputSameConnectivity) {
  Loops loops{subdivide({V(0, 0), V(6, 0), V(6, 4), V(0, 4)}, 0.5), circle(V(2, 2), 1.0, 24, false),
              circle(V(4.5, 2), 0.6, 16, false)};
  const Eigen::Rotation2Dd rot(0.7);
  Loops moved = loops;
  for (auto& l : moved) {
    for (auto& p : l) p = rot * p + V(3.25, -1.5);
  }
  RefineOptions cdt_only;
  cdt_only.refine = false;
  ASSERT_EQ(triangulate(loops, cdt_only).triangles, triangulate(moved, cdt_only).triangles);
  const Triangulation2D t0 = triangulate(loops);
  const Triangulation2D t1 = triangulate(moved);
  ASSERT_EQ(t0.triangles, t1.triangles);
  ASSERT_EQ(t0.points.size(), t1.points.size());
  for (size_t i = 0; i < t0.points.size(); ++i) {
    EXPECT_LT((rot * t0.points[i] + V(3.25, -1.5) - t1.points[i]).norm(), 1e-9 * 6.0);
  }
}

TEST(Mesh2dTriangulate, RejectsBadInput) {
  EXPECT_THROW(triangulate({{V(0, 0), V(1, 0)}}), MeshingError);
  EXPECT_THROW(triangulate({{V(0, 0), V(0, 1), V(1, 0)}}), MeshingError);  // clockwise outer
  EXPECT_THROW(triangulate({{V(0, 0), V(1, 0), V(1, 0), V(0, 1)}}), MeshingError);
  // A hole that is counter-clockwise, and a hole outside the outer loop.
  const auto square = subdivide({V(0, 0), V(4, 0), V(4, 4), V(0, 4)}, 1.0);
  EXPECT_THROW(triangulate({square, circle(V(2, 2), 1.0, 12, true)}), MeshingError);
  EXPECT_THROW(triangulate({square, circle(V(8, 2), 1.0, 12, false)}), MeshingError);
  EXPECT_NO_THROW(triangulate({square, circle(V(2, 2), 1.0, 12, false)}));
  // A bow tie: segments cross.
  EXPECT_THROW(triangulate({{V(0, 0), V(2, 0), V(0, 1), V(2, 1.5)}}), MeshingError);
}

// Throughput (no assertion on time): squares refined to ~5k, ~50k, ~500k triangles.
TEST(Mesh2dTriangulate, Throughput) {
  for (const int n : {42, 135, 415}) {
    const Loops loops{subdivide({V(0, 0), V(1, 0), V(1, 1), V(0, 1)}, 1.0 / n)};
    const auto start = std::chrono::steady_clock::now();
    const Triangulation2D t = triangulate(loops);
    const double s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf(
        "[mesh2d] throughput: %zu triangles in %.3f s = %.0f triangles/s (min angle %.2f)\n",
        t.triangles.size(), s, static_cast<double>(t.triangles.size()) / s, min_angle_deg(t));
    EXPECT_GE(min_angle_deg(t), 25.0);
    if (n == 415) {
      EXPECT_GT(t.triangles.size(), 400000u);
    }
  }
}

}  // namespace
}  // namespace cooperage::mesh2d::test
