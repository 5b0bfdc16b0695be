#include "quality_command.h"

#include "json_writer.h"

#include "framework/io/read/read_mesh_file.h"
#include "framework/quality/evaluate.h"
#include "framework/quality/summary.h"
#include "framework/report/html_report.h"
#include "framework/report/report_from_file.h"

#include <cstdio>
#include <vector>

namespace cooperage::app {
namespace {

struct BlockReport {
  const io::MeshBlock* block;
  std::vector<quality::MetricSummary> metrics;
};

std::vector<BlockReport> evaluate_blocks(const io::MeshFile& file) {
  std::vector<BlockReport> reports;
  for (const auto& b : file.blocks) {
    BlockReport r{&b, {}};
    const int stride = quality::node_count(b.type);
    for (quality::Metric m : quality::kAllMetrics) {
      if (!quality::is_defined(m, b.type)) continue;
      const auto values =
          quality::evaluate(m, b.type, file.coords, b.connectivity.data(), b.size(), stride);
      r.metrics.push_back(quality::summarize(m, values));
    }
    reports.push_back(std::move(r));
  }
  return reports;
}

std::size_t element_count(const io::MeshFile& file) {
  std::size_t n = 0;
  for (const auto& b : file.blocks) n += b.size();
  return n;
}

void write_text(const std::string& path, const io::MeshFile& file,
                const std::vector<BlockReport>& reports, std::ostream& out) {
  out << path << ": " << file.coords.size() << " nodes, " << element_count(file) << " elements in "
      << file.blocks.size() << " blocks\n";
  for (const auto& [type, count] : file.skipped) {
    out << "skipped " << count << " " << type << " cells\n";
  }
  char line[256];
  for (const auto& r : reports) {
    out << "\nblock \"" << r.block->name << "\": " << r.block->size() << ' '
        << quality::to_string(r.block->type) << '\n';
    std::snprintf(line, sizeof line, "  %-17s %12s %12s %12s %12s %9s\n", "metric", "min", "mean",
                  "max", "median", "inverted");
    out << line;
    for (const auto& s : r.metrics) {
      const bool sj = s.metric == quality::to_string(quality::Metric::ScaledJacobian);
      if (sj) {
        std::snprintf(line, sizeof line, "  %-17s %12.6g %12.6g %12.6g %12.6g %9zu\n",
                      s.metric.c_str(), s.min, s.mean, s.max, s.median, s.inverted);
      } else {
        std::snprintf(line, sizeof line, "  %-17s %12.6g %12.6g %12.6g\n", s.metric.c_str(), s.min,
                      s.mean, s.max);
      }
      out << line;
    }
  }
}

void write_json(const std::string& path, const io::MeshFile& file,
                const std::vector<BlockReport>& reports, std::ostream& out) {
  JsonWriter w(out);
  w.begin_object();
  w.key("file");
  w.value(path);
  w.key("nodes");
  w.value(static_cast<int>(file.coords.size()));
  w.key("elements");
  w.value(static_cast<int>(element_count(file)));
  w.key("skipped");
  w.begin_object();
  for (const auto& [type, count] : file.skipped) {
    w.key(type);
    w.value(static_cast<int>(count));
  }
  w.end_object();
  w.key("blocks");
  w.begin_array();
  for (const auto& r : reports) {
    w.begin_object();
    w.key("name");
    w.value(r.block->name);
    w.key("type");
    w.value(std::string(quality::to_string(r.block->type)));
    w.key("count");
    w.value(static_cast<int>(r.block->size()));
    w.key("metrics");
    w.begin_object();
    for (const auto& s : r.metrics) {
      w.key(s.metric);
      w.begin_object();
      w.key("min");
      w.value(s.min);
      w.key("mean");
      w.value(s.mean);
      w.key("max");
      w.value(s.max);
      if (s.metric == quality::to_string(quality::Metric::ScaledJacobian)) {
        w.key("median");
        w.value(s.median);
        w.key("inverted");
        w.value(static_cast<int>(s.inverted));
      }
      w.end_object();
    }
    w.end_object();
    w.end_object();
  }
  w.end_array();
  w.end_object();
  out << '\n';
}

}  // namespace

int run_quality(const std::string& path, bool json, std::ostream& out, const std::string& html) {
  const io::MeshFile file = io::read_mesh_file(path);
  const auto reports = evaluate_blocks(file);
  if (json)
    write_json(path, file, reports, out);
  else
    write_text(path, file, reports, out);
  if (!html.empty()) {
    report::write_report(html, report::report_input(file, path));
    if (!json) out << "wrote " << html << '\n';
  }
  return 0;
}

}  // namespace cooperage::app
