// An element size as a length or "D/N" (io/element_size.h), read from text
// and from a journal's <mesh size>.
#include "framework/io/element_size.h"

#include "framework/core/error.h"
#include "framework/io/journal_reader.h"
#include "journal_text.h"

#include <gtest/gtest.h>

#include <string>

namespace cooperage::io {
namespace {

TEST(ElementSize, ALengthOrTheDiagonalOverN) {
  const auto length = parse_element_size("2.5");
  ASSERT_TRUE(length);
  EXPECT_EQ(length->value, 2.5);
  EXPECT_FALSE(length->of_diagonal);
  for (const char* text : {"D/40", "d/40", " D / 40 ", "D/4e1", "D/40.0"}) {
    const auto fraction = parse_element_size(text);
    ASSERT_TRUE(fraction) << text;
    EXPECT_EQ(fraction->value, 40.0) << text;
    EXPECT_TRUE(fraction->of_diagonal) << text;
  }
}

TEST(ElementSize, AnythingElseIsNotASize) {
  for (const char* text : {"", " ", "D", "D/", "D40", "D/0", "D/-4", "D/nan", "D/inf", "D/40x",
                           "2.5mm", "0", "-1", "nan", "inf", "E/40", "D//40", "40/D"}) {
    EXPECT_FALSE(parse_element_size(text)) << "'" << text << "'";
  }
}

TEST(ElementSize, SettingOneKindClearsTheOther) {
  MeshSettings s;
  set_element_size(s, {40.0, true});
  EXPECT_FALSE(s.size);
  EXPECT_EQ(s.size_divisor, 40.0);
  set_element_size(s, 2.0);
  EXPECT_EQ(s.size, 2.0);
  EXPECT_FALSE(s.size_divisor);
}

TEST(ElementSize, AJournalsMeshSizeMayBeTheDiagonalOverN) {
  const Job job =
      parse_journal(testing::journal(R"(<brick name="b" size="1 1 1"/>)", R"(<mesh size="D/20"/>)"),
                    "job.xml", "/base");
  ASSERT_TRUE(job.mesh);
  EXPECT_FALSE(job.mesh->size);
  EXPECT_EQ(job.mesh->size_divisor, 20.0);
  try {
    parse_journal(testing::journal(R"(<brick name="b" size="1 1 1"/>)", R"(<mesh size="D/x"/>)"),
                  "job.xml", "/base");
    ADD_FAILURE() << "D/x was accepted";
  } catch (const MeshingError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("job.xml:"), std::string::npos) << what;
    EXPECT_NE(what.find("attribute \"size\" must be a positive number or D/N"), std::string::npos)
        << what;
  }
}

}  // namespace
}  // namespace cooperage::io
