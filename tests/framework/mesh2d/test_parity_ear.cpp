// mesh2d::parity_ear: the corner of an odd boundary cut off as a triangle.
#include "framework/mesh2d/parity_ear.h"

#include <gtest/gtest.h>

namespace cooperage::mesh2d {
namespace {

using Loops = std::vector<std::vector<Point2>>;

TEST(ParityEar, AStraightNodeIsNoCorner) {
  // A square with a node in the middle of its bottom edge: four right
  // corners, the first of them taken (ties by index).
  const Loops loops{{{0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}}};
  const auto ear = parity_ear(loops);
  ASSERT_TRUE(ear.has_value());
  EXPECT_EQ(ear->loop, 0u);
  EXPECT_EQ(ear->index, 0u);
}

TEST(ParityEar, TheCornerNearestSixtyDegrees) {
  // A house with a steep roof: its apex is 53 degrees, nearer 60 than the
  // floor's right corners; the eaves are 153.
  const Loops loops{{{0, 0}, {2, 0}, {2, 2}, {1, 4}, {0, 2}}};
  const auto ear = parity_ear(loops);
  ASSERT_TRUE(ear.has_value());
  EXPECT_EQ(ear->index, 3u);
}

TEST(ParityEar, NotACornerWhoseTriangleHoldsAHole) {
  // The corner at the origin would take the hole's nodes into its
  // triangle; the next right corner along the outer loop is free.
  const Loops loops{{{0, 0}, {2, 0}, {4, 0}, {4, 4}, {0, 4}},
                    {{0.6, 0.6}, {0.6, 1.0}, {1.0, 1.0}, {1.0, 0.6}}};
  const auto ear = parity_ear(loops);
  ASSERT_TRUE(ear.has_value());
  EXPECT_EQ(ear->loop, 0u);
  EXPECT_EQ(ear->index, 2u);
}

TEST(ParityEar, NotAReflexCorner) {
  // An L: its inner corner (index 3, 270 degrees) is never an ear, though
  // it is nearer 60 degrees than nothing; right corners are.
  const Loops loops{{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}, {0, 1}}};
  const auto ear = parity_ear(loops);
  ASSERT_TRUE(ear.has_value());
  EXPECT_NE(ear->index, 3u);
  EXPECT_NE(ear->index, 6u);  // straight
}

TEST(ParityEar, NoneOnLoopsTooShortToLoseANode) {
  EXPECT_FALSE(parity_ear(Loops{{{0, 0}, {1, 0}, {0, 1}}}).has_value());
  EXPECT_FALSE(parity_ear(Loops{{{0, 0}, {2, 0}, {2, 2}, {0, 2}}, {{1, 0.5}, {0.5, 1}, {1, 1.5}}})
                   .has_value());
}

}  // namespace
}  // namespace cooperage::mesh2d
