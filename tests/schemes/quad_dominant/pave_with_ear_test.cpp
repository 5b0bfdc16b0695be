// quad_dominant::pave_with_ear: an odd boundary meshed as quads and one
// triangle, checked by area and conformity (not by a stored mesh).
#include "schemes/quad_dominant/pave_with_ear.h"

#include "framework/core/error.h"

#include <gtest/gtest.h>

#include <map>

namespace cooperage::quad_dominant {
namespace {

using Loops = std::vector<std::vector<Eigen::Vector2d>>;

double signed_area(const std::vector<Eigen::Vector2d>& p, const int* idx, int n) {
  double a = 0;
  for (int k = 0; k < n; ++k) {
    const Eigen::Vector2d& u = p[static_cast<size_t>(idx[k])];
    const Eigen::Vector2d& v = p[static_cast<size_t>(idx[(k + 1) % n])];
    a += u.x() * v.y() - u.y() * v.x();
  }
  return 0.5 * a;
}

// A 3 x 2 rectangle with nodes every 0.5, one edge split once more: 21
// boundary nodes, counter-clockwise.
std::vector<Eigen::Vector2d> odd_rectangle() {
  std::vector<Eigen::Vector2d> loop;
  for (int i = 0; i < 6; ++i) loop.emplace_back(0.5 * i, 0.0);
  loop.emplace_back(2.75, 0.0);  // the extra node
  for (int i = 0; i < 4; ++i) loop.emplace_back(3.0, 0.5 * i);
  for (int i = 0; i < 6; ++i) loop.emplace_back(3.0 - 0.5 * i, 2.0);
  for (int i = 0; i < 4; ++i) loop.emplace_back(0.0, 2.0 - 0.5 * i);
  return loop;
}

TEST(PaveWithEar, AnOddBoundaryIsQuadsAndOneTriangleCoveringTheDomain) {
  const Loops loops{odd_rectangle()};
  ASSERT_EQ(loops[0].size() % 2, 1u);
  EXPECT_THROW(pave::pave_2d(loops), MeshingError);  // no all-quad mesh
  const PavedWithEar out = pave_with_ear(loops);
  ASSERT_TRUE(out.ear.has_value());
  const pave::QuadMesh2D& m = out.mesh;
  ASSERT_EQ(m.boundary_count, 21);
  for (size_t k = 0; k < loops[0].size(); ++k) EXPECT_EQ(m.points[k], loops[0][k]);
  // Every element counter-clockwise with area; together the rectangle.
  double area = signed_area(m.points, out.ear->data(), 3);
  EXPECT_GT(area, 0.0);
  for (const auto& q : m.quads) {
    const double a = signed_area(m.points, q.data(), 4);
    EXPECT_GT(a, 0.0);
    area += a;
  }
  EXPECT_NEAR(area, 6.0, 1e-9);
  // Conformal: an edge on the boundary once, every other edge twice, in
  // opposite directions.
  std::map<std::pair<int, int>, int> uses;
  const auto add = [&](const int* idx, int n) {
    for (int k = 0; k < n; ++k) ++uses[{idx[k], idx[(k + 1) % n]}];
  };
  add(out.ear->data(), 3);
  for (const auto& q : m.quads) add(q.data(), 4);
  for (const auto& [edge, n] : uses) {
    EXPECT_EQ(n, 1) << edge.first << "-" << edge.second;
    const bool boundary =
        edge.first < 21 && edge.second < 21 && (edge.second - edge.first + 21) % 21 == 1;
    if (!boundary) {
      EXPECT_EQ(uses.count({edge.second, edge.first}), 1u) << edge.first;
    }
  }
  for (int k = 0; k < 21; ++k) EXPECT_EQ(uses.count({k, (k + 1) % 21}), 1u) << k;
}

TEST(PaveWithEar, AnEvenBoundaryIsPavesAlone) {
  std::vector<Eigen::Vector2d> loop = odd_rectangle();
  loop.erase(loop.begin() + 6);  // the extra node
  const PavedWithEar out = pave_with_ear({loop});
  EXPECT_FALSE(out.ear.has_value());
  EXPECT_EQ(out.mesh.quads.size(), pave::pave_2d({loop}).quads.size());
}

}  // namespace
}  // namespace cooperage::quad_dominant
