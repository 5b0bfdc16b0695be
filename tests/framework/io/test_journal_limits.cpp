// Journal values are bounded (issue 21, 3c and 4): numbers in normal range,
// integers and names bounded, and no error echoes more than a line of input.
#include "framework/io/journal_reader.h"

#include "framework/core/error.h"
#include "journal_text.h"

#include <gtest/gtest.h>

#include <string>

namespace cooperage::io {
namespace {

using testing::journal;

std::string error_of(const std::string& xml) {
  try {
    parse_journal(xml, "job.xml", "/base");
  } catch (const MeshingError& e) {
    EXPECT_NE(e.code(), ErrorCode::Internal);
    return e.what();
  }
  return "";
}

TEST(JournalLimits, DenormalAndHugeNumbersAreRefused) {
  // The issue's cases: a denormal radius passed "positive"; a cylinder at
  // 1e300 hung the kernel's boolean.
  EXPECT_NE(error_of(journal(R"(<cylinder name="c" radius="4.9e-324" height="1"/>)"))
                .find("positive number between 1e-7 and 1e7"),
            std::string::npos);
  EXPECT_NE(error_of(journal(R"(<cylinder name="c" base="1e300 0 0" radius="1" height="1"/>)"))
                .find("three numbers"),
            std::string::npos);
  EXPECT_NE(error_of(journal(R"(<brick name="b" size="1e8 1 1"/>)")).find("attribute \"size\""),
            std::string::npos);
  EXPECT_NE(error_of(journal(R"(<brick name="b" size="1 1 1"/>)", R"(<mesh size="1e-9"/>)"))
                .find("attribute \"size\""),
            std::string::npos);
  // Ordinary values still pass, zero included.
  EXPECT_EQ(error_of(journal(R"(<brick name="b" origin="0 -1e6 2.5e-3" size="1e-3 1e6 1"/>)",
                             R"(<mesh size="1e-7"/>)")),
            "");
}

TEST(JournalLimits, IntegersAreBounded) {
  const std::string msg =
      error_of(journal(R"(<brick name="b" size="1 1 1"/>)",
                       R"(<mesh size="1"><curve id="1" intervals="2147483647"/></mesh>)"));
  EXPECT_NE(msg.find("positive integer up to 1e9"), std::string::npos) << msg;
  EXPECT_EQ(error_of(journal(R"(<brick name="b" size="1 1 1"/>)",
                             R"(<mesh size="1"><curve id="1" intervals="65535"/></mesh>)")),
            "");
}

TEST(JournalLimits, ShapeNamesAreAtMost64Characters) {
  EXPECT_EQ(error_of(journal("<brick name=\"" + std::string(64, 'n') + "\" size=\"1 1 1\"/>")), "");
  const std::string msg =
      error_of(journal("<brick name=\"" + std::string(100000, 'n') + "\" size=\"1 1 1\"/>"));
  EXPECT_NE(msg.find("at most 64 characters"), std::string::npos);
  EXPECT_LT(msg.size(), 300u) << "a 100 KB name is not echoed";
}

TEST(JournalLimits, NoErrorEchoesMoreThanALineOfInput) {
  const std::string big(10000, 'x');
  for (const std::string& xml : {
           journal("<" + big + "/>"),  // a 10,000-character tag
           journal("<brick name=\"b\" size=\"1 1 1\" " + big + "=\"1\"/>"),  // attribute name
           journal("<brick name=\"b\" size=\"" + big + "\"/>"),              // attribute value
           journal("<brick name=\"b\" size=\"1 1 1\">" + big + "</brick>"),  // text
           journal(R"(<brick name="b" size="1 1 1"/>)", "<export file=\"" + big + ".step\"/>"),
           // A report path of the wrong extension, a report and a plug-in named twice.
           journal(R"(<brick name="b" size="1 1 1"/>)", "<report file=\"" + big + "\"/>"),
           journal(R"(<brick name="b" size="1 1 1"/>)",
                   "<report file=\"" + big + ".html\"/><report file=\"" + big + ".html\"/>"),
           "<cooperage version=\"1\"><plugin file=\"" + big + "\"/><plugin file=\"" + big +
               "\"/></cooperage>",
           "<cooperage version=\"" + big + "\"/>",
           "<" + big + ">",
       }) {
    const std::string msg = error_of(xml);
    EXPECT_FALSE(msg.empty());
    EXPECT_LT(msg.size(), 400u) << msg.substr(0, 200);
    EXPECT_EQ(msg.find('\n'), std::string::npos);
  }
}

TEST(JournalLimits, MeshLimitsAreRead) {
  const Job job = parse_journal(
      journal(R"(<brick name="b" size="1 1 1"/>)",
              R"(<mesh size="1" max_elements="5000" volume_tolerance="2.5" threads="64"/>)"),
      "job.xml", "/base");
  ASSERT_TRUE(job.mesh);
  EXPECT_EQ(job.mesh->max_elements, 5000.0);
  EXPECT_DOUBLE_EQ(*job.mesh->volume_tolerance, 0.025);
  EXPECT_EQ(job.mesh->threads, 64);  // capped at the hardware's when meshing
  EXPECT_NE(error_of(journal(R"(<brick name="b" size="1 1 1"/>)",
                             R"(<mesh size="1" volume_tolerance="150"/>)"))
                .find("in percent and at most 100"),
            std::string::npos);
  EXPECT_NE(
      error_of(journal(R"(<brick name="b" size="1 1 1"/>)", R"(<mesh size="1" max_elements="0"/>)"))
          .find("max_elements"),
      std::string::npos);
}

}  // namespace
}  // namespace cooperage::io
