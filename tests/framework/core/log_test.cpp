#include "framework/core/log.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace cooperage::log {

TEST(Log, ThresholdFiltersLowerLevels) {
  std::vector<std::string> lines;
  set_sink([&](Level, const std::string& line) { lines.push_back(line); });
  set_threshold(Level::Warning);
  info("hidden");
  warning("shown");
  error("also shown");
  set_threshold(Level::Debug);
  debug("now shown");
  set_threshold(Level::Off);
  error("never");
  EXPECT_EQ(lines, (std::vector<std::string>{"shown", "also shown", "now shown"}));
  set_sink(nullptr);
  set_threshold(Level::Warning);
}

}  // namespace cooperage::log
