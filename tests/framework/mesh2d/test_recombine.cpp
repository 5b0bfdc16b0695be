// Recombination of triangulations into quad-dominant meshes: a valid mixed
// mesh (every interior edge used twice in opposite directions, boundary
// edges once, area kept), every quad above the threshold, triangles only
// where no good quad can be made, the same pairing for a rotated input.
#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <map>

#include "framework/mesh2d/recombine.h"
#include "mesh2d_checks.h"

namespace cooperage::mesh2d::test {
namespace {

using V = Eigen::Vector2d;

double area(const MixedMesh2D& m) {
  double a = 0.0;
  auto add = [&](const auto& cell) {
    for (size_t k = 0; k < cell.size(); ++k) {
      const V& p = m.points[static_cast<size_t>(cell[k])];
      const V& q = m.points[static_cast<size_t>(cell[(k + 1) % cell.size()])];
      a += 0.5 * (p.x() * q.y() - p.y() * q.x());
    }
  };
  for (const auto& q : m.quads) add(q);
  for (const auto& t : m.triangles) add(t);
  return a;
}

// Directed edge -> count; every interior edge has its twin, every boundary
// segment is used once, and the cells cover the domain.
void expect_valid_mixed(const Loops& loops, const MixedMesh2D& m) {
  std::map<std::pair<int, int>, int> directed;
  auto add = [&](const auto& cell) {
    for (size_t k = 0; k < cell.size(); ++k) {
      const std::pair<int, int> e{cell[k], cell[(k + 1) % cell.size()]};
      ASSERT_EQ(++directed[e], 1);
    }
  };
  for (const auto& q : m.quads) add(q);
  for (const auto& t : m.triangles) add(t);
  size_t nb = 0;
  std::map<std::pair<int, int>, int> boundary;
  for (const auto& l : loops) {
    for (size_t i = 0; i < l.size(); ++i) {
      boundary[{static_cast<int>(nb + i), static_cast<int>(nb + (i + 1) % l.size())}] = 1;
    }
    nb += l.size();
  }
  for (const auto& [e, n] : directed) {
    if (boundary.count(e)) continue;
    EXPECT_TRUE(directed.count({e.second, e.first})) << "edge " << e.first << "-" << e.second;
  }
  for (const auto& [e, n] : boundary) EXPECT_TRUE(directed.count(e)) << "boundary segment missing";
  EXPECT_NEAR(area(m), loops_area(loops), 1e-9 * loops_area(loops));
}

double worst_quad(const MixedMesh2D& m) {
  double w = 1.0;
  for (const auto& q : m.quads) {
    w = std::min(w, quad_quality(m.points[static_cast<size_t>(q[0])], m.points[static_cast<size_t>(q[1])],
                                 m.points[static_cast<size_t>(q[2])], m.points[static_cast<size_t>(q[3])]));
  }
  return w;
}

TEST(Mesh2dRecombine, QuadQualityOfReferenceShapes) {
  EXPECT_NEAR(quad_quality(V(0, 0), V(1, 0), V(1, 1), V(0, 1)), 1.0, 1e-15);
  // A rhombus of two equilateral triangles: sin 60.
  EXPECT_NEAR(quad_quality(V(0, 0), V(1, 0), V(1.5, std::sqrt(0.75)), V(0.5, std::sqrt(0.75))),
              std::sqrt(0.75), 1e-12);
  EXPECT_LT(quad_quality(V(0, 0), V(2, 0), V(0.5, 0.5), V(0, 2)), 0.0);  // reflex corner
  EXPECT_LT(quad_quality(V(0, 0), V(0, 1), V(1, 1), V(1, 0)), 0.0);      // clockwise
}

TEST(Mesh2dRecombine, SquareIsQuadDominant) {
  const Loops loops{subdivide({V(0, 0), V(10, 0), V(10, 10), V(0, 10)}, 0.5)};
  const Triangulation2D t = triangulate(loops);
  const MixedMesh2D m = recombine(t);
  expect_valid_mixed(loops, m);
  EXPECT_EQ(m.points.size(), t.points.size());
  EXPECT_EQ(2 * m.quads.size() + m.triangles.size(), t.triangles.size());
  EXPECT_GE(worst_quad(m), 0.5);
  const double fraction = static_cast<double>(m.triangles.size()) /
                          static_cast<double>(m.quads.size() + m.triangles.size());
  // Delaunay refinement makes near-equilateral triangles, not pairs made for
  // merging: about one cell in eight stays a triangle at the 0.5 bound.
  EXPECT_LT(fraction, 0.15);
  // Augmenting paths pair up triangles the greedy matching leaves apart.
  RecombineOptions greedy;
  greedy.max_path_quads = 0;
  const MixedMesh2D g = recombine(t, greedy);
  EXPECT_LT(2 * m.triangles.size(), g.triangles.size());
  std::printf("[mesh2d] recombine square: %zu quads, %zu triangles (greedy only: %zu), worst quad %.3f\n",
              m.quads.size(), m.triangles.size(), g.triangles.size(), worst_quad(m));
}

TEST(Mesh2dRecombine, NoTwoAdjacentTrianglesCouldMakeAGoodQuad) {
  const Loops loops{subdivide({V(0, 0), V(6, 0), V(6, 4), V(0, 4)}, 0.4), circle(V(2, 2), 1.0, 24, false)};
  const MixedMesh2D m = recombine(triangulate(loops));
  expect_valid_mixed(loops, m);
  std::map<std::pair<int, int>, int> apex;  // directed edge of a leftover triangle -> opposite node
  for (const auto& t : m.triangles) {
    for (int k = 0; k < 3; ++k) apex[{t[(k + 1) % 3], t[(k + 2) % 3]}] = t[k];
  }
  for (const auto& [e, c] : apex) {
    auto twin = apex.find({e.second, e.first});
    if (twin == apex.end()) continue;
    const double q = quad_quality(m.points[static_cast<size_t>(c)], m.points[static_cast<size_t>(e.first)],
                                  m.points[static_cast<size_t>(twin->second)],
                                  m.points[static_cast<size_t>(e.second)]);
    EXPECT_LT(q, 0.5) << "triangles across " << e.first << "-" << e.second << " make a good quad";
  }
}

// A 20-degree corner: any quad there has a 20-degree angle (quality
// sin 20 < 0.5), so the corner node lies in triangles only.
TEST(Mesh2dRecombine, SharpCornerStaysTriangular) {
  const double a = 20.0 * M_PI / 180.0;
  const V tip(0, 0);
  const Loops loops{subdivide({tip, V(6, 0), V(6 * std::cos(a), 6 * std::sin(a))}, 0.3)};
  const MixedMesh2D m = recombine(triangulate(loops));
  expect_valid_mixed(loops, m);
  EXPECT_GE(worst_quad(m), 0.5);
  for (const auto& q : m.quads) {
    for (int v : q) EXPECT_NE(v, 0) << "a quad at the 20-degree corner";
  }
  bool corner_in_triangle = false;
  for (const auto& t : m.triangles) corner_in_triangle = corner_in_triangle || t[0] == 0 || t[1] == 0 || t[2] == 0;
  EXPECT_TRUE(corner_in_triangle);
  EXPECT_GT(m.quads.size(), 4 * m.triangles.size());
  std::printf("[mesh2d] recombine 20-degree wedge: %zu quads, %zu triangles\n", m.quads.size(),
              m.triangles.size());
}

TEST(Mesh2dRecombine, RotatedInputSamePairing) {
  const Loops loops{subdivide({V(0, 0), V(6, 0), V(6, 4), V(0, 4)}, 0.5), circle(V(2, 2), 1.0, 24, false),
                    circle(V(4.5, 2), 0.6, 16, false)};
  const Eigen::Rotation2Dd rot(0.7);
  Loops moved = loops;
  for (auto& l : moved) {
    for (auto& p : l) p = rot * p + V(3.25, -1.5);
  }
  const Triangulation2D t0 = triangulate(loops);
  const Triangulation2D t1 = triangulate(moved);
  ASSERT_EQ(t0.triangles, t1.triangles);
  const MixedMesh2D m0 = recombine(t0);
  const MixedMesh2D m1 = recombine(t1);
  EXPECT_EQ(m0.quads, m1.quads);
  EXPECT_EQ(m0.triangles, m1.triangles);
}

}  // namespace
}  // namespace cooperage::mesh2d::test
