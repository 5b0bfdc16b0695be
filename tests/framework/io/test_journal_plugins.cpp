// Journal <plugin> elements: read in order before <geometry>, paths made
// relative to the journal's directory (absolute ones kept), the library
// itself checked only when it is loaded; misplaced or repeated ones are errors.
#include "framework/io/journal_reader.h"

#include "framework/core/error.h"

#include <gtest/gtest.h>

#include <string>

namespace cooperage::io {
namespace {

const std::string kGeometry = "<geometry><brick name=\"b\" size=\"1 1 1\"/></geometry>\n";

std::string plugin_error_of(const std::string& xml) {
  try {
    parse_journal(xml, "job.xml", "/jobs/a");
  } catch (const MeshingError& e) {
    EXPECT_EQ(e.code(), ErrorCode::InvalidInput);
    return e.what();
  }
  return {};
}

TEST(JournalPlugins, ReadInOrderRelativeToTheJournal) {
  const Job job = parse_journal(
      "<cooperage version=\"1\">\n"
      "<plugin file=\"lib/libone.so\"/>\n"
      "<plugin file=\"../libtwo.so\"/>\n"
      "<plugin file=\"/opt/p/libthree.so\"/>\n" +
          kGeometry + "</cooperage>\n",
      "job.xml", "/jobs/a");
  ASSERT_EQ(job.plugins.size(), 3u);
  EXPECT_EQ(job.plugins[0].file, "lib/libone.so");
  EXPECT_EQ(job.plugins[0].path, "/jobs/a/lib/libone.so");
  EXPECT_EQ(job.plugins[0].where.line, 2);
  EXPECT_EQ(job.plugins[1].path, "/jobs/libtwo.so");
  EXPECT_EQ(job.plugins[2].path, "/opt/p/libthree.so");
  // A missing library is the loader's error, at run time, not the reader's.
}

TEST(JournalPlugins, AJournalWithoutPluginsHasNone) {
  EXPECT_TRUE(
      parse_journal("<cooperage version=\"1\">" + kGeometry + "</cooperage>", "job.xml", "/jobs/a")
          .plugins.empty());
}

TEST(JournalPlugins, MisplacedRepeatedOrEmptyPluginsAreErrors) {
  std::string m = plugin_error_of("<cooperage version=\"1\">\n" + kGeometry +
                                  "<plugin file=\"libone.so\"/>\n</cooperage>\n");
  EXPECT_NE(m.find("job.xml:3"), std::string::npos) << m;
  EXPECT_NE(m.find("must come before <geometry>"), std::string::npos) << m;
  m = plugin_error_of(
      "<cooperage version=\"1\">\n<plugin file=\"libone.so\"/>\n"
      "<plugin file=\"./libone.so\"/>\n" +
      kGeometry + "</cooperage>\n");
  EXPECT_NE(m.find("job.xml:3"), std::string::npos) << m;
  EXPECT_NE(m.find("already loaded at line 2"), std::string::npos) << m;
  m = plugin_error_of("<cooperage version=\"1\">\n<plugin file=\"\"/>\n" + kGeometry +
                      "</cooperage>\n");
  EXPECT_NE(m.find("job.xml:2: <plugin>: attribute \"file\" must be non-empty"), std::string::npos)
      << m;
  m = plugin_error_of("<cooperage version=\"1\">\n<plugin/>\n" + kGeometry + "</cooperage>\n");
  EXPECT_NE(m.find("file"), std::string::npos) << m;
  m = plugin_error_of("<cooperage version=\"1\">\n<plugin file=\"a.so\">x</plugin>\n" + kGeometry +
                      "</cooperage>\n");
  EXPECT_NE(m.find("<plugin>"), std::string::npos) << m;
}

}  // namespace
}  // namespace cooperage::io
