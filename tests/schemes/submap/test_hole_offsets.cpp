// rank_hole_offsets: nearest offsets first; ties in distance broken by the
// lattice offsets alone, whatever the noise in the prediction.
#include <gtest/gtest.h>

#include "schemes/submap/hole_offsets.h"

namespace cooperage::submap {
namespace {

TEST(HoleOffsets, NearestFirst) {
  const auto r = rank_hole_offsets(Vec2(2.2, 3.9), {0, 0}, {5, 5});
  ASSERT_EQ(r.size(), 36u);
  EXPECT_EQ(r.front(), (LatticePoint{2, 4}));
  EXPECT_EQ(r[1], (LatticePoint{3, 4}));
}

TEST(HoleOffsets, HalfIntegerTiesIgnoreNoise) {
  // The exact tie at (3.5, 2) between i = 3 and i = 4, perturbed either way.
  for (double noise : {0.0, 1e-13, -1e-13, 1e-9, -1e-9}) {
    SCOPED_TRACE(noise);
    const auto r = rank_hole_offsets(Vec2(3.5 + noise, 2.0 - noise), {0, 0}, {6, 6});
    ASSERT_GE(r.size(), 2u);
    EXPECT_EQ(r[0], (LatticePoint{3, 2}));
    EXPECT_EQ(r[1], (LatticePoint{4, 2}));
  }
  // Four-way tie at a cell centre.
  for (double noise : {0.0, 3e-12, -3e-12}) {
    const auto r = rank_hole_offsets(Vec2(1.5 - noise, 1.5 + noise), {0, 0}, {3, 3});
    ASSERT_GE(r.size(), 4u);
    EXPECT_EQ(r[0], (LatticePoint{1, 1}));
    EXPECT_EQ(r[1], (LatticePoint{1, 2}));
    EXPECT_EQ(r[2], (LatticePoint{2, 1}));
    EXPECT_EQ(r[3], (LatticePoint{2, 2}));
  }
}

TEST(HoleOffsets, EmptyBoxGivesNothing) {
  EXPECT_TRUE(rank_hole_offsets(Vec2(0, 0), {2, 0}, {1, 3}).empty());
  EXPECT_EQ(rank_hole_offsets(Vec2(9, 9), {1, 1}, {1, 1}).size(), 1u);
}

}  // namespace
}  // namespace cooperage::submap
