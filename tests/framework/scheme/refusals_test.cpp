// Every scheme's refusal joined for a person: the last registered (the most
// general) first, so a line clipped for the terminal shows its reason.
#include "framework/scheme/refusals.h"

#include <gtest/gtest.h>

namespace cooperage::scheme {
namespace {

TEST(JoinRefusals, TheLastRegisteredSchemeLeads) {
  EXPECT_EQ(join_refusals({{"map", "volume map needs 6 mappable surfaces, volume has 9"},
                           {"cooper", "surface 4 cannot be a side"}}),
            "cooper: surface 4 cannot be a side; map: volume map needs 6 mappable surfaces, "
            "volume has 9");
  EXPECT_EQ(join_refusals({{"map", "a"}, {"submap", "b"}, {"pave", "c"}}),
            "pave: c; submap: b; map: a");
}

TEST(JoinRefusals, NoneIsEmpty) {
  EXPECT_EQ(join_refusals({}), "");
  EXPECT_EQ(join_refusals({{"map", "a"}}), "map: a");
}

}  // namespace
}  // namespace cooperage::scheme
