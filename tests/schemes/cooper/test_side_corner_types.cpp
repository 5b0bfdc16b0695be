// Corner types of a side chosen with its neighbours (side_corner_types.h):
// a wall with a notch from its top whose floor corners are 45-degree
// chamfers (a lug with a cone under it, seen on the wall). Its reflex
// corners lie at 225 degrees, between SIDE and CORNER; rounding types two
// of them one way and two the other. The cone beside the chamfers says they
// run between the caps, the tip's cap that the floor runs along them.
#include "schemes/cooper/side_corner_types.h"

#include <gtest/gtest.h>

namespace cooperage::cooper {
namespace {

// Uses of the wall (0,0) -> (10,0) -> (10,10) -> (7,10) -> (7,5) -> (6,4)
// -> (4,4) -> (3,5) -> (3,10) -> (0,10); the corner before each use.
const std::vector<double> kWall = {90, 90, 90, 90, 225.1, 224.9, 224.9, 225.1, 90, 90};

// The directions agree with `decided`: a use runs along exactly when its
// direction has the typing's parity.
void expect_agrees(const SideTyping& t, const std::vector<int>& decided) {
  for (size_t k = 0; k < decided.size(); ++k) {
    if (decided[k] < 0) continue;
    EXPECT_EQ(t.directions[k] % 2 == t.parity, decided[k] == 1) << "use " << k;
  }
}

TEST(SideCornerTypes, TheAnglesOwnTypesWhenTheyAgree) {
  const std::vector<int> decided = {1, 0, 1, 0};
  const auto t = type_side_corners({90, 90, 90, 90}, decided);
  ASSERT_TRUE(t);
  EXPECT_EQ(t->turns, (std::vector<int>{1, 1, 1, 1}));
  expect_agrees(*t, decided);
  EXPECT_FALSE(has_ambiguous_corner({90, 90, 90, 90}));
  EXPECT_TRUE(has_ambiguous_corner(kWall));
  EXPECT_TRUE(can_turn_four(kWall));
  EXPECT_FALSE(can_turn_four({90, 90, 90}));         // three right angles turn by three
  EXPECT_TRUE(can_turn_four({90, 90, 90, 140, 90}));  // 140 as a SIDE
}

TEST(SideCornerTypes, AChamferedNotchTakesTheTypesItsNeighboursNeed) {
  // bottom, top and the notch's floor along; the chamfers between.
  const std::vector<int> decided = {1, -1, 1, -1, 0, 1, 0, -1, 1, -1};
  const auto t = type_side_corners(kWall, decided);
  ASSERT_TRUE(t);
  // SIDE where the chamfer continues the notch's side, CORNER at the floor.
  EXPECT_EQ(t->turns, (std::vector<int>{1, 1, 1, 1, 0, -1, -1, 0, 1, 1}));
  expect_agrees(*t, decided);
  // The same wall under a neighbour that runs the chamfers along the caps.
  const std::vector<int> flat = {1, -1, 1, -1, 1, 1, 1, -1, 1, -1};
  const auto f = type_side_corners(kWall, flat);
  ASSERT_TRUE(f);
  EXPECT_EQ(f->turns, (std::vector<int>{1, 1, 1, 1, -1, 0, 0, -1, 1, 1}));
  expect_agrees(*f, flat);
}

TEST(SideCornerTypes, NoTypingWhenTheNeighboursContradictTheCorners) {
  // Two uses along the caps on either side of a right-angled corner.
  EXPECT_FALSE(type_side_corners({90, 90, 90, 90}, {1, 1, -1, -1}));
  // Along, along, between, between: a right angle is no SIDE (90 degrees
  // off; a corner is retyped by 60 at most).
  EXPECT_FALSE(type_side_corners({90, 90, 90, 90}, {1, 1, 0, 0}));
}

}  // namespace
}  // namespace cooperage::cooper
