// Tests of the coarse loop vertices with parity switching at corners
// (corner_picks.h, loop_picks in coarse_loops.h): every sharp corner of a
// rectangle becomes a coarse vertex whatever its side counts.
#include "schemes/pave/coarse_loops.h"
#include "schemes/pave/corner_picks.h"
#include "schemes/pave/pave_2d.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace cooperage::pave::detail {
namespace {

using V2 = Eigen::Vector2d;

constexpr double kCorner = 140.0 * M_PI / 180.0;

/// A counter-clockwise rectangle w x h with nx, ny intervals per side; the
/// corners are at loop positions 0, nx, nx + ny, 2 nx + ny.
std::vector<V2> rectangle(int nx, int ny, double w = 1.0, double h = 0.7) {
  const V2 c[4] = {{0, 0}, {w, 0}, {w, h}, {0, h}};
  const int n[4] = {nx, ny, nx, ny};
  std::vector<V2> p;
  for (int s = 0; s < 4; ++s) {
    for (int i = 0; i < n[s]; ++i) p.push_back(c[s] + (c[(s + 1) % 4] - c[s]) * (double(i) / n[s]));
  }
  return p;
}

std::vector<int> iota_loop(size_t n, size_t start = 0) {
  std::vector<int> loop;
  for (size_t k = 0; k < n; ++k) loop.push_back(static_cast<int>((k + start) % n));
  return loop;
}

/// Fine loop nodes (ids) that are coarse vertices.
std::set<int> coarse_nodes(const std::vector<int>& loop, const std::vector<size_t>& picks) {
  std::set<int> out;
  for (size_t k : picks) out.insert(loop[k]);
  return out;
}

/// Coarse edges over a single fine edge.
int odd_edge_count(size_t n, const std::vector<size_t>& picks) {
  int odd = 0;
  for (size_t j = 0; j < picks.size(); ++j)
    odd += (picks[(j + 1) % picks.size()] + n - picks[j]) % n == 1;
  return odd;
}

TEST(PaveCornerPicks, RectangleWithOddSidesHasAllFourCornersAsCoarseVertices) {
  // 5 + 3 + 5 + 3 = 16 nodes: one parity would skip two corners (0.707).
  const std::vector<V2> P = rectangle(5, 3);
  const std::vector<int> L = iota_loop(P.size());
  const std::vector<size_t> picks = loop_picks(P, L, 0, kCorner);
  const std::set<int> coarse = coarse_nodes(L, picks);
  for (int corner : {0, 5, 8, 13}) EXPECT_TRUE(coarse.count(corner)) << "corner " << corner;
  EXPECT_EQ(odd_edge_count(P.size(), picks), 4);                 // one per odd side
  EXPECT_DOUBLE_EQ(skipped_quality_of_picks(P, L, picks), 1.0);  // only straight nodes skipped
  // Without switching: one parity, two corners skipped.
  EXPECT_NEAR(skipped_quality_of_picks(P, L, loop_picks(P, L, 0, 0.0)), std::sqrt(0.5), 1e-9);
  // The odd edge sits in the middle of each odd side: 5 intervals -> its third.
  EXPECT_TRUE(coarse.count(2) && coarse.count(3));
}

TEST(PaveCornerPicks, OddLoopAndEvenSidesKeepFewOddEdges) {
  // 7 + 4 + 7 + 4 = 22 nodes: two odd sides, two odd edges.
  const std::vector<V2> P = rectangle(7, 4);
  const std::vector<int> L = iota_loop(P.size());
  const std::vector<size_t> picks = loop_picks(P, L, 0, kCorner);
  const std::set<int> coarse = coarse_nodes(L, picks);
  for (int corner : {0, 7, 11, 18}) EXPECT_TRUE(coarse.count(corner)) << "corner " << corner;
  EXPECT_EQ(odd_edge_count(P.size(), picks), 2);
  // An odd loop (7 + 4 + 7 + 5 = 23) has an odd number of odd edges.
  const std::vector<V2> Q = [] {
    std::vector<V2> q;
    const V2 c[4] = {{0, 0}, {1, 0}, {1, 0.7}, {0, 0.7}};
    const int n[4] = {7, 4, 7, 5};
    for (int s = 0; s < 4; ++s)
      for (int i = 0; i < n[s]; ++i)
        q.push_back(c[s] + (c[(s + 1) % 4] - c[s]) * (double(i) / n[s]));
    return q;
  }();
  const std::vector<int> M = iota_loop(Q.size());
  const std::vector<size_t> odd_picks = loop_picks(Q, M, 0, kCorner);
  for (int corner : {0, 7, 11, 18})
    EXPECT_TRUE(coarse_nodes(M, odd_picks).count(corner)) << "corner " << corner;
  EXPECT_EQ(odd_edge_count(Q.size(), odd_picks), 3);
}

TEST(PaveCornerPicks, SameCoarseNodesWhateverTheStartingNode) {
  const std::vector<V2> P = rectangle(5, 3);
  const std::set<int> reference =
      coarse_nodes(iota_loop(P.size()), loop_picks(P, iota_loop(P.size()), 0, kCorner));
  for (size_t start = 1; start < P.size(); ++start) {
    const std::vector<int> L = iota_loop(P.size(), start);
    EXPECT_EQ(coarse_nodes(L, loop_picks(P, L, 0, kCorner)), reference) << "start " << start;
  }
}

TEST(PaveCornerPicks, CoarseBoundaryPairsTheOddEdgesAndKeepsTheCornersAsCoarseVertices) {
  const std::vector<V2> P = rectangle(5, 3);
  const CoarseBoundary coarse = coarse_boundary(P, {iota_loop(P.size())}, true, 0, kCorner);
  EXPECT_EQ(coarse.odd_edges.size(), 4u);
  EXPECT_EQ(coarse.midpoint.size() + coarse.odd_edges.size(), coarse.loops[0].size());
  const std::set<int> fine(coarse.fine_of_coarse.begin(), coarse.fine_of_coarse.end());
  for (int corner : {0, 5, 8, 13}) EXPECT_TRUE(fine.count(corner));
  // Every corner is an END node: one coarse cell.
  for (size_t c = 0; c < coarse.fine_of_coarse.size(); ++c) {
    const int f = coarse.fine_of_coarse[c];
    EXPECT_EQ(coarse.min_cells[c], f == 0 || f == 5 || f == 8 || f == 13 ? 1 : 2) << "node " << f;
  }
}

/// Whether two edges of the coarse polygon that share no vertex cross
/// (a plain O(m^2) check, independent of the one in coarse_loops.cpp).
bool coarse_polygon_crosses(const std::vector<V2>& P, const std::vector<int>& L,
                            const std::vector<size_t>& picks) {
  const size_t m = picks.size();
  const auto at = [&](size_t j) { return P[static_cast<size_t>(L[picks[j % m]])]; };
  const auto side = [](const V2& a, const V2& b, const V2& c) {
    const V2 u = b - a, v = c - a;
    return u.x() * v.y() - u.y() * v.x();
  };
  for (size_t i = 0; i < m; ++i)
    for (size_t k = i + 2; k < m; ++k) {
      if ((k + 1) % m == i) continue;
      const bool apart_k =
          (side(at(i), at(i + 1), at(k)) > 0) != (side(at(i), at(i + 1), at(k + 1)) > 0);
      const bool apart_i =
          (side(at(k), at(k + 1), at(i)) > 0) != (side(at(k), at(k + 1), at(i + 1)) > 0);
      if (apart_k && apart_i) return true;
    }
  return false;
}

// The cap of a lug's cone underside where it runs into a block's wall at 8
// degrees, as pave got it in the plan => mesh campaign (seed 5 case 94,
// surface 7, normalised): a sliver ends at node 0. Node 0 is the sharpest
// corner, so the best skipped node makes it a coarse vertex and skips node
// 1; the chord 0 -> 2 then passes beyond the sliver's other side (nodes 19
// to 22) and the triangulation failed ("loop edges intersect").
TEST(PaveCornerPicks, ACoarseLoopThatWouldCrossItselfTakesTheOtherNodes) {
  const std::vector<V2> P = {{0, 0},
                             {0.164981, 0},
                             {0.321134, 0.0530454},
                             {0.451654, 0.153848},
                             {0.542398, 0.291499},
                             {0.58359, 0.45114},
                             {0.570775, 0.615518},
                             {0.505319, 0.766865},
                             {0.394299, 0.888782},
                             {0.249714, 0.968092},
                             {0.0872188, 0.996189},
                             {0.0857594, 0.756413},
                             {0.0846734, 0.565159},
                             {0.121011, 0.554793},
                             {0.149024, 0.522206},
                             {0.151681, 0.475026},
                             {0.127502, 0.439498},
                             {0.0925531, 0.425116},
                             {0.113259, 0.250749},
                             {0.127689, 0.129656},
                             {0.136067, 0.0596069},
                             {0.140935, 0.0190919},
                             {0.111802, 0.0155072},
                             {0.0674366, 0.00972009}};
  const std::vector<int> L = iota_loop(P.size());
  ASSERT_TRUE(coarse_polygon_crosses(P, L, preferred_picks(P, L, 0, kCorner)))
      << "the case no longer arises: the test shows nothing";
  EXPECT_FALSE(coarse_polygon_crosses(P, L, loop_picks(P, L, 0, kCorner)));
  const QuadMesh2D m = pave_2d({P});
  EXPECT_FALSE(m.quads.empty());
}

}  // namespace
}  // namespace cooperage::pave::detail
