// Moving the free nodes of split quads: the thin triangle beside a sharp
// corner gets better, fixed nodes stay, quads keep their floor, and a moved
// mesh moves the same way.
#include "framework/mesh/improve_split_nodes.h"

#include "framework/mesh/split_poor_quads.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace cooperage::mesh {
namespace {

// A 20-degree tip T and its two boundary neighbours b1, b2; the free node P
// sits just past the b1-b2 diagonal (where a quad put it), so the triangle
// (b1, P, b2) the split leaves is thin. Two quads join P to the fixed nodes
// c1, m, c2 on the right.
struct Fan {
  std::vector<Vec3> points;
  std::vector<Quad> quads{{1, 4, 6, 3}, {3, 6, 5, 2}};
  std::vector<Tri> tris{{0, 1, 2}, {1, 3, 2}};
  std::vector<bool> movable{false, false, false, true, false, false, false};
};

Fan fan() {
  const double t = std::tan(10.0 * M_PI / 180.0);
  Fan f;
  f.points = {Vec3(0, 0, 0),    Vec3(1, -t, 0),  Vec3(1, t, 0), Vec3(1.05, 0, 0),
              Vec3(2, -0.6, 0), Vec3(2, 0.6, 0), Vec3(2, 0, 0)};
  return f;
}

double quality(const std::vector<Vec3>& p, const Tri& t) {
  return min_corner_sine(p, t.data(), 3, Vec3(0, 0, 1)) * 2.0 / std::sqrt(3.0);
}
double quality(const std::vector<Vec3>& p, const Quad& q) {
  return min_corner_sine(p, q.data(), 4, Vec3(0, 0, 1));
}

TEST(ImproveSplitNodes, ThinTriangleGetsBetterAndQuadsKeepTheirFloor) {
  Fan f = fan();
  const std::vector<Vec3> start = f.points;
  const double thin = quality(start, f.tris[1]);
  const double tip = quality(start, f.tris[0]);
  improve_split_nodes(
      f.points, f.quads, f.tris, f.movable, [](const Vec3& x) { return x; }, 0.5);
  EXPECT_GT(quality(f.points, f.tris[1]), thin + 0.2) << "thin triangle was " << thin;
  EXPECT_NEAR(quality(f.points, f.tris[0]), tip, 1e-15);  // fixed nodes only
  for (size_t i = 0; i < start.size(); ++i) {
    if (!f.movable[i]) {
      EXPECT_EQ(f.points[i], start[i]) << "node " << i;
    }
  }
  for (const Quad& q : f.quads) {
    EXPECT_GE(quality(f.points, q), std::min(0.5, quality(start, q)) - 1e-12);
  }
}

TEST(ImproveSplitNodes, ProjectionKeepsNodesOnTheSurface) {
  Fan f = fan();
  improve_split_nodes(
      f.points, f.quads, f.tris, f.movable, [](const Vec3& x) { return Vec3(x.x(), x.y(), 0.0); },
      0.5);
  EXPECT_EQ(f.points[3].z(), 0.0);
}

TEST(ImproveSplitNodes, RigidMotionMovesTheSameWay) {
  Fan plain = fan();
  Fan moved = fan();
  const Eigen::Matrix3d r = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  const Vec3 shift(5, -2, 7);
  for (Vec3& p : moved.points) p = r * p + shift;
  const Vec3 normal = r * Vec3(0, 0, 1);
  auto on_plane = [&](const Vec3& x) { return Vec3(x - (x - shift).dot(normal) * normal); };
  improve_split_nodes(
      plain.points, plain.quads, plain.tris, plain.movable, [](const Vec3& x) { return x; }, 0.5);
  improve_split_nodes(moved.points, moved.quads, moved.tris, moved.movable, on_plane, 0.5);
  for (size_t i = 0; i < plain.points.size(); ++i) {
    EXPECT_LT((r * plain.points[i] + shift - moved.points[i]).norm(), 1e-9) << "node " << i;
  }
}

}  // namespace
}  // namespace cooperage::mesh
