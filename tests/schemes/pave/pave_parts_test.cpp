// Tests of the steps of pave_2d on small hand-made inputs: the constrained
// Delaunay triangulation, recombination, the all-quad split, cleanup,
// smoothing and the Hilbert order of the triangulation's output.
#include "schemes/pave/cdt_2d.h"
#include "schemes/pave/cleanup_2d.h"
#include "schemes/pave/recombine.h"
#include "schemes/pave/smooth_2d.h"
#include "schemes/pave/spatial_order.h"
#include "schemes/pave/split_to_quads.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <set>

namespace cooperage::pave::detail {
namespace {

using V2 = Eigen::Vector2d;

double orient(const V2& a, const V2& b, const V2& c) { return cross2(b - a, c - a); }

CdtInput square_input(int per_side, double size, bool refine) {
  CdtInput in;
  std::vector<int> loop;
  const V2 corners[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (int s = 0; s < 4; ++s) {
    for (int i = 0; i < per_side; ++i) {
      loop.push_back(static_cast<int>(in.points.size()));
      in.points.push_back(corners[s] +
                          (corners[(s + 1) % 4] - corners[s]) * (double(i) / per_side));
      in.sizes.push_back(size);
    }
  }
  in.loops = {loop};
  in.refine = refine;
  return in;
}

TEST(PaveCdt, BoundaryOnlyTriangulationHasNMinus2TrianglesAndAllLoopEdges) {
  const CdtInput in = square_input(3, 1.0, false);
  const Triangulation2D t = constrained_delaunay(in);
  EXPECT_EQ(t.tris.size(), in.points.size() - 2);
  std::set<std::pair<int, int>> edges;
  for (const auto& tr : t.tris) {
    EXPECT_GT(orient(t.points[tr[0]], t.points[tr[1]], t.points[tr[2]]), 0);
    for (int k = 0; k < 3; ++k) edges.insert({tr[k], tr[(k + 1) % 3]});
  }
  const auto& loop = in.loops[0];
  for (size_t k = 0; k < loop.size(); ++k)
    EXPECT_TRUE(edges.count({loop[k], loop[(k + 1) % loop.size()]}));
}

TEST(PaveCdt, RefinementFillsTheDomainAtTheLocalSize) {
  const CdtInput in = square_input(10, 0.1, true);
  const Triangulation2D t = constrained_delaunay(in);
  double area = 0;
  for (const auto& tr : t.tris) {
    const double a = 0.5 * orient(t.points[tr[0]], t.points[tr[1]], t.points[tr[2]]);
    EXPECT_GT(a, 0);
    area += a;
  }
  EXPECT_NEAR(area, 1.0, 1e-12);
  EXPECT_GT(t.points.size(), 80u);   // interior points were added
  EXPECT_LT(t.points.size(), 250u);  // but not far below the size
}

TEST(PaveSplit, RecombinedSquareSplitsIntoValidQuads) {
  const CdtInput in = square_input(4, 0.25, true);
  const Triangulation2D t = constrained_delaunay(in);
  const std::vector<Cell> cells = recombine(t, 0.3);
  int covered = 0;
  for (const Cell& c : cells) covered += c[3] < 0 ? 1 : 2;
  EXPECT_EQ(covered, static_cast<int>(t.tris.size()));
  std::vector<V2> fine = t.points;
  std::vector<int> fine_of(t.points.size());
  for (size_t i = 0; i < fine_of.size(); ++i) fine_of[i] = static_cast<int>(i);
  std::unordered_map<std::uint64_t, int> mids;
  std::vector<Quad> quads;
  split_to_quads(cells, t.points, fine_of, mids, fine, quads);
  int expected = 0;
  for (const Cell& c : cells) expected += c[3] < 0 ? 3 : 4;
  EXPECT_EQ(static_cast<int>(quads.size()), expected);
  for (const Quad& q : quads) EXPECT_GT(scaled_jacobian_2d(fine, q), 0);
}

TEST(PaveCleanup, DoubletIsMerged) {
  std::vector<V2> pts{{0, 0}, {2, 0}, {2, 2}, {0, 2}, {1.1, 0.9}};
  std::vector<Quad> quads{{4, 0, 1, 2}, {4, 2, 3, 0}};
  std::vector<char> fixed{1, 1, 1, 1, 0};
  EXPECT_EQ(remove_doublets(pts, quads, fixed), 1);
  ASSERT_EQ(quads.size(), 1u);
  EXPECT_EQ(pts.size(), 4u);
  EXPECT_GT(scaled_jacobian_2d(pts, quads[0]), 0.99);
}

TEST(PaveCleanup, DiamondIsCollapsed) {
  // A 4 x 4 grid whose centre node is split into a (south) and c (north)
  // with the diamond (west, a, east, c) between them.
  std::vector<V2> pts;
  auto id = [](int i, int j) { return j * 5 + i; };
  for (int j = 0; j < 5; ++j) {
    for (int i = 0; i < 5; ++i) pts.emplace_back(i, j);
  }
  const int a = id(2, 2), c = 25;
  pts[static_cast<size_t>(a)] = V2(2, 1.8);
  pts.emplace_back(2, 2.2);
  std::vector<Quad> quads;
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 4; ++i) {
      Quad q{id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)};
      if (j >= 2) {
        for (int& v : q) v = v == a ? c : v;  // north of the split uses c
      }
      quads.push_back(q);
    }
  }
  quads.push_back({id(1, 2), a, id(3, 2), c});
  std::vector<char> fixed(pts.size(), 0);
  for (int j = 0; j < 5; ++j) {
    for (int i = 0; i < 5; ++i)
      fixed[static_cast<size_t>(id(i, j))] = i == 0 || j == 0 || i == 4 || j == 4;
  }
  for (const Quad& q : quads) ASSERT_GT(scaled_jacobian_2d(pts, q), 0);
  EXPECT_EQ(collapse_diamonds(pts, quads, fixed), 1);
  EXPECT_EQ(quads.size(), 16u);
  EXPECT_EQ(pts.size(), 25u);
  for (const Quad& q : quads) EXPECT_GT(scaled_jacobian_2d(pts, q), 0.5);
}

