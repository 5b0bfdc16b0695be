// render_report / write_report: a self-contained page with every section,
// escaped text, and atomic writes that leave nothing on failure.
#include "framework/report/html_report.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "framework/core/error.h"
#include "framework/report/colormap.h"
#include "framework/report/html_figures.h"
#include "framework/report/html_text.h"

namespace cooperage::report {
namespace {

namespace fs = std::filesystem;

struct TwoHexes {
  std::vector<Eigen::Vector3d> coords;
  std::vector<int> hexes;
  TwoHexes() {
    for (int k = 0; k < 2; ++k)
      for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 3; ++i) coords.emplace_back(i, j, k);
    const auto id = [](int i, int j, int k) { return (k * 2 + j) * 3 + i; };
    for (int i = 0; i < 2; ++i) {
      for (int v : {id(i, 0, 0), id(i + 1, 0, 0), id(i + 1, 1, 0), id(i, 1, 0), id(i, 0, 1),
                    id(i + 1, 0, 1), id(i + 1, 1, 1), id(i, 1, 1)})
        hexes.push_back(v);
    }
  }
  ReportInput input() const {
    ReportInput in;
    in.title = "two <hexes>.step";
    in.coords = &coords;
    ElementBlock b;
    b.name = "volume 1";
    b.part = "volume 1";
    b.scheme = "map";
    b.connectivity = hexes.data();
    b.count = 2;
    b.stride = 8;
    b.seconds = 0.25;
    in.blocks.push_back(b);
    in.plan.push_back({"volume 1",
                       "map",
                       "best applicable, score 1.00",
                       {"+ map score 1.00", "- cooper: no caps"}});
    in.stages = {{"geometry", 0.5}, {"volumes", 1.5}};
    in.warnings = {"surface 3: <script>alert(1)</script> fell back"};
    in.notes = {"wrote out.exo"};
    return in;
  }
};

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(HtmlReport, HasEverySectionAndCountsAndNoExternalResources) {
  const TwoHexes mesh;
  const std::string html = render_report(mesh.input());
  for (const char* part :
       {"<!DOCTYPE html>", "<canvas class=\"mesh\"", "<svg class=\"histogram\"", "id=\"plan\"",
        "id=\"time\"", "id=\"warnings\"", "id=\"notes\"", "best applicable, score 1.00",
        "- cooper: no caps", "<b>12</b> nodes", "<b>2</b> hexes", "wrote out.exo"}) {
    EXPECT_NE(html.find(part), std::string::npos) << part;
  }
  // Two unit cubes: scaled Jacobian 1, in the last of the 40 bins.
  EXPECT_NE(html.find("0.95 to 1.00: 2 elements"), std::string::npos);
  EXPECT_NE(html.find("total</th><th class=\"num\">2.000 s"), std::string::npos);
  // Nothing is fetched: no src/href attributes, no imports, no url() to elsewhere.
  EXPECT_EQ(html.find(" src="), std::string::npos);
  EXPECT_EQ(html.find("href="), std::string::npos);
  EXPECT_EQ(html.find("@import"), std::string::npos);
  EXPECT_FALSE(std::regex_search(html, std::regex("url\\((?!#)")));
  EXPECT_EQ(html.find("<link"), std::string::npos);
}

TEST(HtmlReport, EscapesTextAndKeepsTheDataScriptClosed) {
  const TwoHexes mesh;
  ReportInput in = mesh.input();
  in.blocks[0].part = "volume </script><b>";
  const std::string html = render_report(in);
  EXPECT_EQ(html.find("<script>alert(1)"), std::string::npos);
  EXPECT_NE(html.find("&lt;script&gt;alert(1)&lt;/script&gt;"), std::string::npos);
  EXPECT_NE(html.find("Cooperage report: two &lt;hexes&gt;.step"), std::string::npos);
  // The only "</script>" are the ends of the three script elements.
  std::size_t count = 0;
  for (std::size_t at = html.find("</script>"); at != std::string::npos;
       at = html.find("</script>", at + 1))
    ++count;
  EXPECT_EQ(count, 3u);
}

TEST(HtmlReport, IsDeterministic) {
  const TwoHexes mesh;
  EXPECT_EQ(render_report(mesh.input()), render_report(mesh.input()));
}

TEST(HtmlReport, BadConnectivityThrowsBeforeAnyFileIsWritten) {
  const TwoHexes mesh;
  ReportInput in = mesh.input();
  std::vector<int> bad = mesh.hexes;
  bad[3] = 99;
  in.blocks[0].connectivity = bad.data();
  const fs::path dir =
      fs::temp_directory_path() / ("cooperage-report-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path file = dir / "r.html";
  std::ofstream(file) << "old";
  EXPECT_THROW(write_report(file.string(), in), MeshingError);
  EXPECT_EQ(slurp(file), "old") << "an existing report is never replaced by a broken one";
  std::size_t files = 0;
  for (const auto& e : fs::directory_iterator(dir)) files += e.is_regular_file();
  EXPECT_EQ(files, 1u) << "no temporary file left";
  fs::remove_all(dir);
}

TEST(HtmlReport, UnwritablePathIsFileNotFoundAndLeavesNothing) {
  const TwoHexes mesh;
  const fs::path dir =
      fs::temp_directory_path() / ("cooperage-report-nodir-" + std::to_string(::getpid()));
  try {
    write_report((dir / "r.html").string(), mesh.input());
    ADD_FAILURE() << "no error";
  } catch (const MeshingError& e) {
    EXPECT_EQ(e.code(), ErrorCode::FileNotFound);
    EXPECT_NE(std::string(e.what()).find("r.html"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(dir));
}

TEST(HtmlReport, WritesTheRenderedPage) {
  const TwoHexes mesh;
  const fs::path file =
      fs::temp_directory_path() / ("cooperage-report-ok-" + std::to_string(::getpid()) + ".html");
  write_report(file.string(), mesh.input());
  EXPECT_EQ(slurp(file), render_report(mesh.input()));
  fs::remove(file);
}

TEST(HtmlText, Base64MatchesRfc4648) {
  const auto b64 = [](const std::string& s) {
    return detail::base64(reinterpret_cast<const std::uint8_t*>(s.data()), s.size());
  };
  EXPECT_EQ(b64(""), "");
  EXPECT_EQ(b64("f"), "Zg==");
  EXPECT_EQ(b64("fo"), "Zm8=");
  EXPECT_EQ(b64("foo"), "Zm9v");
  EXPECT_EQ(b64("foob"), "Zm9vYg==");
  EXPECT_EQ(b64("fooba"), "Zm9vYmE=");
  EXPECT_EQ(b64("foobar"), "Zm9vYmFy");
}

TEST(HtmlText, JsonStringEscapes) {
  EXPECT_EQ(detail::json_string("a\"b\\c\n</script>"), "\"a\\\"b\\\\c\\u000a<\\/script>\"");
}

TEST(Colormap, EndsAndInverted) {
  EXPECT_EQ(color_of(1.0), scaled_jacobian_stops().back().rgb);
  EXPECT_EQ(color_of(1e-9), scaled_jacobian_stops().front().rgb);
  EXPECT_EQ(color_of(0.0), inverted_color());
  EXPECT_EQ(color_of(-0.5), inverted_color());
  EXPECT_EQ(hex_color({255, 0, 16}), "#ff0010");
}

TEST(Histogram, CountsEveryValueInItsBin) {
  const auto counts = detail::histogram_counts({-1.0, -0.01, 0.0, 0.49, 1.0, 0.999});
  ASSERT_EQ(counts.size(), static_cast<std::size_t>(detail::kHistogramBins));
  EXPECT_EQ(counts[0], 1u);
  EXPECT_EQ(counts[19], 1u);  // -0.01 in [-0.05, 0)
  EXPECT_EQ(counts[20], 1u);  // 0 in [0, 0.05)
  EXPECT_EQ(counts[29], 1u);  // 0.49 in [0.45, 0.5)
  EXPECT_EQ(counts[39], 2u);  // 0.999 and 1
}

}  // namespace
}  // namespace cooperage::report
