#include "json_writer.h"

#include <gtest/gtest.h>

#include <sstream>

namespace cooperage::app {

TEST(JsonWriter, NestsObjectsAndArraysWithCommas) {
  std::ostringstream out;
  JsonWriter j(out);
  j.begin_object();
  j.key("a");
  j.value(1);
  j.key("b");
  j.value(std::vector<int>{1, 2});
  j.key("c");
  j.begin_array();
  j.begin_object();
  j.key("s");
  j.value("x\"y");
  j.end_object();
  j.value(true);
  j.end_array();
  j.end_object();
  EXPECT_EQ(out.str(), R"({"a":1,"b":[1,2],"c":[{"s":"x\"y"},true]})");
}

TEST(JsonWriter, NonFiniteNumbersBecomeNull) {
  std::ostringstream out;
  JsonWriter j(out);
  j.value(std::vector<double>{0.5, 1.0 / 0.0});
  EXPECT_EQ(out.str(), "[0.5,null]");
}

}  // namespace cooperage::app
