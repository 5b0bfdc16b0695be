// Journal reader: <block>, <sideset>, <nodeset> (the groups solvers see),
// read into Job::groups, and every malformed one refused naming its line.
#include "framework/io/journal_reader.h"

#include "framework/core/error.h"

#include <gtest/gtest.h>

#include <initializer_list>
#include <string>

namespace cooperage::io {
namespace {

// Line 1 <cooperage>, 2-4 geometry, 5 <mesh>, groups from line 6.
std::string groups_journal(const std::string& groups, const std::string& tail = "") {
  return "<cooperage version=\"1\">\n<geometry>\n<brick name=\"b\" size=\"1 1 1\"/>\n"
         "</geometry>\n<mesh size=\"0.5\"/>\n" +
         groups + "\n" + tail + "</cooperage>\n";
}

void expect_error(const std::string& xml, std::initializer_list<std::string> parts) {
  try {
    parse_journal(xml, "job.xml", "/base");
    ADD_FAILURE() << "no error for:\n" << xml;
  } catch (const MeshingError& e) {
    EXPECT_EQ(e.code(), ErrorCode::InvalidInput) << e.what();
    for (const auto& part : parts)
      EXPECT_NE(std::string(e.what()).find(part), std::string::npos)
          << "message \"" << e.what() << "\" lacks \"" << part << "\"";
  }
}

TEST(JournalGroups, ReadsBlocksSideSetsAndNodeSetsWithNamesAndLines) {
  const Job job = parse_journal(groups_journal(R"(<block id="1" name="steel" volumes="1 2"/>
<sideset id="10" name="inlet" surfaces="3"/>
<nodeset id="20" name="fixed" surfaces="4" curves="5 6" vertices="7"/>
<block id="2" volumes="3"/>
<sideset id="11" surfaces="1 2"/>)",
                                               "<export file=\"out.exo\"/>\n"),
                                "job.xml", "/base");
  const GroupSettings& g = job.groups;
  ASSERT_EQ(g.blocks.size(), 2u);
  EXPECT_EQ(g.blocks[0].id, 1);
  EXPECT_EQ(g.blocks[0].name, "steel");
  EXPECT_EQ(g.blocks[0].volumes, (std::vector<int>{1, 2}));
  EXPECT_TRUE(g.blocks[0].surfaces.empty());
  EXPECT_EQ(g.blocks[0].where.line, 6);
  EXPECT_EQ(g.blocks[1].name, "block_2");  // unnamed: the default name
  ASSERT_EQ(g.side_sets.size(), 2u);
  EXPECT_EQ(g.side_sets[0].name, "inlet");
  EXPECT_EQ(g.side_sets[0].surfaces, std::vector<int>{3});
  EXPECT_EQ(g.side_sets[1].name, "sideset_11");
  ASSERT_EQ(g.node_sets.size(), 1u);
  EXPECT_EQ(g.node_sets[0].surfaces, std::vector<int>{4});
  EXPECT_EQ(g.node_sets[0].curves, (std::vector<int>{5, 6}));
  EXPECT_EQ(g.node_sets[0].vertices, std::vector<int>{7});
  EXPECT_EQ(g.node_sets[0].where.line, 8);
  EXPECT_EQ(job.exports.size(), 1u);
}

TEST(JournalGroups, ANodeSetAndASideSetMayShareANameAndAnId) {
  // Cubit habit: sideset 1 "inlet" and nodeset 1 "inlet"; the formats keep
  // the two kinds apart.
  const Job job = parse_journal(groups_journal(R"(<sideset id="1" name="inlet" surfaces="3"/>
<nodeset id="1" name="inlet" surfaces="3"/>)"),
                                "job.xml", "/base");
  EXPECT_EQ(job.groups.side_sets.size(), 1u);
  EXPECT_EQ(job.groups.node_sets.size(), 1u);
}

TEST(JournalGroups, DuplicateIdsAndNamesAreRefusedNamingBothLines) {
  expect_error(groups_journal("<block id=\"1\" volumes=\"1\"/>\n<block id=\"1\" volumes=\"2\"/>"),
               {"job.xml:7:", "<block>", "block id 1 is already used at line 6"});
  expect_error(groups_journal("<sideset id=\"1\" name=\"Top\" surfaces=\"1\"/>\n"
                              "<sideset id=\"2\" name=\"top\" surfaces=\"2\"/>"),
               {"job.xml:7:", "side set name \"top\" is already used at line 6", "ignoring case"});
  // A default name counts too.
  expect_error(groups_journal("<nodeset id=\"3\" surfaces=\"1\"/>\n"
                              "<nodeset id=\"4\" name=\"nodeset_3\" surfaces=\"2\"/>"),
               {"job.xml:7:", "\"nodeset_3\" is already used at line 6"});
}

TEST(JournalGroups, AnEntityInTwoBlocksIsRefused) {
  expect_error(
      groups_journal("<block id=\"1\" volumes=\"1 2\"/>\n<block id=\"2\" volumes=\"3 2\"/>"),
      {"job.xml:7:", "volume 2 is already in block 1 at line 6"});
  expect_error(groups_journal("<block id=\"1\" surfaces=\"4\"/>\n<block id=\"2\" surfaces=\"4\"/>"),
               {"job.xml:7:", "surface 4 is already in block 1 at line 6"});
}

TEST(JournalGroups, MalformedGroupsAreRefusedNamingTheLine) {
  expect_error(groups_journal("<block id=\"1\"/>"),
               {"job.xml:6:", "<block>", "exactly one of \"volumes\"", "\"surfaces\""});
  expect_error(groups_journal("<block id=\"1\" volumes=\"1\" surfaces=\"2\"/>"),
               {"job.xml:6:", "exactly one of"});
  expect_error(groups_journal("<block id=\"0\" volumes=\"1\"/>"), {"job.xml:6:", "\"id\""});
  expect_error(groups_journal("<block id=\"1\" name=\"steel block\" volumes=\"1\"/>"),
               {"job.xml:6:", "\"name\" must be a letter", "steel block"});
  expect_error(groups_journal("<block id=\"1\" name=\"2nd\" volumes=\"1\"/>"),
               {"job.xml:6:", "\"name\""});
  expect_error(
      groups_journal("<block id=\"1\" name=\"" + std::string(33, 'a') + "\" volumes=\"1\"/>"),
      {"job.xml:6:", "at most 32"});
  expect_error(groups_journal("<sideset id=\"1\"/>"), {"job.xml:6:", "<sideset>", "\"surfaces\""});
  expect_error(groups_journal("<sideset id=\"1\" volumes=\"1\"/>"),
               {"job.xml:6:", "unknown attribute", "volumes"});
  expect_error(groups_journal("<nodeset id=\"1\" name=\"n\"/>"),
               {"job.xml:6:", "<nodeset>", "needs \"surfaces\", \"curves\" or \"vertices\""});
  expect_error(groups_journal("<nodeset id=\"1\" curves=\"1 1\"/>"), {"job.xml:6:", "\"curves\""});
}

TEST(JournalGroups, GroupsComeAfterMeshAndBeforeExports) {
  expect_error(
      "<cooperage version=\"1\">\n<geometry>\n<brick name=\"b\" size=\"1 1 1\"/>\n"
      "</geometry>\n<block id=\"1\" volumes=\"1\"/>\n<mesh size=\"1\"/>\n</cooperage>\n",
      {"job.xml:6:", "<mesh>", "must come before <block>"});
  expect_error(groups_journal("<export file=\"a.exo\"/>\n<sideset id=\"1\" surfaces=\"1\"/>"),
               {"job.xml:7:", "<sideset>", "must come before <export>"});
  // Among themselves, any order.
  EXPECT_NO_THROW(parse_journal(groups_journal("<nodeset id=\"1\" surfaces=\"1\"/>\n"
                                               "<block id=\"1\" volumes=\"1\"/>\n"
                                               "<sideset id=\"1\" surfaces=\"1\"/>"),
                                "job.xml", "/base"));
}

}  // namespace
}  // namespace cooperage::io