TEST(PaveSmooth, UntanglesAndNeverMovesFixedNodes) {
  // 3 x 3 grid with the four interior nodes scrambled (some quads inverted).
  std::vector<V2> pts;
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 4; ++i) pts.emplace_back(i, j);
  }
  pts[5] = V2(2.4, 2.6);
  pts[6] = V2(0.7, 2.2);
  pts[9] = V2(2.2, 0.6);
  pts[10] = V2(1.1, 1.3);
  std::vector<Quad> quads;
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 3; ++i)
      quads.push_back({j * 4 + i, j * 4 + i + 1, j * 4 + i + 5, j * 4 + i + 4});
  }
  std::vector<char> fixed(16, 1);
  fixed[5] = fixed[6] = fixed[9] = fixed[10] = 0;
  const std::vector<V2> before = pts;
  smooth_quads_2d(pts, quads, fixed);
  for (size_t i = 0; i < pts.size(); ++i) {
    if (fixed[i]) {
      EXPECT_EQ(pts[i], before[i]);
    }
  }
  for (const Quad& q : quads) EXPECT_GT(scaled_jacobian_2d(pts, q), 0.9);
}

TEST(PaveSpatialOrder, HilbertIndexVisitsEveryCellOnceThroughNeighbours) {
  for (int bits : {1, 2, 4}) {
    const std::uint32_t n = 1u << bits;
    std::vector<std::pair<int, int>> cell_at(static_cast<size_t>(n) * n, {-1, -1});
    for (std::uint32_t x = 0; x < n; ++x) {
      for (std::uint32_t y = 0; y < n; ++y) {
        const std::uint64_t d = hilbert_index(x, y, bits);
        ASSERT_LT(d, cell_at.size());
        EXPECT_EQ(cell_at[d].first, -1) << "index " << d << " used twice";
        cell_at[d] = {static_cast<int>(x), static_cast<int>(y)};
      }
    }
    EXPECT_EQ(cell_at.front(), std::make_pair(0, 0));
    for (size_t d = 1; d < cell_at.size(); ++d) {
      const int step = std::abs(cell_at[d].first - cell_at[d - 1].first) +
                       std::abs(cell_at[d].second - cell_at[d - 1].second);
      EXPECT_EQ(step, 1) << "cells " << d - 1 << " and " << d << " are not neighbours (bits "
                         << bits << ")";
    }
  }
}

TEST(PaveCdt, OutputIsInHilbertOrderAndKeepsTheLoopPoints) {
  const CdtInput in = square_input(16, 2.0 / 16, true);
  const Triangulation2D t = constrained_delaunay(in);
  ASSERT_GT(t.points.size(), in.points.size() + 10);
  for (size_t i = 0; i < in.points.size(); ++i) EXPECT_EQ(t.points[i], in.points[i]);
  Eigen::AlignedBox2d box;
  for (const V2& p : in.points) box.extend(p);
  const HilbertKeys key(box);
  for (size_t i = in.points.size() + 1; i < t.points.size(); ++i)
    EXPECT_LE(key(t.points[i - 1]), key(t.points[i]));
  int previous_lowest = -1;
  for (const auto& tri : t.tris) {
    const int lowest = std::min({tri[0], tri[1], tri[2]});
    EXPECT_GE(lowest, previous_lowest);  // triangles by their lowest point
    previous_lowest = lowest;
  }
}

}  // namespace
}  // namespace cooperage::pave::detail
