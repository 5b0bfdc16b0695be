#include "framework/report/html_report.h"

#include <algorithm>
#include <map>
#include <ostream>
#include <sstream>

#include "framework/io/export/export_common.h"
#include "framework/quality/evaluate.h"
#include "framework/quality/summary.h"
#include "framework/report/html_figures.h"
#include "framework/report/html_text.h"
#include "framework/report/mesh_pictures.h"

namespace cooperage::report {
namespace {

using detail::format_number;
using detail::format_seconds;
using detail::html_escape;
using quality::ElementType;

struct BlockQuality {
  std::vector<double> values;  ///< scaled Jacobian per element
  quality::MetricSummary summary;
};

std::vector<BlockQuality> evaluate_blocks(const ReportInput& input) {
  static const std::vector<Eigen::Vector3d> no_coords;
  const auto& coords = input.coords ? *input.coords : no_coords;
  std::vector<BlockQuality> out;
  for (const ElementBlock& b : input.blocks) {
    quality::EvaluateOptions options;
    if (!b.normals.empty()) options.normals = &b.normals;
    BlockQuality q;
    if (b.count > 0) {
      q.values = quality::evaluate(quality::Metric::ScaledJacobian, b.type, coords, b.connectivity,
                                   b.count, b.stride, options);
    }
    q.summary = quality::summarize(quality::Metric::ScaledJacobian, q.values);
    out.push_back(std::move(q));
  }
  return out;
}

bool is_volume(ElementType t) { return t == ElementType::Hex || t == ElementType::Wedge; }

std::string plural(std::size_t n, const std::string& word) {
  const bool es = !word.empty() && word.back() == 'x';  // hex, hexes
  return std::to_string(n) + " " + word + (n == 1 ? "" : es ? "es" : "s");
}

std::string type_word(ElementType t) {
  switch (t) {
    case ElementType::Hex: return "hex";
    case ElementType::Wedge: return "wedge";
    case ElementType::Quad: return "quad";
    case ElementType::Tri: return "triangle";
  }
  return "element";
}

std::string summary_line(const ReportInput& input, const std::vector<BlockQuality>& quality) {
  std::map<ElementType, std::size_t> counts;
  bool volumes = false;
  for (const auto& b : input.blocks) {
    counts[b.type] += b.count;
    volumes = volumes || (is_volume(b.type) && b.count > 0);
  }
  // The headline quality is over the elements of the highest dimension.
  std::vector<double> all;
  for (std::size_t i = 0; i < input.blocks.size(); ++i) {
    if (is_volume(input.blocks[i].type) != volumes) continue;
    all.insert(all.end(), quality[i].values.begin(), quality[i].values.end());
  }
  const auto s = quality::summarize(quality::Metric::ScaledJacobian, all);
  std::string line = "<b>" + std::to_string(input.coords ? input.coords->size() : 0) + "</b> nodes";
  for (ElementType t :
       {ElementType::Hex, ElementType::Wedge, ElementType::Quad, ElementType::Tri}) {
    if (counts[t] == 0) continue;
    const std::string words = plural(counts[t], type_word(t));  // "12 hexes"
    const std::size_t space = words.find(' ');
    line += " &middot; <b>" + words.substr(0, space) + "</b>" + words.substr(space);
  }
  if (s.count > 0) {
    line += " &middot; scaled Jacobian min <b>" + format_number("%.3f", s.min) + "</b> mean <b>" +
            format_number("%.3f", s.mean) + "</b> max <b>" + format_number("%.3f", s.max) + "</b>";
    line += std::string(" &middot; <b") + (s.inverted ? " class=\"bad\"" : "") + ">" +
            std::to_string(s.inverted) + "</b> inverted";
  }
  double total = 0;
  for (const auto& st : input.stages) total += st.seconds;
  if (!input.stages.empty()) line += " &middot; " + format_seconds(total);
  return line;
}

void write_pictures(std::ostream& out, const std::vector<Picture>& pictures) {
  out << "<section id=\"mesh\"><h2>Mesh</h2>\n";
  if (pictures.empty()) {
    out << "<p>No elements to draw.</p></section>\n";
    return;
  }
  out << "<div class=\"pictures\">\n";
  for (std::size_t i = 0; i < pictures.size(); ++i) {
    const Picture& p = pictures[i];
    out << "<figure><canvas class=\"mesh\" width=\"520\" height=\"400\" data-picture=\"" << i
        << "\" aria-label=\"" << html_escape(p.part) << "\"></canvas><figcaption><b>"
        << html_escape(p.part) << "</b>: " << plural(p.elements, "element") << ", "
        << plural(p.boundary_faces, "boundary face");
    if (p.surface.faces.size() < p.boundary_faces) {
      out << " (drawn simplified to " << p.surface.faces.size()
          << " by vertex clustering to keep the file small; each drawn face shows the lowest "
             "scaled Jacobian of the faces merged into it or around it)";
    }
    out << ". <button type=\"button\" data-edges=\"" << i << "\">edges on/off</button>";
    if (!p.worst.empty()) {
      out << "<br>Worst elements (marked):<ol class=\"worst\">";
      for (const MarkedElement& w : p.worst) {
        out << "<li>" << html_escape(w.block) << " element " << w.index + 1 << ": <span"
            << (w.scaled_jacobian <= 0 ? " class=\"bad\"" : "") << ">"
            << format_number("%.4f", w.scaled_jacobian) << "</span> at ("
            << format_number("%.4g", w.centroid.x()) << ", "
            << format_number("%.4g", w.centroid.y()) << ", "
            << format_number("%.4g", w.centroid.z()) << ")</li>";
      }
      out << "</ol>";
    }
    out << "</figcaption></figure>\n";
  }
  out << "</div>\n<p class=\"hint\">Faces coloured by the scaled Jacobian of their element: "
      << detail::legend_svg()
      << "<br>Drag to rotate, wheel to zoom, double-click to reset. Elements are numbered from 1 "
         "within their block.</p></section>\n";
}

void write_quality(std::ostream& out, const ReportInput& input,
                   const std::vector<BlockQuality>& quality) {
  out << "<section id=\"quality\"><h2>Quality (scaled Jacobian)</h2>\n";
  if (input.blocks.empty()) {
    out << "<p>No elements.</p></section>\n";
    return;
  }
  out << "<table><tr><th>block</th><th>scheme</th><th>type</th><th class=\"num\">elements</th>"
         "<th class=\"num\">min</th><th class=\"num\">mean</th><th class=\"num\">median</th>"
         "<th class=\"num\">max</th><th class=\"num\">inverted</th><th "
         "class=\"num\">time</th></tr>\n";
  for (std::size_t i = 0; i < input.blocks.size(); ++i) {
    const ElementBlock& b = input.blocks[i];
    const auto& s = quality[i].summary;
    out << "<tr><td>" << html_escape(b.name) << "</td><td>" << html_escape(b.scheme) << "</td><td>"
        << quality::to_string(b.type) << "</td><td class=\"num\">" << b.count << "</td>";
    for (double v : {s.min, s.mean, s.median, s.max}) {
      out << "<td class=\"num\">" << (s.count ? format_number("%.4f", v) : "-") << "</td>";
    }
    out << "<td class=\"num" << (s.inverted ? " bad" : "") << "\">" << s.inverted
        << "</td><td class=\"num\">" << (b.seconds ? format_seconds(*b.seconds) : "-")
        << "</td></tr>\n";
  }
  out << "</table>\n<div class=\"histograms\">\n";
  for (std::size_t i = 0; i < input.blocks.size(); ++i) {
    const ElementBlock& b = input.blocks[i];
    const std::string label =
        b.name + ", " + std::string(quality::to_string(b.type)) + ": scaled Jacobian histogram";
    out << "<figure>" << detail::histogram_svg(quality[i].values, label) << "<figcaption>"
        << html_escape(b.name) << ", " << plural(b.count, type_word(b.type))
        << "</figcaption></figure>\n";
  }
  out << "</div></section>\n";
}

void write_plan(std::ostream& out, const std::vector<PlanRow>& plan) {
  if (plan.empty()) return;
  out << "<section id=\"plan\"><h2>Plan</h2>\n<table><tr><th>entity</th><th>scheme</th>"
         "<th>why</th></tr>\n";
  for (const PlanRow& r : plan) {
    out << "<tr><td>" << html_escape(r.entity) << "</td><td>" << html_escape(r.scheme)
        << "</td><td>" << html_escape(r.reason);
    if (!r.details.empty()) {
      out << "<details><summary>" << plural(r.details.size(), "note") << "</summary><pre>";
      for (const auto& d : r.details) out << html_escape(d) << "\n";
      out << "</pre></details>";
    }
    out << "</td></tr>\n";
  }
  out << "</table></section>\n";
}

void write_stages(std::ostream& out, const std::vector<StageTime>& stages) {
  if (stages.empty()) return;
  double total = 0, longest = 0;
  for (const auto& s : stages) {
    total += s.seconds;
    longest = std::max(longest, s.seconds);
  }
  out << "<section id=\"time\"><h2>Time per stage</h2>\n<table><tr><th>stage</th>"
         "<th class=\"num\">time</th><th></th></tr>\n";
  for (const auto& s : stages) {
    const double width = longest > 0 ? 240.0 * s.seconds / longest : 0.0;
    out << "<tr><td>" << html_escape(s.stage) << "</td><td class=\"num\">"
        << format_seconds(s.seconds)
        << "</td><td><div class=\"bar\" style=\"width:" << format_number("%.1f", width)
        << "px\"></div></td></tr>\n";
  }
  out << "<tr><th>total</th><th class=\"num\">" << format_seconds(total)
      << "</th><th></th></tr></table></section>\n";
}

void write_list(std::ostream& out, const char* id, const char* title,
                const std::vector<std::string>& lines) {
  if (lines.empty()) return;
  out << "<section id=\"" << id << "\" class=\"" << id << "\"><h2>" << title << " (" << lines.size()
      << ")</h2><ul>\n";
  for (const auto& l : lines) out << "<li>" << html_escape(l) << "</li>\n";
  out << "</ul></section>\n";
}

void write_document(std::ostream& out, const ReportInput& input, const ReportOptions& options) {
  const auto quality = evaluate_blocks(input);
  std::vector<std::vector<double>> values;
  values.reserve(quality.size());
  for (const auto& q : quality) values.push_back(q.values);
  const auto pictures =
      input.coords ? build_pictures(input, values, options) : std::vector<Picture>{};

  out << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n"
      << "<meta name=\"generator\" content=\"Cooperage\">\n<title>Cooperage report: "
      << html_escape(input.title) << "</title>\n<script>" << detail::error_probe_script()
      << "</script>\n<style>" << detail::page_style() << "</style></head>\n<body>\n";
  out << "<header><h1>Cooperage report: " << html_escape(input.title)
      << "</h1>\n<p class=\"summary\">" << summary_line(input, quality) << "</p></header>\n";
  write_list(out, "warnings", "Warnings", input.warnings);
  write_pictures(out, pictures);
  write_quality(out, input, quality);
  write_plan(out, input.plan);
  write_stages(out, input.stages);
  write_list(out, "notes", "Run", input.notes);
  out << "<script type=\"application/json\" id=\"cooperage-data\">"
      << detail::pictures_json(pictures) << "</script>\n<script>" << detail::viewer_script()
      << "</script>\n</body></html>\n";
}

}  // namespace

std::string render_report(const ReportInput& input, const ReportOptions& options) {
  std::ostringstream out;
  write_document(out, input, options);
  return out.str();
}

void write_report(const std::string& path, const ReportInput& input, const ReportOptions& options) {
  const std::string html = render_report(input, options);  // errors before any file exists
  io::detail::write_text_atomically(path, [&](std::ostream& out) { out << html; });
}

}  // namespace cooperage::report
