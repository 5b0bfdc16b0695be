// The imprinting dump (COOPERAGE_DEBUG_IMPRINT): nothing is written without
// the variable; with it, both ends go to JSON with every node's position
// to the last bit, every subcap's loops, the ribs, the fixed nodes and why
// imprinting stopped.
#include "schemes/cooper/imprint_debug.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <unistd.h>

namespace cooperage::cooper {
namespace {

namespace fs = std::filesystem;

std::string text_of(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// A square upper subcap over a square lower one, unit corners.
BarrelEnds two_squares() {
  BarrelEnds e;
  for (int k = 0; k < 4; ++k) {
    const Vec2 p(k == 1 || k == 2 ? 1.0 : 0.0, k >= 2 ? 1.0 / 3.0 : 0.0);
    e.xy[1 + k] = p;
    e.xy[5 + k] = p;
    e.ribs.push_back({1 + k, 5 + k});
    e.fixed.insert(1 + k);
  }
  e.upper.push_back({7, {{1, 2, 3, 4}}});
  e.lower.push_back({9, {{5, 6, 7, 8}}});
  return e;
}

class ImprintDebug : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("cooperage-imprint-debug-" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override {
    ::unsetenv("COOPERAGE_DEBUG_IMPRINT");
    ::unsetenv("COOPERAGE_DEBUG_IMPRINT_STEPS");
    fs::remove_all(dir_);
  }
  fs::path dir_;
};

TEST_F(ImprintDebug, NothingIsWrittenWithoutTheVariable) {
  ::unsetenv("COOPERAGE_DEBUG_IMPRINT");
  const BarrelEnds in = two_squares();
  EXPECT_FALSE(write_imprint_debug("b1", in, imprint_subcaps(in)));
  EXPECT_TRUE(fs::is_empty(dir_));
}

TEST_F(ImprintDebug, BothEndsAreWrittenWithTheReason) {
  ::setenv("COOPERAGE_DEBUG_IMPRINT", dir_.c_str(), 1);
  const BarrelEnds in = two_squares();
  ImprintResult out = imprint_subcaps(in);
  ASSERT_TRUE(out.ok) << out.why;
  out.why = "a reason with \"quotes\"";
  out.ok = false;
  ASSERT_TRUE(write_imprint_debug("volume1-barrel2", in, out));
  const std::string before = text_of(dir_ / "volume1-barrel2-in.json");
  const std::string after = text_of(dir_ / "volume1-barrel2-out.json");
  // 1/3 to 17 significant digits reads back as the same double.
  EXPECT_NE(before.find("\"3\": [1, 0.33333333333333331]"), std::string::npos) << before;
  EXPECT_NE(before.find("\"upper\": [{\"id\": 7, \"loops\": [[1, 2, 3, 4]]}]"), std::string::npos)
      << before;
  EXPECT_NE(before.find("\"lower\": [{\"id\": 9, \"loops\": [[5, 6, 7, 8]]}]"), std::string::npos)
      << before;
  EXPECT_NE(before.find("\"ribs\": [[1, 5], [2, 6], [3, 7], [4, 8]]"), std::string::npos) << before;
  EXPECT_NE(before.find("\"fixed\": [1, 2, 3, 4]"), std::string::npos) << before;
  EXPECT_NE(before.find("\"why\": \"\""), std::string::npos) << before;
  EXPECT_NE(after.find("\"why\": \"a reason with \\\"quotes\\\"\""), std::string::npos) << after;
}

// With COOPERAGE_DEBUG_IMPRINT_STEPS, the ends before every step are
// written too: the first as given, the last with the ribs the steps made.
TEST_F(ImprintDebug, EveryStepsEndsAreWrittenWhenAsked) {
  ::setenv("COOPERAGE_DEBUG_IMPRINT", dir_.c_str(), 1);
  EXPECT_EQ(imprint_debug_steps(), 0);
  ::setenv("COOPERAGE_DEBUG_IMPRINT_STEPS", "50", 1);
  ASSERT_EQ(imprint_debug_steps(), 50);
  ImprintOptions options;
  options.trace_steps = imprint_debug_steps();
  const BarrelEnds in = two_squares();
  const ImprintResult out = imprint_subcaps(in, options);
  ASSERT_TRUE(out.ok) << out.why;
  ASSERT_FALSE(out.trace.empty());
  EXPECT_EQ(out.trace.front().second, "start");
  ASSERT_TRUE(write_imprint_debug("volume1-barrel1", in, out));
  for (size_t k = 0; k < out.trace.size(); ++k)
    EXPECT_TRUE(fs::exists(dir_ / ("volume1-barrel1-step" + std::to_string(k) + ".json"))) << k;
  EXPECT_FALSE(
      fs::exists(dir_ / ("volume1-barrel1-step" + std::to_string(out.trace.size()) + ".json")));
  const std::string first = text_of(dir_ / "volume1-barrel1-step0.json");
  EXPECT_NE(first.find("\"why\": \"before step 0, after start\""), std::string::npos) << first;
  EXPECT_NE(first.find("\"ribs\": [[1, 5], [2, 6], [3, 7], [4, 8]]"), std::string::npos) << first;
}

}  // namespace
}  // namespace cooperage::cooper
