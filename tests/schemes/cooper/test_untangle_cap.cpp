// Untangling a projected subcap against its source's corners (Knupp 2001):
// folds are opened with the boundary kept, in the plane the faces are
// counter-clockwise about, and a mesh without folds is left alone.
#include "schemes/cooper/smooth_cap.h"
#include "schemes/cooper/untangle_cap.h"
#include "unit_grid.h"

#include <gtest/gtest.h>

#include <cmath>

namespace cooperage::cooper {
namespace {

using mesh::Vec3;

using test_meshes::UnitGrid;

double folded_worst(const std::vector<Vec3>& p, const std::vector<mesh::Quad>& q,
                    const Vec3& normal) {
  return min_quad_corner_quality(p, q, normal);
}

TEST(UntangleCap, OpensAGridWhoseInteriorIsMirrored) {
  // The interior of a 4 x 4 grid mirrored left to right: the boundary is
  // where it was, every quad touching the interior folds.
  const UnitGrid source(4);
  std::vector<Vec3> target = source.points;
  for (size_t i = 0; i < target.size(); ++i) {
    if (source.movable[i]) target[i].x() = 4.0 - target[i].x() + 0.3;
  }
  ASSERT_LT(folded_worst(target, source.quads, Vec3::UnitZ()), 0.0);
  const auto flat = [](const Vec3& x) { return Vec3(x.x(), x.y(), 0.0); };

  std::vector<Vec3> untangled = target;
  ASSERT_TRUE(untangle_cap(untangled, source.points, source.quads, {}, source.movable,
                           Vec3::UnitZ(), flat));
  EXPECT_GT(folded_worst(untangled, source.quads, Vec3::UnitZ()), 0.0);
  for (size_t i = 0; i < target.size(); ++i) {
    if (!source.movable[i]) {
      EXPECT_EQ(untangled[i], target[i]) << "boundary node " << i;
    }
    EXPECT_EQ(untangled[i].z(), 0.0);
  }
}

TEST(UntangleCap, BringsNodesLeftOutsideIntoAShrunkBoundary) {
  // The source's boundary squeezed to a third of its width at the target
  // (an imprinted line much nearer a hole's wall at one end), its interior
  // left where the source had it: outside the target. The target lies in
  // z = 5 and the faces run counter-clockwise about -z there (seen from the
  // other end); the result stays in that plane.
  const UnitGrid source(4);
  std::vector<Vec3> target(source.points.size());
  std::vector<mesh::Quad> quads = source.quads;
  for (auto& q : quads) std::swap(q[1], q[3]);
  for (size_t i = 0; i < target.size(); ++i) {
    const Vec3& p = source.points[i];
    target[i] = source.movable[i] ? Vec3(p.x(), p.y(), 5.0) : Vec3(p.x() / 3.0, p.y(), 5.0);
  }
  const Vec3 down = -Vec3::UnitZ();
  ASSERT_LT(folded_worst(target, quads, down), 0.0);
  const auto plane = [](const Vec3& x) { return Vec3(x.x(), x.y(), 5.0); };
  ASSERT_TRUE(untangle_cap(target, source.points, quads, {}, source.movable, down, plane));
  // Untangled, then the worst corners raised (0.16 without that).
  EXPECT_GT(folded_worst(target, quads, down), 0.25);
  for (size_t i = 0; i < target.size(); ++i) {
    EXPECT_EQ(target[i].z(), 5.0);
    if (source.movable[i]) {
      EXPECT_GT(target[i].x(), 0.0);
      EXPECT_LT(target[i].x(), 4.0 / 3.0);
    }
  }
}

// Half an annulus, rows at the given radii, one column every 45 degrees,
// counter-clockwise about +z; only the middle row's inner nodes move.
struct HalfRing {
  std::vector<Vec3> points;
  std::vector<mesh::Quad> quads;
  std::vector<char> movable;
  HalfRing(double inner, double middle, double outer) {
    const double pi = 3.14159265358979323846;
    for (int row = 0; row < 3; ++row) {
      const double r = row == 0 ? inner : row == 1 ? middle : outer;
      for (int k = 0; k <= 4; ++k) {
        points.emplace_back(r * std::cos(k * pi / 4), r * std::sin(k * pi / 4), 0);
        movable.push_back(row == 1 && k > 0 && k < 4 ? 1 : 0);
      }
    }
    for (int row = 0; row < 2; ++row) {
      for (int k = 0; k < 4; ++k) {
        const int a = row * 5 + k;
        quads.push_back({a, a + 5, a + 6, a + 1});
      }
    }
  }
};

TEST(UntangleCap, OpensAThinCurvedStripLeftFolded) {
  // At the source the ring is 1 wide; at the target 0.1 wide, narrower
  // than the sagitta of its 45-degree chords (0.15), with the middle row
  // left where the source had it: inside the hole. A node moved to its
  // neighbours' mean lands outside the strip, so guarded smoothing stops.
  const HalfRing source(1.0, 1.5, 2.0);
  HalfRing target(1.9, 1.95, 2.0);
  for (size_t i = 0; i < target.points.size(); ++i) {
    if (source.movable[i]) target.points[i] = source.points[i];
  }
  ASSERT_LT(folded_worst(target.points, source.quads, Vec3::UnitZ()), 0.0);
  const auto flat = [](const Vec3& x) { return Vec3(x.x(), x.y(), 0.0); };
  std::vector<Vec3> smoothed = target.points;
  smart_smooth_cap(smoothed, source.quads, {}, source.movable, Vec3::UnitZ(), flat, 60);
  EXPECT_LE(folded_worst(smoothed, source.quads, Vec3::UnitZ()), 0.0)
      << "guarded smoothing alone opens this fold; the test no longer shows the untangler's use";
  ASSERT_TRUE(untangle_cap(target.points, source.points, source.quads, {}, source.movable,
                           Vec3::UnitZ(), flat));
  // Untangled, then the worst corners raised (0.08 without that).
  EXPECT_GT(folded_worst(target.points, source.quads, Vec3::UnitZ()), 0.5);
}

TEST(UntangleCap, LeavesAMeshWithoutFoldsAlone) {
  UnitGrid g(3);
  g.points[5] += Vec3(0.2, -0.1, 0);  // distorted, not folded
  const std::vector<Vec3> before = g.points;
  EXPECT_FALSE(
      untangle_cap(g.points, UnitGrid(3).points, g.quads, {}, g.movable, Vec3::UnitZ(), nullptr));
  EXPECT_EQ(g.points, before);
}

TEST(UntangleCap, RefusesMismatchedInput) {
  UnitGrid g(2);
  std::vector<Vec3> p = g.points;
  EXPECT_FALSE(untangle_cap(p, {}, g.quads, {}, g.movable, Vec3::UnitZ(), nullptr));
  EXPECT_FALSE(untangle_cap(p, g.points, g.quads, {}, g.movable, Vec3::Zero(), nullptr));
  EXPECT_EQ(p, g.points);
}

}  // namespace
}  // namespace cooperage::cooper
