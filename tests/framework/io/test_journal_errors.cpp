// Journal reader: every bad journal fails with the right code and a message
// that names the file, the line and the element.
#include "framework/io/journal_reader.h"

#include "framework/core/error.h"
#include "journal_text.h"

#include <gtest/gtest.h>

#include <initializer_list>
#include <string>

namespace cooperage::io {
namespace {

/// Parses `xml` as "job.xml" and expects a MeshingError with `code` whose
/// message contains every string in `parts`.
void expect_error(const std::string& xml, ErrorCode code,
                  std::initializer_list<std::string> parts) {
  try {
    parse_journal(xml, "job.xml", "/base");
    ADD_FAILURE() << "no error for:\n" << xml;
  } catch (const MeshingError& e) {
    EXPECT_EQ(e.code(), code) << e.what();
    for (const auto& part : parts)
      EXPECT_NE(std::string(e.what()).find(part), std::string::npos)
          << "message \"" << e.what() << "\" lacks \"" << part << "\"";
  }
}

/// A journal whose <geometry> holds `ops` (starting on line 3) followed by `rest`.
using testing::journal;

const std::string kBrick = R"(<brick name="b" size="1 1 1"/>)";

TEST(JournalErrors, MalformedXmlIsAParseErrorWithFileAndLine) {
  expect_error(
      "<cooperage version=\"1\">\n<geometry>\n<brick name=\"b\" size=\"1 1 1\">\n"
      "</geometry>\n</cooperage>\n",
      ErrorCode::ParseError, {"job.xml:", "malformed XML"});
  try {
    parse_journal(
        "<cooperage version=\"1\">\n<geometry>\n<brick name=\"b\" size=\"1 1 1\">\n"
        "</geometry>\n</cooperage>\n",
        "job.xml", ".");
  } catch (const MeshingError& e) {
    // tinyxml2 reports the line of the element left open
    EXPECT_EQ(std::string(e.what()).rfind("job.xml:3: ", 0), 0u) << e.what();
    EXPECT_NE(std::string(e.what()).find("brick"), std::string::npos) << e.what();
  }
  expect_error("", ErrorCode::ParseError, {"job.xml:"});
  expect_error("<cooperage version=\"1\"><geometry>", ErrorCode::ParseError, {"job.xml:1"});
}

TEST(JournalErrors, MissingFileIsFileNotFound) {
  try {
    read_journal("/nonexistent/dir/job.xml");
    ADD_FAILURE();
  } catch (const MeshingError& e) {
    EXPECT_EQ(e.code(), ErrorCode::FileNotFound);
    EXPECT_NE(std::string(e.what()).find("/nonexistent/dir/job.xml"), std::string::npos);
  }
  try {
    read_journal(COOPERAGE_SOURCE_DIR);  // a directory
    ADD_FAILURE();
  } catch (const MeshingError& e) {
    EXPECT_EQ(e.code(), ErrorCode::FileNotFound);
  }
}

TEST(JournalErrors, UnknownElementIsNamedWithItsLine) {
  expect_error(journal("<bric name=\"b\" size=\"1 1 1\"/>"), ErrorCode::InvalidInput,
               {"job.xml:3:", "<bric>", "unknown element", "did you mean <brick>", "<cylinder>"});
  expect_error(journal(kBrick, "<meshes size=\"1\"/>"), ErrorCode::InvalidInput,
               {"job.xml:5:", "<meshes>", "did you mean <mesh>"});
  expect_error(journal(kBrick, "<mesh><edge id=\"1\" size=\"1\"/></mesh>"), ErrorCode::InvalidInput,
               {"job.xml:5:", "<edge>", "<curve>"});
  expect_error(
      journal("<prism name=\"p\" direction=\"0 0 1\"><profile points=\"0 0 0, 1 0 0, 0 1 0\"/>"
              "<loop points=\"0 0 0, 1 0 0, 0 1 0\"/></prism>"),
      ErrorCode::InvalidInput, {"job.xml:3:", "<loop>", "<hole>"});
  expect_error("<journal version=\"1\"/>", ErrorCode::InvalidInput,
               {"job.xml:1:", "<journal>", "<cooperage"});
}

TEST(JournalErrors, UnknownAttributeIsNamed) {
  expect_error(journal("<brick name=\"b\" sise=\"1 1 1\"/>"), ErrorCode::InvalidInput,
               {"job.xml:3:", "<brick>", "unknown attribute \"sise\"", "did you mean \"size\"",
                "allowed: name, origin, size"});
  expect_error(journal(kBrick, "<export file=\"a.exo\" format=\"exodus\"/>"),
               ErrorCode::InvalidInput, {"job.xml:5:", "<export>", "\"format\""});
  expect_error(journal(kBrick, "<export file=\"a.exo\" encoding=\"binary\"/>"),
               ErrorCode::InvalidInput, {"job.xml:5:", "<export>", "encoding", "a.exo"});
  expect_error(journal(kBrick, "<export file=\"a.vtu\" encoding=\"base64\"/>"),
               ErrorCode::InvalidInput, {"job.xml:5:", "<export>", "encoding", "base64"});
  expect_error(
      "<cooperage version=\"1\" author=\"me\"><geometry>" + kBrick + "</geometry></cooperage>",
      ErrorCode::InvalidInput, {"<cooperage>", "\"author\""});
}

TEST(JournalErrors, NegativeSizeNamesElementAndLine) {
  expect_error(journal("<brick name=\"b\" size=\"1 -2 3\"/>"), ErrorCode::InvalidInput,
               {"job.xml:3: <brick>: attribute \"size\" must be three positive numbers between "
                "1e-7 and 1e7, got \"1 -2 3\""});
  expect_error(journal(kBrick, "<mesh size=\"-0.5\"/>"), ErrorCode::InvalidInput,
               {"job.xml:5: <mesh>:", "\"size\"", "positive", "-0.5"});
  expect_error(journal(kBrick, "<mesh>\n<curve id=\"1\" size=\"0\"/></mesh>"),
               ErrorCode::InvalidInput, {"job.xml:6: <curve>:", "\"size\""});
  expect_error(journal(kBrick, "<mesh>\n<curve id=\"1\" intervals=\"0\"/></mesh>"),
               ErrorCode::InvalidInput,
               {"job.xml:6: <curve>:", "\"intervals\"", "positive integer"});
  expect_error(journal("<cylinder name=\"c\" radius=\"-1\" height=\"1\"/>"),
               ErrorCode::InvalidInput, {"job.xml:3: <cylinder>:", "\"radius\""});
  expect_error(journal("<sphere name=\"s\" radius=\"0\"/>"), ErrorCode::InvalidInput,
               {"<sphere>", "\"radius\""});
  expect_error(journal(kBrick + "<scale shape=\"b\" factor=\"-2\"/>"), ErrorCode::InvalidInput,
               {"<scale>", "\"factor\""});
}

TEST(JournalErrors, BadVectorsAndNumbers) {
  expect_error(journal("<brick name=\"b\" origin=\"1 2\" size=\"1 1 1\"/>"),
               ErrorCode::InvalidInput, {"job.xml:3:", "<brick>", "\"origin\"", "\"1 2\""});
  expect_error(journal("<cylinder name=\"c\" axis=\"0 0 0\" radius=\"1\" height=\"1\"/>"),
               ErrorCode::InvalidInput, {"<cylinder>", "\"axis\"", "nonzero"});
  expect_error(journal("<brick name=\"b\" size=\"1 nan 1\"/>"), ErrorCode::InvalidInput,
               {"\"size\"", "nan"});
  expect_error(journal("<brick name=\"b\" size=\"1 inf 1\"/>"), ErrorCode::InvalidInput,
               {"\"size\""});
  expect_error(journal("<brick name=\"b\" size=\"1 1e999 1\"/>"), ErrorCode::InvalidInput,
               {"\"size\""});
  expect_error(journal("<brick name=\"b\" size=\"1 1 1 1\"/>"), ErrorCode::InvalidInput,
               {"\"size\""});
  expect_error(journal("<brick name=\"b\" size=\"1,1,1\"/>"), ErrorCode::InvalidInput,
               {"\"size\""});
  for (const char* bad : {"+-1", "--1", "0x10", "1e", "e5", ".", "-", "1..2", "infinity"})
    expect_error(journal(std::string("<sphere name=\"s\" radius=\"") + bad + "\"/>"),
                 ErrorCode::InvalidInput, {"\"radius\"", bad});
  expect_error(journal("<sphere name=\"s\" radius=\"1cm\"/>"), ErrorCode::InvalidInput,
               {"\"radius\"", "\"1cm\""});
  expect_error(journal(kBrick, "<mesh threads=\"two\"/>"), ErrorCode::InvalidInput,
               {"\"threads\""});
  expect_error(journal("<import name=\"i\" file=\"a.step\" heal=\"yes\"/>"),
               ErrorCode::InvalidInput, {"\"heal\"", "\"true\" or \"false\""});
}

TEST(JournalErrors, MissingRequiredAttribute) {
  expect_error(journal("<brick name=\"b\"/>"), ErrorCode::InvalidInput,
               {"job.xml:3: <brick>:", "missing required attribute \"size\""});
  expect_error(journal("<brick size=\"1 1 1\"/>"), ErrorCode::InvalidInput, {"\"name\""});
  expect_error("<cooperage><geometry>" + kBrick + "</geometry></cooperage>",
               ErrorCode::InvalidInput, {"\"version\""});
  expect_error("<cooperage version=\"2\"><geometry>" + kBrick + "</geometry></cooperage>",
               ErrorCode::InvalidInput, {"version \"2\""});
}

TEST(JournalErrors, ShapeReferences) {
  expect_error(journal(kBrick + "\n<fuse name=\"f\" inputs=\"b c\"/>"), ErrorCode::InvalidInput,
               {"job.xml:4: <fuse>:", "\"c\"", "not defined"});
  expect_error(journal("<translate shape=\"b\" by=\"1 0 0\"/>\n" + kBrick), ErrorCode::InvalidInput,
               {"job.xml:3: <translate>:", "\"b\"", "not defined"});
  expect_error(
      journal(kBrick + "\n<brick name=\"c\" size=\"1 1 1\"/>\n<cut name=\"d\" inputs=\"b c\"/>\n"
                       "<translate shape=\"c\" by=\"1 0 0\"/>"),
      ErrorCode::InvalidInput, {"job.xml:6: <translate>:", "\"c\"", "consumed", "line 5"});
  expect_error(journal(kBrick + "\n<sphere name=\"b\" radius=\"1\"/>"), ErrorCode::InvalidInput,
               {"job.xml:4: <sphere>:", "\"b\"", "already defined at line 3"});
  expect_error(journal(kBrick + "\n<fuse name=\"f\" inputs=\"b\"/>"), ErrorCode::InvalidInput,
               {"<fuse>", "two or more"});
  expect_error(journal(kBrick + "\n<fuse name=\"f\" inputs=\"b b\"/>"), ErrorCode::InvalidInput,
               {"<fuse>", "distinct"});
  expect_error(journal("<brick name=\"1b\" size=\"1 1 1\"/>"), ErrorCode::InvalidInput,
               {"<brick>", "\"name\""});
}

TEST(JournalErrors, DuplicateSettingsNameBothLines) {
  expect_error(
      journal(kBrick,
              "<mesh>\n<volume id=\"1\" size=\"1\"/>\n<volume id=\"1\" scheme=\"map\"/>\n</mesh>"),
      ErrorCode::InvalidInput, {"job.xml:7: <volume>:", "volume 1", "line 6"});
  expect_error(
      journal(kBrick,
              "<mesh>\n<curve id=\"2\" size=\"1\"/>\n<curve id=\"2\" size=\"2\"/>\n</mesh>"),
      ErrorCode::InvalidInput, {"job.xml:7: <curve>:", "curve 2", "line 6"});
  expect_error(journal(kBrick,
                       "<mesh>\n<vertex_type surface=\"1\" vertex=\"2\" type=\"end\"/>\n"
                       "<vertex_type surface=\"1\" vertex=\"2\" type=\"side\"/>\n</mesh>"),
               ErrorCode::InvalidInput, {"job.xml:7:", "line 6"});
  expect_error(journal(kBrick, "<export file=\"a.exo\"/>\n<export file=\"a.exo\"/>"),
               ErrorCode::InvalidInput, {"job.xml:6: <export>:", "line 5"});
  expect_error(
      journal(kBrick,
              "<quality metric=\"skew\" max=\"0.5\"/>\n<quality metric=\"skew\" max=\"0.6\"/>"),
      ErrorCode::InvalidInput, {"job.xml:6: <quality>:", "line 5"});
}

TEST(JournalErrors, SectionOrderAndCount) {
  expect_error(journal(kBrick, "<export file=\"a.exo\"/>\n<mesh size=\"1\"/>"),
               ErrorCode::InvalidInput, {"job.xml:6: <mesh>:", "before <export>"});
  expect_error(journal(kBrick, "<mesh size=\"1\"/>\n<mesh size=\"2\"/>"), ErrorCode::InvalidInput,
               {"job.xml:6: <mesh>:", "twice", "line 5"});
  expect_error("<cooperage version=\"1\"><mesh size=\"1\"/></cooperage>", ErrorCode::InvalidInput,
               {"<mesh>", "<geometry>"});
  expect_error("<cooperage version=\"1\"/>", ErrorCode::InvalidInput, {"needs a <geometry>"});
  expect_error(journal(""), ErrorCode::InvalidInput, {"<geometry>", "at least one shape"});
  expect_error(journal("<imprint_merge/>\n" + kBrick), ErrorCode::InvalidInput,
               {"job.xml:3: <imprint_merge>:", "last"});
  expect_error(journal("<brick name=\"b\" size=\"1 1 1\">text</brick>"), ErrorCode::InvalidInput,
               {"<brick>", "text"});
}

TEST(JournalErrors, ProfilesAndShapes) {
  expect_error(
      journal("<prism name=\"p\" direction=\"0 0 1\"><profile points=\"0 0 0, 1 0 0\"/></prism>"),
      ErrorCode::InvalidInput, {"<profile>", "three or more points"});
  expect_error(journal("<prism name=\"p\" direction=\"0 0 1\"><profile points=\"0 0 0, 1 0 0, 2 0 "
                       "0\"/></prism>"),
               ErrorCode::InvalidInput, {"<profile>", "collinear"});
  expect_error(journal("<prism name=\"p\" direction=\"0 0 1\"><profile points=\"0 0 0, 1 0 0, 1 1 "
                       "0, 0 1 1\"/></prism>"),
               ErrorCode::InvalidInput, {"<profile>", "plane"});
  expect_error(journal("<prism name=\"p\" direction=\"1 0 0\"><profile points=\"0 0 0, 1 0 0, 1 1 "
                       "0\"/></prism>"),
               ErrorCode::InvalidInput, {"<prism>", "\"direction\"", "plane of the profile"});
  expect_error(journal("<prism name=\"p\" direction=\"0 0 1\"><profile points=\"0 0 0, 1 0 0, 1 1 "
                       "0, 0 0 0\"/></prism>"),
               ErrorCode::InvalidInput, {"<profile>", "first and last"});
  expect_error(journal("<prism name=\"p\" direction=\"0 0 1\"/>"), ErrorCode::InvalidInput,
               {"<prism>", "<profile>"});
  expect_error(
      journal("<prism name=\"p\" direction=\"0 0 1\"><profile points=\"0 0 0, 4 0 0, 4 4 0\"/>"
              "<hole points=\"1 1 1, 2 1 1, 2 2 1\"/></prism>"),
      ErrorCode::InvalidInput, {"<hole>", "plane of the profile"});
  expect_error(journal("<revolve name=\"r\" axis=\"0 0 1\" angle=\"400\"><profile points=\"1 0 0, "
                       "2 0 0, 2 0 1\"/></revolve>"),
               ErrorCode::InvalidInput, {"<revolve>", "\"angle\""});
  expect_error(journal("<cone name=\"k\" radius1=\"1\" radius2=\"1\" height=\"1\"/>"),
               ErrorCode::InvalidInput, {"<cone>", "<cylinder>"});
  expect_error(journal("<torus name=\"t\" major_radius=\"1\" minor_radius=\"1\"/>"),
               ErrorCode::InvalidInput, {"<torus>", "minor_radius must be less than major_radius"});
  expect_error(journal("<import name=\"i\" file=\"part.stl\"/>"), ErrorCode::InvalidInput,
               {"<import>", "\"file\"", ".step"});
}

TEST(JournalErrors, LoftSections) {
  const std::string sq0 = R"(<section points="0 0 0, 1 0 0, 1 1 0, 0 1 0"/>)";
  const std::string sq1 = R"(<section points="0 0 1, 1 0 1, 1 1 1, 0 1 1"/>)";
  const std::string tri1 = R"(<section points="0 0 1, 1 0 1, 1 1 1"/>)";
  const std::string apex = R"(<section points="0.5 0.5 2"/>)";
  expect_error(journal("<loft name=\"L\">" + sq0 + "</loft>"), ErrorCode::InvalidInput,
               {"job.xml:3:", "<loft>", "at least two <section>"});
  expect_error(journal("<loft name=\"L\">\n" + sq0 + "\n" + tri1 + "\n</loft>"),
               ErrorCode::InvalidInput,
               {"job.xml:5:", "<section>", "same number of points", "compatible wires",
                "line 4 has 4, this one has 3", "ruled=\"false\""});
  expect_error(journal("<loft name=\"L\">" + sq0 + "\n" + apex + "\n" + sq1 + "</loft>"),
               ErrorCode::InvalidInput, {"job.xml:4:", "<section>", "first or the last"});
  expect_error(journal("<loft name=\"L\">" + sq0 +
                       R"(<section points="0 0 1, 1 0 1, 1 1 1, 0 1 1.5"/></loft>)"),
               ErrorCode::InvalidInput, {"<section>", "plane"});
  expect_error(journal("<loft name=\"L\">" + sq0 + R"(<section points="0 0 1, 1 0 1"/></loft>)"),
               ErrorCode::InvalidInput, {"<section>", "one point \"x y z\" or three or more"});
  expect_error(journal("<loft name=\"L\" ruled=\"yes\">" + sq0 + sq1 + "</loft>"),
               ErrorCode::InvalidInput, {"<loft>", "\"ruled\""});
  expect_error(journal("<loft name=\"L\" smooth=\"true\">" + sq0 + sq1 + "</loft>"),
               ErrorCode::InvalidInput, {"<loft>", "unknown attribute \"smooth\"", "ruled"});
  expect_error(journal("<loft name=\"L\">" + sq0 + R"(<section points="0 0 1" id="2"/></loft>)"),
               ErrorCode::InvalidInput, {"<section>", "unknown attribute \"id\""});
  expect_error(
      journal("<loft name=\"L\">" + sq0 + "<profile points=\"0 0 1, 1 0 1, 1 1 1\"/></loft>"),
      ErrorCode::InvalidInput, {"<profile>", "allowed: <section>"});
  expect_error(
      journal("<loft name=\"L\"><section points=\"0 0 0\"/><section points=\"0 0 1\"/></loft>"),
      ErrorCode::InvalidInput, {"<loft>", "at least one polygon"});
  // A smooth loft may change the number of points between sections.
  EXPECT_NO_THROW(parse_journal(
      journal("<loft name=\"L\" ruled=\"false\">" + sq0 + tri1 + "</loft>"), "job.xml", "/base"));
}

TEST(JournalErrors, MeshQualityAndExportSemantics) {
  const auto mesh = [](const std::string& body) {
    return journal(kBrick, "<mesh>\n" + body + "\n</mesh>");
  };
  expect_error(mesh("<curve id=\"1\" size=\"1\" intervals=\"3\"/>"), ErrorCode::InvalidInput,
               {"job.xml:6: <curve>:", "not both"});
  expect_error(mesh("<curve id=\"1\" size=\"1\" ratio=\"1.2\"/>"), ErrorCode::InvalidInput,
               {"<curve>", "\"ratio\"", "bias"});
  expect_error(mesh("<curve id=\"1\" bias=\"geometric\"/>"), ErrorCode::InvalidInput,
               {"<curve>", "\"ratio\"", "\"first_size\""});
  expect_error(mesh("<curve id=\"1\"/>"), ErrorCode::InvalidInput, {"<curve>", "sets nothing"});
  expect_error(mesh("<curve id=\"0\" size=\"1\"/>"), ErrorCode::InvalidInput,
               {"<curve>", "\"id\""});
  // Scheme names are checked against the registry when the run starts
  // (pipeline/check_settings_test.cpp); the reader checks their spelling.
  expect_error(mesh("<surface id=\"1\" scheme=\"sub map\"/>"), ErrorCode::InvalidInput,
               {"<surface>", "\"scheme\"", "a scheme name", "\"sub map\""});
  expect_error(mesh("<volume id=\"1\" scheme=\"\"/>"), ErrorCode::InvalidInput,
               {"<volume>", "\"scheme\""});
  expect_error(mesh("<volume id=\"1\" scheme=\"map\" sources=\"1\"/>"), ErrorCode::InvalidInput,
               {"<volume>", "\"sources\""});
  expect_error(mesh("<volume id=\"1\" sources=\"1 2\" targets=\"2\"/>"), ErrorCode::InvalidInput,
               {"<volume>", "surface 2", "source and a target"});
  expect_error(mesh("<volume id=\"1\" sources=\"1 x\"/>"), ErrorCode::InvalidInput,
               {"<volume>", "\"sources\""});
  expect_error(mesh("<vertex_type surface=\"1\" vertex=\"2\" type=\"corners\"/>"),
               ErrorCode::InvalidInput, {"<vertex_type>", "\"type\"", "\"corner\""});
  expect_error(journal(kBrick, "<quality metric=\"skew\"/>"), ErrorCode::InvalidInput,
               {"job.xml:5: <quality>:", "\"min\"", "\"max\""});
  expect_error(journal(kBrick, "<quality metric=\"skewness\" max=\"1\"/>"), ErrorCode::InvalidInput,
               {"<quality>", "\"metric\"", "\"scaled_jacobian\""});
  expect_error(journal(kBrick, "<quality metric=\"skew\" min=\"0.8\" max=\"0.2\"/>"),
               ErrorCode::InvalidInput, {"<quality>", "greater"});
  // Thresholds no element can meet (campaign case 5926: min="65536").
  expect_error(journal(kBrick, "<quality metric=\"scaled_jacobian\" min=\"65536\"/>"),
               ErrorCode::InvalidInput, {"<quality>", "\"min\" (65536)", "at most 1"});
  expect_error(journal(kBrick, "<quality metric=\"edge_ratio\" max=\"0.5\"/>"),
               ErrorCode::InvalidInput, {"<quality>", "\"max\" (0.5)", "at least 1"});
  expect_error(journal(kBrick, "<quality metric=\"skew\" max=\"-0.1\"/>"), ErrorCode::InvalidInput,
               {"<quality>", "at least 0"});
  expect_error(
      journal(kBrick, "<export file=\"out.step\"/>"), ErrorCode::InvalidInput,
      {"job.xml:5: <export>:", "out.step", ".exo, .msh, .vtu, .inp, .obj, .off, .stl, .ply"});
}

TEST(JournalErrors, ReportFileAndOrder) {
  expect_error(journal(kBrick, "<report file=\"out.pdf\"/>"), ErrorCode::InvalidInput,
               {"job.xml:5: <report>:", "out.pdf", ".html, .htm"});
  expect_error(journal(kBrick, "<report file=\"a.html\"/>\n<report file=\"a.html\"/>"),
               ErrorCode::InvalidInput, {"job.xml:6: <report>:", "already a report at line 5"});
  expect_error(journal(kBrick, "<report file=\"a.html\"/>\n<export file=\"a.exo\"/>"),
               ErrorCode::InvalidInput, {"job.xml:6: <export>:", "must come before <report>"});
  expect_error(journal(kBrick, "<report file=\"a.html\" title=\"x\"/>"), ErrorCode::InvalidInput,
               {"<report>", "\"title\""});
}

}  // namespace
}  // namespace cooperage::io
