// Loops of a real cap merged with the rims of flush virtual caps beside it
// (Blacker 1996, sec. 4 Fig. 8d): value types only.
#include "schemes/cooper/loop_nodes.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace cooperage::cooper {
namespace {

// A U-shaped cap whose loop runs into a notch along 1-8-9-2, and the notch's
// rim 1-10-2 (the flush wall) given the other way round: the shared notch
// edges cancel; the merged loop keeps the real cap's direction.
TEST(MergeLoops, SharedEdgesCancelAndTheReferenceDirectionIsKept) {
  const std::vector<std::vector<int>> cap{{0, 1, 8, 9, 2, 7, 3, 4, 5, 6}};
  const std::vector<std::vector<int>> rim{{1, 10, 2, 9, 8}};
  const auto merged = merge_loops(cap, rim);
  ASSERT_EQ(merged.size(), 1u);
  std::vector<int> loop = merged.front();
  std::rotate(loop.begin(), std::find(loop.begin(), loop.end(), 0), loop.end());
  EXPECT_EQ(loop, (std::vector<int>{0, 1, 10, 2, 7, 3, 4, 5, 6}));
}

TEST(MergeLoops, APinchIsNotASimpleLoop) {
  // Two squares touching at node 2 only.
  EXPECT_TRUE(merge_loops({{0, 1, 2, 3}}, {{2, 4, 5, 6}}).empty());
}

}  // namespace
}  // namespace cooperage::cooper
