// Splitting poor quads into triangles: good quads are kept, a poor quad is
// split along the diagonal that keeps a sharp corner whole, halves of two
// poor quads that make a good quad are merged, and the split does not
// depend on where the mesh lies (rigid motion) or on its plane.
#include "framework/mesh/split_poor_quads.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

namespace cooperage::mesh {
namespace {

std::vector<Vec3> plane(const std::vector<std::pair<double, double>>& xy) {
  std::vector<Vec3> p;
  for (const auto& [x, y] : xy) p.emplace_back(x, y, 0.0);
  return p;
}

template <size_t N>
std::set<int> nodes(const std::array<int, N>& cell) {
  return {cell.begin(), cell.end()};
}

double signed_area(const std::vector<Vec3>& p, const int* c, int n) {
  double a = 0;
  for (int k = 0; k < n; ++k) {
    const Vec3& u = p[static_cast<size_t>(c[k])];
    const Vec3& v = p[static_cast<size_t>(c[(k + 1) % n])];
    a += 0.5 * (u.x() * v.y() - u.y() * v.x());
  }
  return a;
}

TEST(SplitPoorQuads, GoodQuadsAreKept) {
  const auto p = plane({{0, 0}, {1, 0}, {1, 1}, {0, 1}, {2, 0}, {2.2, 1.1}});
  const std::vector<Quad> quads{{0, 1, 2, 3}, {1, 4, 5, 2}};
  const QuadDominant m = split_poor_quads(p, quads, 0.5);
  EXPECT_EQ(m.quads, quads);
  EXPECT_TRUE(m.tris.empty());
  EXPECT_NEAR(min_corner_sine(p, quads[0].data(), 4, Vec3::UnitZ()), 1.0, 1e-12);
}

// A kite with a 20-degree corner at node 0: split along 1-3, so the
// triangle at the corner keeps its 20 degrees instead of two 10s.
TEST(SplitPoorQuads, SharpCornerIsNotHalved) {
  const double h = 2.0 * std::tan(10.0 * M_PI / 180.0);
  const auto p = plane({{0, 0}, {2, -h}, {2.6, 0}, {2, h}});
  const std::vector<Quad> quads{{0, 1, 2, 3}};
  ASSERT_LT(min_corner_sine(p, quads[0].data(), 4, Vec3::UnitZ()), 0.5);
  const QuadDominant m = split_poor_quads(p, quads, 0.5);
  EXPECT_TRUE(m.quads.empty());
  ASSERT_EQ(m.tris.size(), 2u);
  const int with_corner = std::count_if(m.tris.begin(), m.tris.end(),
                                        [](const Tri& t) { return nodes(t).count(0) == 1; });
  EXPECT_EQ(with_corner, 1);
  for (const Tri& t : m.tris) EXPECT_GT(signed_area(p, t.data(), 3), 0.0);  // as the quad
  const Tri& corner = nodes(m.tris[0]).count(0) ? m.tris[0] : m.tris[1];
  EXPECT_NEAR(min_corner_sine(p, corner.data(), 3, Vec3::UnitZ()), std::sin(20.0 * M_PI / 180.0),
              1e-9);
}

// Two poor quads A = 0 1 4 5 and B = 1 2 3 4, sharp at 5 and 3. Each is
// split away from its sharp corner; the halves next to their shared edge
// 1-4 make the good kite 0 1 2 4, which is kept as a quad.
const std::vector<std::pair<double, double>> kTwoPoor{{0, 0},     {1, -0.6}, {2, 0},
                                                      {3.5, 1.3}, {1, 1},    {-1.5, 1.3}};
const std::vector<Quad> kTwoPoorQuads{{0, 1, 4, 5}, {1, 2, 3, 4}};

TEST(SplitPoorQuads, HalvesOfTwoPoorQuadsMakingAGoodQuadAreMerged) {
  const auto p = plane(kTwoPoor);
  for (const Quad& q : kTwoPoorQuads)
    ASSERT_LT(min_corner_sine(p, q.data(), 4, Vec3::UnitZ()), 0.5);
  const QuadDominant m = split_poor_quads(p, kTwoPoorQuads, 0.5);
  ASSERT_EQ(m.quads.size(), 1u);
  EXPECT_EQ(nodes(m.quads[0]), (std::set<int>{0, 1, 2, 4}));
  EXPECT_GE(min_corner_sine(p, m.quads[0].data(), 4, Vec3::UnitZ()), 0.5);
  std::set<std::set<int>> tris;
  for (const Tri& t : m.tris) tris.insert(nodes(t));
  EXPECT_EQ(tris, (std::set<std::set<int>>{{0, 4, 5}, {2, 3, 4}}));
  // The same domain, every cell counter-clockwise.
  double before = 0, after = 0;
  for (const Quad& q : kTwoPoorQuads) before += signed_area(p, q.data(), 4);
  for (const Quad& q : m.quads) after += signed_area(p, q.data(), 4);
  for (const Tri& t : m.tris) {
    EXPECT_GT(signed_area(p, t.data(), 3), 0.0);
    after += signed_area(p, t.data(), 3);
  }
  EXPECT_NEAR(after, before, 1e-12);
}

TEST(SplitPoorQuads, RigidMotionOutOfThePlaneGivesTheSameElements) {
  const auto p = plane(kTwoPoor);
  const QuadDominant m0 = split_poor_quads(p, kTwoPoorQuads, 0.5);
  const Eigen::AngleAxisd rotation(1.234, Vec3(0.3, -0.8, 0.5).normalized());
  std::vector<Vec3> moved;
  for (const Vec3& x : p) moved.push_back(rotation * x + Vec3(4, -2, 7));
  const QuadDominant m1 = split_poor_quads(moved, kTwoPoorQuads, 0.5);
  EXPECT_EQ(m0.quads, m1.quads);
  EXPECT_EQ(m0.tris, m1.tris);
}

}  // namespace
}  // namespace cooperage::mesh
