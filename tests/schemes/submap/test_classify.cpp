// Vertex classification with the loop sum rule, its repair, and the edge
// directions and interval balance that follow from it (value types, no CAD).
#include <gtest/gtest.h>

#include "schemes/submap/classify.h"
#include "schemes/submap/directions.h"

namespace cooperage::submap {
namespace {

constexpr VertexType E = VertexType::End, S = VertexType::Side, C = VertexType::Corner,
                     R = VertexType::Reversal;

std::vector<CornerInput> corners(const std::vector<double>& angles) {
  std::vector<CornerInput> out;
  for (double a : angles) out.push_back({a, std::nullopt});
  return out;
}

TEST(SubmapClassify, LShapeRawTypesObeyTheSumRule) {
  const LoopTypes t = classify_loop(corners({90, 90, 90, 270, 90, 90}), 4);
  ASSERT_TRUE(t.ok) << t.why;
  EXPECT_EQ(t.types, (std::vector<VertexType>{E, E, E, C, E, E}));
  EXPECT_EQ(t.raw_sum, 4);
  EXPECT_EQ(t.changed, 0);
}

TEST(SubmapClassify, HoleLoopNeedsMinusFour) {
  const LoopTypes t = classify_loop(corners({270, 270, 270, 270}), -4);
  ASSERT_TRUE(t.ok) << t.why;
  EXPECT_EQ(t.types, (std::vector<VertexType>{C, C, C, C}));
}

TEST(SubmapClassify, RepairChangesTheMostAmbiguousVertex) {
  // A quadrilateral with one blunt corner at 132 degrees: raw SIDE gives sum 3;
  // the nearest valid classification makes that vertex END, not any other.
  const LoopTypes t = classify_loop(corners({90, 70, 132, 68}), 4);
  ASSERT_TRUE(t.ok) << t.why;
  EXPECT_EQ(t.raw_sum, 3);
  EXPECT_EQ(t.types, (std::vector<VertexType>{E, E, E, E}));
  EXPECT_EQ(t.changed, 1);
  // Same angles, other order: the result follows the vertex, not its index.
  const LoopTypes u = classify_loop(corners({132, 68, 90, 70}), 4);
  ASSERT_TRUE(u.ok);
  EXPECT_EQ(u.types, (std::vector<VertexType>{E, E, E, E}));
}

TEST(SubmapClassify, RepairOfTooManyEndsPicksTheLargestAngle) {
  // Five ENDs (sum 5): the vertex at 128 degrees becomes SIDE (deviation 52),
  // not the ones at 95 (deviation 85).
  const auto types =
      repair_loop({95, 95, 128, 95, 95}, {E, E, E, E, E}, {false, false, false, false, false}, 4);
  ASSERT_TRUE(types);
  EXPECT_EQ(*types, (std::vector<VertexType>{E, E, S, E, E}));
}

TEST(SubmapClassify, RepairTiesAreBrokenByVertexOrder) {
  // Two identical candidates: earlier vertices keep their raw type.
  const auto types =
      repair_loop({90, 90, 90, 128, 128}, {E, E, E, S, S}, {false, false, false, false, false}, 4);
  ASSERT_TRUE(types);
  EXPECT_EQ(*types, (std::vector<VertexType>{E, E, E, S, E}));
}

TEST(SubmapClassify, PinnedTypeIsKept) {
  // A rectangle with one vertex pinned SIDE cannot keep four ENDs; the
  // repair must move another vertex, never the pinned one.
  std::vector<CornerInput> in = corners({90, 90, 90, 90, 180});
  in[0].pinned = S;
  const LoopTypes t = classify_loop(in, 4);
  // Pinned SIDE at 90 plus three ENDs and a SIDE at 180: sum 3, and the
  // 180-degree vertex is 90 away from END, beyond the repair limit.
  EXPECT_FALSE(t.ok);
  EXPECT_NE(t.why.find("loop sum 3, needs 4"), std::string::npos) << t.why;

  std::vector<CornerInput> in2 = corners({90, 90, 90, 90, 150});
  in2[1].pinned = S;
  const LoopTypes t2 = classify_loop(in2, 4);
  ASSERT_TRUE(t2.ok) << t2.why;
  EXPECT_EQ(t2.types, (std::vector<VertexType>{E, S, E, E, E}));

  // A pin that agrees with the sum rule against the angle is kept as is.
  std::vector<CornerInput> in3 = corners({90, 90, 170, 90, 90});
  in3[2].pinned = E;
  in3[3].pinned = S;
  const LoopTypes t3 = classify_loop(in3, 4);
  ASSERT_TRUE(t3.ok) << t3.why;
  EXPECT_EQ(t3.types, (std::vector<VertexType>{E, E, E, S, E}));
}

TEST(SubmapClassify, SharpAndUnrepairableLoopsAreRejectedWithAReason) {
  const LoopTypes sharp = classify_loop(corners({25, 80, 75}), 4);
  EXPECT_FALSE(sharp.ok);
  EXPECT_EQ(sharp.bad_corner, 0);
  EXPECT_NE(sharp.why.find("25 degrees cannot be END/SIDE/CORNER/REVERSAL"), std::string::npos);

  const LoopTypes disk = classify_loop(corners({180}), 4);
  EXPECT_FALSE(disk.ok);
  EXPECT_NE(disk.why.find("loop sum 0, needs 4"), std::string::npos) << disk.why;

  const LoopTypes triangle = classify_loop(corners({60, 60, 60}), 4);
  EXPECT_FALSE(triangle.ok);
  EXPECT_NE(triangle.why.find("loop sum 3, needs 4"), std::string::npos) << triangle.why;
}

TEST(SubmapClassify, ReversalIsAValidType) {
  const LoopTypes t = classify_loop(corners({90, 90, 45.5, 350, 45.5, 90, 90}), 4);
  ASSERT_TRUE(t.ok) << t.why;
  EXPECT_EQ(t.types, (std::vector<VertexType>{E, E, E, R, E, E, E}));
}

TEST(SubmapDirections, LShapeWalk) {
  // L: (0,0) (2,0) (2,1) (1,1) (1,2) (0,2); corner k before use k.
  const std::vector<VertexType> types = {E, E, E, C, E, E};
  const auto d = use_directions(types);
  EXPECT_EQ(d, (std::vector<int>{kPlusI, kPlusJ, kMinusI, kPlusJ, kMinusI, kMinusJ}));
  std::vector<DirectedUse> uses;
  for (size_t k = 0; k < d.size(); ++k) uses.push_back({static_cast<int>(k) + 1, d[k]});
  const auto axes = loop_balance(uses);
  EXPECT_EQ(axes[0], (std::map<int, int>{{1, 1}, {3, -1}, {5, -1}}));
  EXPECT_EQ(axes[1], (std::map<int, int>{{2, 1}, {4, 1}, {6, -1}}));
}

TEST(SubmapDirections, WalkStartsAtTheFirstEnd) {
  const auto d = use_directions({S, E, E, E, E});
  EXPECT_EQ(d[1], kPlusI);
  EXPECT_EQ(d[0], kMinusJ);  // the SIDE keeps the direction of the use before it
  EXPECT_EQ(d[4], kMinusJ);
}

TEST(SubmapDirections, SeamUsesCancel) {
  // A cylinder side: bottom +i, seam +j, top -i, seam -j (same curve 2).
  const auto axes = loop_balance({{1, kPlusI}, {2, kPlusJ}, {3, kMinusI}, {2, kMinusJ}});
  EXPECT_EQ(axes[0], (std::map<int, int>{{1, 1}, {3, -1}}));
  EXPECT_TRUE(axes[1].empty());
}

}  // namespace
}  // namespace cooperage::submap
