// The journal reader: the document, the <cooperage> root and its sections in
// order (<plugin>*, <geometry>, <mesh>?, <block|sideset|nodeset>*, <quality>*, <export>*,
// <report>*). The sections live in journal_geometry.cpp, journal_mesh.cpp and journal_groups.cpp;
// attribute parsing in journal_xml.cpp.
#include "framework/io/journal_reader.h"

#include "framework/core/error.h"
#include "framework/core/text.h"
#include "framework/io/journal_xml.h"
#include "framework/quality/metric.h"

#include <tinyxml2.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <iterator>
#include <utility>

namespace cooperage::io {

namespace {

using detail::Element;

const std::vector<std::string> kRootElements = {"plugin",  "geometry", "mesh",   "block", "sideset",
                                                "nodeset", "quality",  "export", "report"};
const char* const kRootOrder =
    "<plugin>*, <geometry>, <mesh>?, <block>/<sideset>/<nodeset>* (in "
    "any order), <quality>*, <export>*, <report>*";

bool is_group(const std::string& tag) {
  return tag == "block" || tag == "sideset" || tag == "nodeset";
}

// Position in the order of sections; the three groups share one.
int rank_of(const std::string& tag) {
  const std::string key = is_group(tag) ? "block" : tag;
  return static_cast<int>(std::find(kRootElements.begin(), kRootElements.end(), key) -
                          kRootElements.begin());
}
const std::vector<std::string> kMetrics = {"scaled_jacobian",  "jacobian",   "skew", "taper",
                                           "aspect_frobenius", "edge_ratio", "shape"};
const std::vector<std::string> kExportExtensions = {".exo", ".msh", ".vtu", ".inp",
                                                    ".obj", ".off", ".stl", ".ply"};
const std::vector<std::string> kBinaryExtensions = {".vtu", ".msh", ".stl", ".ply"};
const std::vector<std::string> kReportExtensions = {".html", ".htm"};

/// A file name ending in the extension `tail` (lower case), in any case:
/// "X.EXO" is an Exodus file, as the writers and the CAD import agree.
bool ends_with(const std::string& s, const std::string& tail) {
  if (s.size() <= tail.size()) return false;
  return std::equal(
      tail.begin(), tail.end(), s.end() - static_cast<long>(tail.size()),
      [](char t, char c) { return t == std::tolower(static_cast<unsigned char>(c)); });
}

std::string shortest(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

QualityCheck read_quality(const Element& e) {
  e.allow_attributes({"metric", "min", "max", "action"});
  e.expect_empty();
  QualityCheck q;
  e.required("metric");
  q.metric = kMetrics[*e.choice("metric", {"scaled_jacobian", "jacobian", "skew", "taper",
                                           "aspect_frobenius", "edge_ratio", "shape"})];
  q.min = e.number("min", detail::NumberKind::Any);
  q.max = e.number("max", detail::NumberKind::Any);
  if (!q.min && !q.max) e.fail("needs \"min\", \"max\" or both");
  if (q.min && q.max && *q.min > *q.max)
    e.fail("\"min\" (" + clip(*e.text("min")) + ") is greater than \"max\" (" +
           clip(*e.text("max")) + ")");
  // A threshold no element can meet fails every run whatever the mesh: a
  // typing slip (e.g. min="65536" for the scaled Jacobian), refused here.
  const quality::Range can = quality::attainable_range(*quality::metric_from_string(q.metric));
  if (q.min && *q.min > can.hi)
    e.fail_at("min", "\"min\" (" + clip(*e.text("min")) + ") is above every value " + q.metric +
                         " can take (at most " + shortest(can.hi) + ")");
  if (q.max && *q.max < can.lo)
    e.fail_at("max", "\"max\" (" + clip(*e.text("max")) + ") is below every value " + q.metric +
                         " can take (at least " + shortest(can.lo) + ")");
  if (e.choice("action", {"warn", "fail"}).value_or(0) == 1) q.action = QualityCheck::Action::Fail;
  q.where = e.where();
  return q;
}

ExportSetting read_export(const Element& e) {
  e.allow_attributes({"file", "encoding"});
  e.expect_empty();
  ExportSetting x{e.required("file"), e.where()};
  if (std::none_of(kExportExtensions.begin(), kExportExtensions.end(),
                   [&](const std::string& ext) { return ends_with(x.file, ext); }))
    e.fail_at("file", "attribute \"file\" must end in one of " + detail::list(kExportExtensions) +
                          " (the extension picks the format), got \"" + clip_path(x.file) + "\"");
  x.binary = e.choice("encoding", {"ascii", "binary"}).value_or(0) == 1;
  if (x.binary && std::none_of(kBinaryExtensions.begin(), kBinaryExtensions.end(),
                               [&](const std::string& ext) { return ends_with(x.file, ext); }))
    e.fail_at("encoding",
              "encoding=\"binary\" is for .vtu, .msh, .stl and .ply files (Exodus is "
              "always binary; Abaqus .inp, .obj and .off always text), got \"" +
                  clip_path(x.file) + "\"");
  return x;
}

ReportSetting read_report(const Element& e) {
  e.allow_attributes({"file"});
  e.expect_empty();
  ReportSetting r{e.required("file"), e.where()};
  if (std::none_of(kReportExtensions.begin(), kReportExtensions.end(),
                   [&](const std::string& ext) { return ends_with(r.file, ext); }))
    e.fail_at("file", "attribute \"file\" must end in one of " + detail::list(kReportExtensions) +
                          " (the report is an HTML page), got \"" + clip_path(r.file) + "\"");
  return r;
}

// The library's path relative to the journal's directory; its existence is
// checked when it is loaded (framework/scheme/plugin_loader.h).
PluginSetting read_plugin(const Element& e, const std::string& base_dir) {
  e.allow_attributes({"file"});
  e.expect_empty();
  PluginSetting p{e.required("file"), {}, e.where()};
  const std::filesystem::path f(p.file);
  p.path = f.is_absolute() || base_dir.empty()
               ? p.file
               : (std::filesystem::path(base_dir) / f).lexically_normal().string();
  return p;
}

void read_root(const Element& root, Job& job) {
  if (std::string(root.name()) != "cooperage")
    root.fail("the root element must be <cooperage version=\"1\">");
  // xmlns* and xsi:* let editors find docs/cooperage-journal.xsd.
  const auto version = root.text("version");
  if (!version) root.fail("missing required attribute \"version\" (use version=\"1\")");
  if (*version != "1")
    root.fail_at("version", "unsupported version \"" + clip(*version) +
                                "\"; this release reads version=\"1\"");

  std::map<std::string, int> seen;  // section -> line of its first occurrence
  std::string last;                 // the last section read
  for (const Element& e : root.children()) {
    const std::string tag = e.name();
    const auto rank = std::find(kRootElements.begin(), kRootElements.end(), tag);
    if (rank == kRootElements.end())
      e.fail("unknown element in <cooperage>" + detail::suggestion(tag, kRootElements, "<", ">") +
             "; allowed, in this order: " + kRootOrder);
    if ((tag == "geometry" || tag == "mesh") && seen.count(tag))
      e.fail("appears twice; the first is at line " + std::to_string(seen[tag]));
    if (!last.empty() && rank_of(tag) < rank_of(last))
      e.fail("must come before <" + last + "> (line " + std::to_string(seen[last]) +
             "); the order is " + kRootOrder);
    if (tag != "geometry" && tag != "plugin" && !seen.count("geometry"))
      e.fail("comes before <geometry>; a journal starts with <geometry> (after any <plugin>)");
    seen.emplace(tag, e.line());
    last = tag;
    if (tag == "plugin") {
      PluginSetting p = read_plugin(e, job.base_dir);
      for (const auto& other : job.plugins)
        if (other.path == p.path)
          e.fail("plug-in \"" + clip_path(p.file) + "\" is already loaded at line " +
                 std::to_string(other.where.line));
      job.plugins.push_back(std::move(p));
    } else if (tag == "geometry") {
      detail::read_geometry(e, job);
    } else if (is_group(tag)) {
      detail::read_group(e, job.groups);
    } else if (tag == "mesh") {
      job.mesh = detail::read_mesh(e);
    } else if (tag == "quality") {
      QualityCheck q = read_quality(e);
      for (const auto& other : job.quality)
        if (other.metric == q.metric && other.action == q.action)
          e.fail("metric \"" + q.metric + "\" with this action is already checked at line " +
                 std::to_string(other.where.line));
      job.quality.push_back(std::move(q));
    } else if (tag == "report") {
      ReportSetting r = read_report(e);
      for (const auto& other : job.reports)
        if (other.file == r.file)
          e.fail("file \"" + clip_path(r.file) + "\" is already a report at line " +
                 std::to_string(other.where.line));
      job.reports.push_back(std::move(r));
    } else {
      ExportSetting x = read_export(e);
      for (const auto& other : job.exports)
        if (other.file == x.file)
          e.fail("file \"" + clip_path(x.file) + "\" is already exported at line " +
                 std::to_string(other.where.line));
      job.exports.push_back(std::move(x));
    }
  }
  if (!seen.count("geometry")) root.fail("needs a <geometry> element");
}

/// Root attributes: version, plus namespace declarations and xsi:* hints.
void check_root_attributes(const tinyxml2::XMLElement* root, const Element& e) {
  for (auto* a = root->FirstAttribute(); a; a = a->Next()) {
    const std::string name = a->Name();
    if (name == "version" || name == "xmlns" || name.rfind("xmlns:", 0) == 0 ||
        name.rfind("xsi:", 0) == 0)
      continue;
    e.fail_at(a->Name(), "unknown attribute \"" + clip(name, 40) + "\"" +
                             detail::suggestion(name, {"version"}, "\"", "\"") +
                             "; allowed: version (and xmlns/xsi declarations)");
  }
}

}  // namespace

Job parse_journal(const std::string& xml_text, const std::string& file_name_for_messages,
                  const std::string& base_dir) {
  const std::string& file = file_name_for_messages;
  tinyxml2::XMLDocument doc;
  if (doc.Parse(xml_text.data(), xml_text.size()) != tinyxml2::XML_SUCCESS) {
    // ErrorStr() is "Error=NAME ErrorID=.. Line number=N: detail"; keep NAME and detail.
    std::string detail = doc.ErrorStr();
    const size_t colon = detail.find(": ", detail.find("Line number="));
    detail = colon == std::string::npos ? std::string() : ": " + clip(detail.substr(colon + 2));
    std::string hint;
    if (doc.ErrorID() == tinyxml2::XML_ERROR_MISMATCHED_ELEMENT)
      hint = " (an element opened here is not closed, or closed by the wrong tag)";
    throw MeshingError(
        ErrorCode::ParseError,
        detail::at(file, doc.ErrorLineNum()) + "malformed XML, " + doc.ErrorName() + detail + hint);
  }
  const tinyxml2::XMLElement* root = doc.RootElement();
  if (!root)
    throw MeshingError(ErrorCode::ParseError,
                       detail::at(file, 1) + "the journal has no root element");
  Job job;
  job.file = file;
  job.base_dir = base_dir;
  const Element root_element(root, file);
  if (std::string(root->Name()) == "cooperage") check_root_attributes(root, root_element);
  read_root(root_element, job);
  return job;
}

Job read_journal(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::exists(path, ec))
    throw MeshingError(ErrorCode::FileNotFound, "journal \"" + path + "\" does not exist");
  if (fs::is_directory(path, ec))
    throw MeshingError(ErrorCode::FileNotFound, "journal \"" + path + "\" is a directory");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw MeshingError(ErrorCode::FileNotFound, "cannot open journal \"" + path + "\"");
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (in.bad()) throw MeshingError(ErrorCode::FileNotFound, "cannot read journal \"" + path + "\"");
  fs::path dir = fs::absolute(path, ec).lexically_normal().parent_path();
  if (ec) dir = fs::path(path).parent_path();
  return parse_journal(text, path, dir.string());
}

}  // namespace cooperage::io
