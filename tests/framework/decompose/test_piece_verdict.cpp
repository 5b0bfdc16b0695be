// piece_verdict.h: the clause of a refusal a person acts on.
#include "framework/decompose/piece_verdict.h"

#include <gtest/gtest.h>

namespace cooperage::decompose {
namespace {

TEST(DecidingReason, CoopersFurthestSortingWhenItReportsOne) {
  const std::string why =
      "map: volume 1: volume map needs 6 mappable surfaces, volume has 16; cooper: volume 1: no "
      "sorting of its faces into caps and sides gives barrels (the one that got furthest: along "
      "(0, 1, 0): surface 1 cannot be a side (surface 1: loop sum 6, needs 4 (no classification "
      "within 80 degrees of the angles repairs it)))";
  EXPECT_EQ(deciding_reason(why),
            "along (0, 1, 0): surface 1 cannot be a side (surface 1: loop sum 6, needs 4 (no "
            "classification within 80 degrees of the angles repairs it))");
}

TEST(DecidingReason, TheWholeRefusalOtherwise) {
  const std::string why = "map: volume 1: volume map needs 6 mappable surfaces, volume has 8";
  EXPECT_EQ(deciding_reason(why), why);
  // Cut short before its parenthesis closes: what there is.
  EXPECT_EQ(deciding_reason("cooper: x (the one that got furthest: along (1, 0, 0): surface 2"),
            "along (1, 0, 0): surface 2");
}

}  // namespace
}  // namespace cooperage::decompose
