// Lattice walk and fill, and the guarded smoother (value types, no CAD).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
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

// A half annulus, r in [2, 4] (j), angle in [0, 180] degrees (i), as
// planar parameters: one block, filled as transfinite interpolation fills
// it -- every interior point on its column's radius at its row's angle.
// The row and column blend put rows on chords across the hole: a sweep
// round the annulus's axis got hexes 0.14 off square from its ribs.
TEST(SubmapLattice, AHalfAnnulusIsFilledAlongItsRadii) {
  const int ni = 24, nj = 4;
  auto loop = polygon({{0, 0}, {ni, 0}, {ni, nj}, {0, nj}}, 0);
  auto polar = [&](int i, int j) {
    const double a = M_PI * i / ni, r = 28.0 + 12.0 * j / nj;
    return Vec2(r * std::cos(a), r * std::sin(a));
  };
  for (BoundaryPoint& b : loop) b.uv = polar(b.ij[0], b.ij[1]);
  const LatticeFill f = fill_lattice({loop});
  ASSERT_TRUE(f.ok) << f.why;
  ASSERT_TRUE(fills_its_box(f));
  for (size_t p = 0; p < f.ij.size(); ++p) {
    const Vec2 want = polar(f.ij[p][0], f.ij[p][1]);
    EXPECT_NEAR((f.uv[p] - want).norm(), 0.0, 1e-12) << f.ij[p][0] << ", " << f.ij[p][1];
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

// Signed area of every cell in (u, v): positive where the fill keeps the
// lattice's orientation.
double smallest_cell_area(const LatticeFill& f) {
  double least = INFINITY;
  for (const auto& c : f.cells) {
    double twice = 0;
    for (size_t k = 0; k < 4; ++k) {
      const Vec2& a = f.uv[static_cast<size_t>(c[k])];
      const Vec2& b = f.uv[static_cast<size_t>(c[(k + 1) % 4])];
      twice += a.x() * b.y() - a.y() * b.x();
    }
    least = std::min(least, 0.5 * twice);
  }
  return least;
}

// A hole's wall notched down into a foot (the plan => mesh campaign, seed 3
// case 71), unrolled: rows 0-4 are the wall between the block's top and
// bottom, one unit apart; columns 16-20 continue 4 rows more into the foot,
// 0.25 apart, and their foot lies further along the wall than their top.
// Blended, the notch's columns spread their rows over the notch's whole
// depth and the cells beside the notch's corners fold; cut into blocks at
// the reentrant corners, every row of the wall stays level and no cell
// folds.
TEST(SubmapLattice, ANotchedWallCutIntoBlocksKeepsItsRowsLevel) {
  const int n = 24, depth = 4, notch = 4, a = 16;
  const double top_u[] = {0,   0.5, 0.9, 1.25, 1.55, 1.8, 2.0, 2.2, 2.4, 2.6, 2.8,  3.05, 3.3,
                          3.6, 4.0, 4.5, 5.1,  5.7,  6.3, 6.9, 7.5, 8.1, 8.7, 9.35, 10};
  std::vector<BoundaryPoint> loop;
  int node = 0;
  auto add = [&](int i, int j, double u, double v) {
    loop.push_back({{i, j}, node++, Vec2(u, v)});
  };
  // Counter-clockwise in (i, j): the bottom rim left to right with the
  // notch, the right seam, the top rim right to left, the left seam.
  const double bottom_u0 = 7.9, notch_w = 0.8;  // the notch spans u 7.9 - 8.7
  auto bottom_u = [&](int i) {
    if (i <= a) return bottom_u0 * i / a;
    if (i >= a + notch)
      return bottom_u0 + notch_w + (10 - bottom_u0 - notch_w) * (i - a - notch) / (n - a - notch);
    return bottom_u0 + notch_w * (i - a) / notch;
  };
  for (int i = 0; i < a; ++i) add(i, 0, bottom_u(i), 0);
  for (int j = 0; j < depth; ++j) add(a, -j, bottom_u(a), -0.25 * j);
  for (int i = a; i < a + notch; ++i) add(i, -depth, bottom_u(i), -0.25 * depth);
  for (int j = depth; j > 0; --j) add(a + notch, -j, bottom_u(a + notch), -0.25 * j);
  for (int i = a + notch; i < n; ++i) add(i, 0, bottom_u(i), 0);
  for (int j = 0; j < 4; ++j) add(n, j, 10, j);
  for (int i = n; i > 0; --i) add(i, 4, top_u[i], 4);
  for (int j = 4; j > 0; --j) add(0, j, 0, j);
  const LatticeFill blend = fill_lattice({loop}, FillInterior::Blend);
  const LatticeFill blocks = fill_lattice({loop}, FillInterior::Blocks);
  ASSERT_TRUE(blend.ok) << blend.why;
  ASSERT_TRUE(blocks.ok) << blocks.why;
  EXPECT_EQ(blocks.cells.size(), blend.cells.size());
  EXPECT_LE(smallest_cell_area(blend), 0.0);  // why the blocks exist
  EXPECT_GT(smallest_cell_area(blocks), 0.0);
  for (size_t p = 0; p < blocks.ij.size(); ++p) {
    if (blocks.ij[p][1] >= 0) {
      EXPECT_NEAR(blocks.uv[p].y(), blocks.ij[p][1], 1e-12) << "point " << p;
    }
  }
}

// A hole's wall whose top is notched 0.16 deep by a slot, unrolled (the
// plan => mesh campaign, seed 7 case 133): the seams are spaced on the
// levels of the caps the wall passes (cooper's level_spacing.h: a blind
// hole's floor at v = 19, five rows under the slot's floor at 30.16). Cut
// into blocks at the notch's corners, the cut lines take the seam's spacing
// and every block blends between its own sides, so each row stays on its
// level; cut evenly, the row of v = 19 lay at 24.1 and the sweep inverted.
TEST(SubmapLattice, CutLinesFollowAGradedSideBesideThem) {
  const double level[] = {0, 4.75, 9.5, 14.25, 19, 30.16, 30.32};
  const int n = 12, lo = 4, hi = 8;
  std::vector<BoundaryPoint> loop;
  int node = 0;
  auto add = [&](int i, int j) { loop.push_back({{i, j}, node++, Vec2(i, level[j])}); };
  for (int i = 0; i < n; ++i) add(i, 0);
  for (int j = 0; j < 6; ++j) add(n, j);
  for (int i = n; i > hi; --i) add(i, 6);
  add(hi, 6);
  for (int i = hi; i > lo; --i) add(i, 5);
  add(lo, 5);
  for (int i = lo; i > 0; --i) add(i, 6);
  for (int j = 6; j > 0; --j) add(0, j);
  const LatticeFill f = fill_lattice({loop}, FillInterior::Blocks);
  ASSERT_TRUE(f.ok) << f.why;
  EXPECT_GT(smallest_cell_area(f), 0.0);
  for (size_t p = 0; p < f.ij.size(); ++p) {
    EXPECT_NEAR(f.uv[p].x(), f.ij[p][0], 1e-9) << "point " << p;
    EXPECT_NEAR(f.uv[p].y(), level[f.ij[p][1]], 1e-9) << "point " << p;
  }
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

TEST(SubmapSmooth, AnEvenLatticeOnACylinderIsAFixedPoint) {
  // A quarter cylinder of radius 1, 7 x 6 nodes at even angles and heights:
  // each free node's Laplacian point lies inside the cylinder on the node's
  // own radius and projects back onto the node. One sweep finds that and the
  // smoothing stops; it used to project and check every node in every sweep.
  std::vector<Vec3> x;
  std::vector<bool> fixed;
  const int na = 6, nz = 5;
  for (int i = 0; i <= na; ++i) {
    const double a = 0.5 * M_PI * i / na;
    for (int j = 0; j <= nz; ++j) {
      x.emplace_back(std::cos(a), std::sin(a), 0.2 * j);
      fixed.push_back(i == 0 || j == 0 || i == na || j == nz);
    }
  }
  auto id = [&](int i, int j) { return i * (nz + 1) + j; };
  std::vector<mesh::Quad> quads;
  for (int i = 0; i < na; ++i) {
    for (int j = 0; j < nz; ++j)
      quads.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  }
  std::vector<Vec3> normals;
  for (const Vec3& p : x) normals.emplace_back(p.x(), p.y(), 0.0);
  int projections = 0;
  const auto cylinder = [&](const Vec3& p, size_t) {
    ++projections;
    const Vec3 radial = Vec3(p.x(), p.y(), 0).normalized();
    return geom::SurfaceProjection{Vec3(radial.x(), radial.y(), p.z()), radial,
                                   Vec2(std::atan2(p.y(), p.x()), p.z()),
                                   std::abs(Vec3(p.x(), p.y(), 0).norm() - 1.0)};
  };
  for (const auto& q : quads) {  // counter-clockwise about the outward normal
    std::array<Vec3, 4> p, n;
    for (size_t k = 0; k < 4; ++k) {
      p[k] = x[static_cast<size_t>(q[k])];
      n[k] = normals[static_cast<size_t>(q[k])];
    }
    ASSERT_GT(quad_scaled_jacobian(p, n), 0.9);
  }
  const std::vector<Vec3> before = x;
  smooth_quads(x, normals, fixed, quads, cylinder, {4, 0.2});
  EXPECT_EQ(x, before);
  const int free_nodes = static_cast<int>(std::count(fixed.begin(), fixed.end(), false));
  EXPECT_EQ(projections, free_nodes) << "sweeps after the first one that moved nothing";
}

}  // namespace
}  // namespace cooperage::submap
