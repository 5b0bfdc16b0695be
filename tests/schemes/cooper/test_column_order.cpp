// The columns of a notched wall's corners keep the wall's order
// (column_order.h): rows on the rims' interval counts, from plain facts.
#include "schemes/cooper/column_order.h"
#include "schemes/cooper/wall_walk.h"

#include <gtest/gtest.h>

#include <map>
#include <vector>

namespace cooperage::cooper {
namespace {

using geom::Vec3;

// A wall in the plane y = 0, x from 0 to 10, z from 0 to 4, parallel to a
// sweep along z: a notch from its top down to z = 3 between x = 2 and 5 (a
// pocket's floor) and one from its bottom up to z = 1 between x = 5.5 and
// 8 (a crossing hole's ceiling). Walked counter-clockwise seen from -y,
// from (0, 0); curve k is the k-th side of the walk. `lean` moves the top
// corners by that much in x (a slanted wall when not 0).
struct NotchedWall {
  VolumeFacts facts;
  SideLattice lattice;
};

NotchedWall notched_wall(double lean = 0.0) {
  const std::vector<Vec3> corners = {{0, 0, 0},         {5.5, 0, 0},      {5.5, 0, 1},
                                     {8, 0, 1},         {8, 0, 0},        {10, 0, 0},
                                     {10 + lean, 0, 4}, {5 + lean, 0, 4}, {5 + lean, 0, 3},
                                     {2 + lean, 0, 3},  {2 + lean, 0, 4}, {lean, 0, 4}};
  const std::vector<double> angles = {90, 90, 270, 270, 90, 90, 90, 90, 270, 270, 90, 90};
  NotchedWall w;
  FaceFact f;
  f.id = 1;
  f.loops.emplace_back();
  for (size_t k = 0; k < corners.size(); ++k) {
    const int id = static_cast<int>(k) + 1;
    w.facts.vertices[id] = corners[k];
    CurveFact c;
    c.id = id;
    c.start = id;
    c.end = static_cast<int>((k + 1) % corners.size()) + 1;
    const Vec3& a = corners[k];
    const Vec3& b = corners[(k + 1) % corners.size()];
    for (int s = 0; s <= 4; ++s) c.samples.push_back(a + (b - a) * (s / 4.0));
    c.length = (b - a).norm();
    w.facts.curves[id] = c;
    f.loops.front().push_back({id, true});
    // The sides along x (odd ids) run along the caps.
    if (k % 2 == 0) w.lattice.along.insert(id);
  }
  f.angles = angles;
  w.facts.faces.push_back(f);
  w.facts.known_size = 10.77;
  w.lattice.sides = {1};
  w.lattice.ok = true;
  return w;
}

// Whether every row holds for these counts (curve id -> intervals).
bool all_hold(const std::vector<IntervalRow>& rows, const std::map<int, int>& counts) {
  for (const IntervalRow& r : rows) {
    long sum = 0;
    for (const auto& [c, k] : r.terms) sum += static_cast<long>(k) * counts.at(c);
    EXPECT_EQ(r.sense, intervals::Sense::GreaterEqual);
    if (sum < r.rhs) return false;
  }
  return true;
}

TEST(CooperColumnOrder, ANotchsCornerKeepsBeforeTheOppositeNotchsCorner) {
  const NotchedWall w = notched_wall();
  const auto rows = column_order_rows(w.facts, w.lattice, Vec3(0, 0, 1), "volume 1 (cooper)");
  ASSERT_FALSE(rows.empty());
  // The top notch's corner at x = 5 has column n1 + n3 + n5 - n7, the
  // bottom notch's at x = 5.5 column n1: n7 >= n3 + n5.
  bool found = false;
  for (const IntervalRow& r : rows) {
    found = found || r.terms == std::map<int, int>{{3, -1}, {5, -1}, {7, 1}};
    EXPECT_NE(r.label.find("side surface 1"), std::string::npos) << r.label;
  }
  EXPECT_TRUE(found);
  // Counts by length at size 0.5: every corner where it lies.
  EXPECT_TRUE(all_hold(rows, {{1, 11}, {3, 5}, {5, 4}, {7, 10}, {9, 6}, {11, 4}}));
  // The pocket floor given 9 intervals and the top rim past it 7: the
  // notch's corner falls two columns past the other notch's (the rims
  // still close: 11 + 5 + 4 = 7 + 9 + 4).
  EXPECT_FALSE(all_hold(rows, {{1, 11}, {3, 5}, {5, 4}, {7, 7}, {9, 9}, {11, 4}}));
  // Equal columns are allowed: the corners are half an element apart.
  EXPECT_TRUE(all_hold(rows, {{1, 10}, {3, 5}, {5, 4}, {7, 9}, {9, 6}, {11, 4}}));
}

TEST(CooperColumnOrder, TheSweepsDirectionEitherWayGivesTheSameRows) {
  const NotchedWall w = notched_wall();
  const auto up = column_order_rows(w.facts, w.lattice, Vec3(0, 0, 1), "v");
  const auto down = column_order_rows(w.facts, w.lattice, Vec3(0, 0, -1), "v");
  ASSERT_EQ(up.size(), down.size());
  for (size_t k = 0; k < up.size(); ++k) EXPECT_EQ(up[k].terms, down[k].terms);
}

TEST(CooperWallWalk, TurnsAtEveryCornerFromTheFirstRimAlong) {
  const NotchedWall w = notched_wall();
  const std::vector<WallStep> walk = wall_walk(w.facts.faces.front(), w.lattice);
  ASSERT_EQ(walk.size(), 12u);
  // Bottom +i, up, notch +i, down, +i, up the right edge, top -i, down
  // into the notch, its floor -i, up, -i, down the left edge.
  const std::vector<int> dirs = {0, 1, 0, 3, 0, 1, 2, 3, 2, 1, 2, 3};
  for (size_t k = 0; k < walk.size(); ++k) {
    EXPECT_EQ(walk[k].use, k);
    EXPECT_EQ(walk[k].dir, dirs[k]) << k;
    EXPECT_EQ(walk[k].along, k % 2 == 0) << k;
  }
  EXPECT_TRUE(upright_wall(w.facts, w.facts.faces.front(), w.lattice, Vec3(0, 0, 1), 1e-6));
  const NotchedWall slanted = notched_wall(1.0);
  EXPECT_FALSE(upright_wall(slanted.facts, slanted.facts.faces.front(), slanted.lattice,
                            Vec3(0, 0, 1), 1e-6));
  // A rim read as a curve between the rims: the roles disagree, no walk.
  NotchedWall wrong = notched_wall();
  wrong.lattice.along.erase(3);
  EXPECT_TRUE(wall_walk(wrong.facts.faces.front(), wrong.lattice).empty());
}

TEST(CooperColumnOrder, ASlantedWallGivesNoRows) {
  // Its corners seen along the sweep are not its columns' feet.
  const NotchedWall w = notched_wall(1.0);
  EXPECT_TRUE(column_order_rows(w.facts, w.lattice, Vec3(0, 0, 1), "v").empty());
}

TEST(CooperColumnOrder, AWallWithoutRimsAlongGivesNoRows) {
  NotchedWall w = notched_wall();
  w.lattice.along.clear();
  EXPECT_TRUE(column_order_rows(w.facts, w.lattice, Vec3(0, 0, 1), "v").empty());
}

}  // namespace
}  // namespace cooperage::cooper
