// Lattice walk and fill, and the guarded smoother (value types, no CAD).
#include <gtest/gtest.h>

#include <set>

#include "schemes/submap/directions.h"
#include "schemes/submap/lattice.h"
#include "schemes/submap/smooth.h"

namespace cooperage::submap {
namespace {

// Boundary points of a rectilinear lattice polygon given by its corners
// (counter-clockwise for an outer loop, clockwise for a hole); uv = (i, j)
// scaled by `h`, node ids from `first_node`.
std::vector<BoundaryPoint> polygon(const std::vector<LatticePoint>& corners, int first_node,
                                   double h = 1.0) {
  std::vector<BoundaryPoint> out;
  int node = first_node;
  for (size_t k = 0; k < corners.size(); ++k) {
    LatticePoint p = corners[k];
    const LatticePoint q = corners[(k + 1) % corners.size()];
    while (p != q) {
      out.push_back({p, node++, Vec2(h * p[0], h * p[1])});
      p[0] += (q[0] > p[0]) - (q[0] < p[0]);
      p[1] += (q[1] > p[1]) - (q[1] < p[1]);
    }
  }
  return out;
}

TEST(SubmapLattice, WalkFollowsDirectionsAndCloses) {
  LatticePoint end{};
  const auto pts = walk_loop({kPlusI, kPlusJ, kMinusI, kPlusJ, kMinusI, kMinusJ},
                             {4, 2, 2, 2, 2, 4}, {0, 0}, &end);
  ASSERT_EQ(pts.size(), 16u);
  EXPECT_EQ(pts[4], (LatticePoint{4, 0}));
  EXPECT_EQ(pts[6], (LatticePoint{4, 2}));
  EXPECT_EQ(pts[8], (LatticePoint{2, 2}));
  EXPECT_EQ(end, (LatticePoint{0, 0}));
  walk_loop({kPlusI, kPlusJ, kMinusI, kMinusJ}, {3, 1, 2, 1}, {0, 0}, &end);
  EXPECT_EQ(end, (LatticePoint{1, 0}));  // unbalanced: does not close
}

TEST(SubmapLattice, LShapeFillIsExactOnAUniformBoundary) {
  const auto loop = polygon({{0, 0}, {4, 0}, {4, 2}, {2, 2}, {2, 4}, {0, 4}}, 0, 0.5);
  const LatticeFill f = fill_lattice({loop});
  ASSERT_TRUE(f.ok) << f.why;
  EXPECT_EQ(f.cells.size(), 12u);           // area 16 - 4
  EXPECT_EQ(f.ij.size(), loop.size() + 5);  // interior (1,1) (2,1) (3,1) (1,2) (1,3)
  for (size_t p = 0; p < f.ij.size(); ++p) {
    EXPECT_NEAR(f.uv[p].x(), 0.5 * f.ij[p][0], 1e-12);
    EXPECT_NEAR(f.uv[p].y(), 0.5 * f.ij[p][1], 1e-12);
  }
}

// A 6 x 4 block whose left and right sides are graded the same way (v =
// 0, 0.5, 0.7, 0.85, 1 of the height: a long first interval, as cooper
// gives a rib leaving a tangent cap): every interior row takes the sides'
// v, as transfinite interpolation does; the lattice index alone would put
// row 1 at 0.25.
TEST(SubmapLattice, GradedSidesCarryTheirSpacingAcross) {
  const double v[5] = {0.0, 0.5, 0.7, 0.85, 1.0};
  auto loop = polygon({{0, 0}, {6, 0}, {6, 4}, {0, 4}}, 0);
  for (BoundaryPoint& b : loop) b.uv.y() = v[b.ij[1]];
  const LatticeFill f = fill_lattice({loop});
  ASSERT_TRUE(f.ok) << f.why;
  EXPECT_TRUE(fills_its_box(f));
  for (size_t p = 0; p < f.ij.size(); ++p) {
    EXPECT_NEAR(f.uv[p].x(), f.ij[p][0], 1e-12);
    EXPECT_NEAR(f.uv[p].y(), v[f.ij[p][1]], 1e-12) << "row " << f.ij[p][1];
  }
  // An L shape is not one block.
  EXPECT_FALSE(
      fills_its_box(fill_lattice({polygon({{0, 0}, {4, 0}, {4, 2}, {2, 2}, {2, 4}, {0, 4}}, 0)})));
}

TEST(SubmapLattice, PlateWithOffCentreHole) {
  const auto outer = polygon({{0, 0}, {8, 0}, {8, 6}, {0, 6}}, 0);
  const auto hole = polygon({{5, 1}, {5, 3}, {7, 3}, {7, 1}}, 1000);  // clockwise
  const LatticeFill f = fill_lattice({outer, hole});
  ASSERT_TRUE(f.ok) << f.why;
  EXPECT_EQ(f.cells.size(), 48u - 4u);
  std::set<std::pair<int, int>> cells;
  for (const auto& c : f.cells)
    cells.insert({f.ij[static_cast<size_t>(c[0])][0], f.ij[static_cast<size_t>(c[0])][1]});
  EXPECT_EQ(cells.count({5, 1}), 0u);
  EXPECT_EQ(cells.count({6, 2}), 0u);
  EXPECT_EQ(cells.count({4, 1}), 1u);
  for (size_t p = 0; p < f.ij.size(); ++p) {
    EXPECT_NEAR(f.uv[p].x(), f.ij[p][0], 1e-12);
    EXPECT_NEAR(f.uv[p].y(), f.ij[p][1], 1e-12);
  }
}

TEST(SubmapLattice, InvalidRegionsAreReported) {
  const auto outer = polygon({{0, 0}, {4, 0}, {4, 4}, {0, 4}}, 0);
  // A hole touching the outer boundary: two nodes on one lattice point.
  const auto touching = polygon({{2, 0}, {2, 2}, {4, 2}, {4, 0}}, 1000);
  EXPECT_FALSE(fill_lattice({outer, touching}).ok);
  // A hole outside the outer loop: winding -1.
  const auto outside = polygon({{6, 1}, {6, 2}, {7, 2}, {7, 1}}, 1000);
  const LatticeFill f = fill_lattice({outer, outside});
  EXPECT_FALSE(f.ok);
  EXPECT_NE(f.why.find("winding"), std::string::npos) << f.why;
}

TEST(SubmapLattice, SeamNodeMayHoldTwoLatticePoints) {
  // A cylinder side unrolled: column 0 and column 4 carry the same nodes.
  auto loop = polygon({{0, 0}, {4, 0}, {4, 2}, {0, 2}}, 0);
  for (auto& b : loop) {
    if (b.ij[0] == 0 && b.ij[1] > 0 && b.ij[1] < 2) b.node = 100 + b.ij[1];
    if (b.ij[0] == 4 && b.ij[1] > 0 && b.ij[1] < 2) b.node = 100 + b.ij[1];
  }
  const LatticeFill f = fill_lattice({loop});
  ASSERT_TRUE(f.ok) << f.why;
  EXPECT_EQ(f.cells.size(), 8u);
}

TEST(SubmapSmooth, SmoothingNeverInvertsAndKeepsTopology) {
  // A 4 x 4 grid on the plane z = 0 with a badly placed interior node.
  std::vector<Vec3> x;
  std::vector<bool> fixed;
  for (int i = 0; i <= 4; ++i) {
    for (int j = 0; j <= 4; ++j) {
      x.emplace_back(i, j, 0);
      fixed.push_back(i == 0 || j == 0 || i == 4 || j == 4);
    }
  }
  auto id = [](int i, int j) { return i * 5 + j; };
  x[static_cast<size_t>(id(2, 2))] = Vec3(2.9, 2.9, 0);
  std::vector<mesh::Quad> quads;
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j)
      quads.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  }
  std::vector<Vec3> normals(x.size(), Vec3(0, 0, 1));
  const auto plane = [](const Vec3& p, size_t) {
    return geom::SurfaceProjection{Vec3(p.x(), p.y(), 0), Vec3(0, 0, 1), Vec2(p.x(), p.y()),
                                   std::abs(p.z())};
  };
  const auto before = quads;
  smooth_quads(x, normals, fixed, quads, plane, {10, 0.2});
  EXPECT_EQ(quads, before);
  for (const auto& q : quads) {
    std::array<Vec3, 4> p, n;
    for (size_t k = 0; k < 4; ++k) {
      p[k] = x[static_cast<size_t>(q[k])];
      n[k] = Vec3(0, 0, 1);
    }
    EXPECT_GT(quad_scaled_jacobian(p, n), 0.9);
  }
  EXPECT_NEAR(x[static_cast<size_t>(id(2, 2))].x(), 2.0, 1e-2);
  EXPECT_EQ(x[0], Vec3(0, 0, 0));
}

}  // namespace
}  // namespace cooperage::submap
