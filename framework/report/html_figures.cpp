#include "framework/report/html_figures.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "framework/report/colormap.h"
#include "framework/report/html_text.h"

namespace cooperage::report::detail {

std::vector<std::size_t> histogram_counts(const std::vector<double>& values) {
  std::vector<std::size_t> counts(kHistogramBins, 0);
  for (double v : values) {
    if (std::isnan(v)) continue;
    const double t = (std::clamp(v, -1.0, 1.0) + 1.0) / 2.0 * kHistogramBins;
    counts[std::min<std::size_t>(static_cast<std::size_t>(t), kHistogramBins - 1)]++;
  }
  return counts;
}

std::string histogram_svg(const std::vector<double>& values, const std::string& label) {
  const auto counts = histogram_counts(values);
  const std::size_t peak =
      std::max<std::size_t>(1, *std::max_element(counts.begin(), counts.end()));
  constexpr double W = 340, H = 140, left = 44, right = 8, top = 10, bottom = 22;
  const double plot_w = W - left - right, plot_h = H - top - bottom;
  const double bar = plot_w / kHistogramBins;
  std::string s = "<svg class=\"histogram\" xmlns=\"http://www.w3.org/2000/svg\" width=\"" +
                  format_number("%g", W) + "\" height=\"" + format_number("%g", H) +
                  "\" viewBox=\"0 0 " + format_number("%g", W) + " " + format_number("%g", H) +
                  "\" role=\"img\" aria-label=\"" + html_escape(label) + "\">";
  s += "<rect x=\"" + format_number("%g", left) + "\" y=\"" + format_number("%g", top) +
       "\" width=\"" + format_number("%g", plot_w) + "\" height=\"" + format_number("%g", plot_h) +
       "\" fill=\"#fafafa\" stroke=\"#ccc\"/>";
  for (int b = 0; b < kHistogramBins; ++b) {
    if (counts[b] == 0) continue;
    const double lo = -1.0 + 2.0 * b / kHistogramBins, hi = lo + 2.0 / kHistogramBins;
    const double h =
        std::max(1.0, plot_h * static_cast<double>(counts[b]) / static_cast<double>(peak));
    s += "<rect x=\"" + format_number("%.2f", left + b * bar) + "\" y=\"" +
         format_number("%.2f", top + plot_h - h) + "\" width=\"" +
         format_number("%.2f", bar - 0.5) + "\" height=\"" + format_number("%.2f", h) +
         "\" fill=\"" + hex_color(color_of(hi <= 0 ? 0.0 : (lo + hi) / 2)) + "\"><title>" +
         format_number("%.2f", lo) + " to " + format_number("%.2f", hi) + ": " +
         std::to_string(counts[b]) + " elements</title></rect>";
  }
  for (double tick : {-1.0, -0.5, 0.0, 0.5, 1.0}) {
    const double x = left + (tick + 1.0) / 2.0 * plot_w;
    s += "<line x1=\"" + format_number("%.1f", x) + "\" x2=\"" + format_number("%.1f", x) +
         "\" y1=\"" + format_number("%g", top + plot_h) + "\" y2=\"" +
         format_number("%g", top + plot_h + 4) + "\" stroke=\"#666\"/>";
    s += "<text x=\"" + format_number("%.1f", x) + "\" y=\"" + format_number("%g", H - 6) +
         "\" text-anchor=\"middle\">" + format_number("%g", tick) + "</text>";
  }
  s += "<text x=\"" + format_number("%g", left - 4) + "\" y=\"" + format_number("%g", top + 9) +
       "\" text-anchor=\"end\">" + std::to_string(peak) + "</text>";
  s += "<text x=\"" + format_number("%g", left - 4) + "\" y=\"" +
       format_number("%g", top + plot_h) + "\" text-anchor=\"end\">0</text>";
  return s + "</svg>";
}

std::string legend_svg() {
  std::string s =
      "<svg class=\"legend\" xmlns=\"http://www.w3.org/2000/svg\" width=\"360\" height=\"40\" "
      "viewBox=\"0 0 360 40\" role=\"img\" aria-label=\"colour scale of the scaled Jacobian\">"
      "<defs><linearGradient id=\"sj-scale\" x1=\"0\" x2=\"1\" y1=\"0\" y2=\"0\">";
  for (const ColorStop& stop : scaled_jacobian_stops()) {
    s += "<stop offset=\"" + format_number("%g", stop.value) + "\" stop-color=\"" +
         hex_color(stop.rgb) + "\"/>";
  }
  s += "</linearGradient></defs>";
  s += "<rect x=\"0\" y=\"4\" width=\"40\" height=\"14\" fill=\"" + hex_color(inverted_color()) +
       "\"/><text x=\"20\" y=\"34\" text-anchor=\"middle\">&#8804; 0</text>";
  s += "<rect x=\"60\" y=\"4\" width=\"290\" height=\"14\" fill=\"url(#sj-scale)\"/>";
  for (double tick : {0.0, 0.25, 0.5, 0.75, 1.0}) {
    s += "<text x=\"" + format_number("%.1f", 60 + 290 * tick) +
         "\" y=\"34\" text-anchor=\"middle\">" + format_number("%g", tick) + "</text>";
  }
  return s + "</svg>";
}

namespace {

std::string number_array(const Eigen::Vector3d& v) {
  return "[" + format_number("%.9g", v.x()) + "," + format_number("%.9g", v.y()) + "," +
         format_number("%.9g", v.z()) + "]";
}

std::string picture_json(const Picture& pic) {
  const FaceSoup& soup = pic.surface;
  Eigen::Vector3d lo = Eigen::Vector3d::Zero(), hi = Eigen::Vector3d::Zero();
  if (!soup.points.empty()) {
    lo = hi = soup.points.front();
    for (const auto& p : soup.points) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
  }
  std::vector<std::uint16_t> pos;
  pos.reserve(soup.points.size() * 3);
  for (const auto& p : soup.points) {
    for (int c = 0; c < 3; ++c) {
      const double span = hi[c] - lo[c];
      const double t = span > 0 ? (p[c] - lo[c]) / span : 0.0;
      pos.push_back(static_cast<std::uint16_t>(std::lround(std::clamp(t, 0.0, 1.0) * 65535.0)));
    }
  }
  const bool small = soup.points.size() < 0xffff;
  std::string idx;
  if (small) {
    std::vector<std::uint16_t> v;
    for (const auto& f : soup.faces) {
      for (int k : f) v.push_back(k < 0 ? 0xffff : static_cast<std::uint16_t>(k));
    }
    idx = base64_of(v);
  } else {
    std::vector<std::uint32_t> v;
    for (const auto& f : soup.faces) {
      for (int k : f) v.push_back(k < 0 ? 0xffffffffu : static_cast<std::uint32_t>(k));
    }
    idx = base64_of(v);
  }
  std::vector<std::uint8_t> sj;
  for (double v : soup.values) {
    const double t = std::isnan(v) ? 0.0 : (std::clamp(v, -1.0, 1.0) + 1.0) / 2.0;
    sj.push_back(static_cast<std::uint8_t>(std::lround(t * 255.0)));
  }
  std::string s = "{\"part\":" + json_string(pic.part) +
                  ",\"points\":" + std::to_string(soup.points.size()) +
                  ",\"faces\":" + std::to_string(soup.faces.size()) +
                  ",\"lo\":" + number_array(lo) + ",\"hi\":" + number_array(hi) + ",\"pos\":\"" +
                  base64_of(pos) + "\",\"idxType\":\"" + (small ? "u16" : "u32") + "\",\"idx\":\"" +
                  idx + "\",\"sj\":\"" + base64_of(sj) + "\",\"worst\":[";
  for (std::size_t i = 0; i < pic.worst.size(); ++i) {
    const MarkedElement& w = pic.worst[i];
    s += (i ? "," : "") + std::string("{\"label\":") +
         json_string(w.block + " element " + std::to_string(w.index + 1)) +
         ",\"sj\":" + format_number("%.6g", w.scaled_jacobian) +
         ",\"at\":" + number_array(w.centroid) + "}";
  }
  return s + "]}";
}

}  // namespace

std::string pictures_json(const std::vector<Picture>& pictures) {
  std::string s = "{\"colormap\":{\"stops\":[";
  const auto& stops = scaled_jacobian_stops();
  for (std::size_t i = 0; i < stops.size(); ++i) {
    s += (i ? "," : "") + std::string("[") + format_number("%g", stops[i].value) + "," +
         std::to_string(stops[i].rgb[0]) + "," + std::to_string(stops[i].rgb[1]) + "," +
         std::to_string(stops[i].rgb[2]) + "]";
  }
  const auto inv = inverted_color();
  s += "],\"inverted\":[" + std::to_string(inv[0]) + "," + std::to_string(inv[1]) + "," +
       std::to_string(inv[2]) + "]},\"pictures\":[";
  for (std::size_t i = 0; i < pictures.size(); ++i) s += (i ? "," : "") + picture_json(pictures[i]);
  return s + "]}";
}

}  // namespace cooperage::report::detail
