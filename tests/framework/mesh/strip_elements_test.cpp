// One row of elements across a strip (framework/mesh/strip_elements.h): on
// thin polygons in the plane, checked against the polygon itself: the
// elements turn like the loop, cover its area exactly, use every loop edge
// once and every other edge twice, and do not depend on where the part is.
#include "framework/mesh/strip_elements.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

namespace cooperage::mesh {
namespace {

// A counter-clockwise ring: from (0, 0) along y = -w sin(pi x / L) to
// (L, 0) in `lower` edges, back along y = +w sin(pi x / L) in `upper`.
std::vector<Vec3> thin_ring(double length, double w, int lower, int upper) {
  std::vector<Vec3> ring;
  for (int k = 0; k < lower; ++k) {
    const double x = length * k / lower;
    ring.emplace_back(x, -w * std::sin(M_PI * x / length), 0.0);
  }
  for (int k = 0; k < upper; ++k) {
    const double x = length * (upper - k) / upper;
    ring.emplace_back(x, w * std::sin(M_PI * x / length), 0.0);
  }
  return ring;
}

double signed_area(const std::vector<Vec3>& x, const std::vector<int>& polygon) {
  double a = 0;
  for (size_t k = 0; k < polygon.size(); ++k) {
    const Vec3& p = x[static_cast<size_t>(polygon[k])];
    const Vec3& q = x[static_cast<size_t>(polygon[(k + 1) % polygon.size()])];
    a += 0.5 * (p.x() * q.y() - q.x() * p.y());
  }
  return a;
}

// The checks that follow from the polygon; returns the elements' area.
void expect_a_row(const std::vector<Vec3>& ring, const StripElements& e) {
  std::map<std::pair<int, int>, int> uses;
  double area = 0;
  const auto add = [&](const std::vector<int>& polygon) {
    const double a = signed_area(ring, polygon);
    EXPECT_GT(a, 0.0) << "an element turns against the loop";
    area += a;
    for (size_t k = 0; k < polygon.size(); ++k) {
      const int u = polygon[k], v = polygon[(k + 1) % polygon.size()];
      ++uses[{std::min(u, v), std::max(u, v)}];
    }
  };
  for (const Quad& q : e.quads) add({q[0], q[1], q[2], q[3]});
  for (const Tri& t : e.tris) add({t[0], t[1], t[2]});
  std::vector<int> all(ring.size());
  for (size_t k = 0; k < ring.size(); ++k) all[k] = static_cast<int>(k);
  EXPECT_NEAR(area, signed_area(ring, all), 1e-12);
  const int n = static_cast<int>(ring.size());
  for (const auto& [edge, count] : uses) {
    const bool on_loop = edge.second - edge.first == 1 || (edge.first == 0 && edge.second == n - 1);
    EXPECT_EQ(count, on_loop ? 1 : 2) << edge.first << "-" << edge.second;
  }
  EXPECT_EQ(2 * e.quads.size() + e.tris.size() + 2, ring.size());  // no node inside
}

TEST(StripElements, EqualChainsGiveQuadsAndATriangleAtEachTip) {
  const std::vector<Vec3> ring = thin_ring(10.0, 0.2, 12, 12);
  const auto e = strip_elements(ring, 0, 12);
  ASSERT_TRUE(e.has_value());
  EXPECT_EQ(e->quads.size(), 10u);
  EXPECT_EQ(e->tris.size(), 2u);
  expect_a_row(ring, *e);
}

TEST(StripElements, UnequalChainsTakeUpTheDifferenceWithTriangles) {
  const std::vector<Vec3> ring = thin_ring(10.0, 0.2, 15, 9);
  const auto e = strip_elements(ring, 0, 15);
  ASSERT_TRUE(e.has_value());
  EXPECT_EQ(e->tris.size(), 2u + 6u);
  expect_a_row(ring, *e);
  // The extra triangles are spread along the row, not bunched at one end:
  // the zipper pairs nodes by arc-length fraction.
  std::vector<int> lone;  // the lower-chain edge of each middle triangle
  for (const Tri& t : e->tris) {
    if (t[0] == 0 || t[1] == 15 || t[0] == 15) continue;  // a tip
    lone.push_back(t[0]);
  }
  ASSERT_EQ(lone.size(), 6u);
  std::sort(lone.begin(), lone.end());
  EXPECT_LT(lone.front(), 4);
  EXPECT_GT(lone.back(), 10);
}

TEST(StripElements, TheTipsMayBeAnywhereInTheRing) {
  std::vector<Vec3> ring = thin_ring(10.0, 0.2, 12, 8);
  std::rotate(ring.begin(), ring.begin() + 5, ring.end());  // tip 0 now at 15, tip 1 at 7
  const auto e = strip_elements(ring, 7, 15);
  ASSERT_TRUE(e.has_value());
  expect_a_row(ring, *e);
}

TEST(StripElements, AMovedStripGivesTheSameElements) {
  const std::vector<Vec3> ring = thin_ring(10.0, 0.2, 14, 11);
  Eigen::Affine3d motion = Eigen::Translation3d(3e3, -7.5, 40.0) *
                           Eigen::AngleAxisd(1.1, Vec3(0.3, -0.5, 0.8).normalized());
  std::vector<Vec3> moved;
  for (const Vec3& p : ring) moved.push_back(motion * p);
  const auto a = strip_elements(ring, 0, 14);
  const auto b = strip_elements(moved, 0, 14);
  ASSERT_TRUE(a && b);
  EXPECT_EQ(a->quads, b->quads);
  EXPECT_EQ(a->tris, b->tris);
}

TEST(StripElements, AChainOfOneEdgeIsNoStrip) {
  const std::vector<Vec3> ring = thin_ring(10.0, 0.2, 1, 6);
  EXPECT_FALSE(strip_elements(ring, 0, 1).has_value());
  EXPECT_FALSE(strip_elements(ring, 0, 0).has_value());
  EXPECT_FALSE(strip_elements(ring, 0, 99).has_value());
}

}  // namespace
}  // namespace cooperage::mesh
