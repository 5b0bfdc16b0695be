#include "framework/report/colormap.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace cooperage::report {

const std::vector<ColorStop>& scaled_jacobian_stops() {
  // ColorBrewer RdYlBu, reversed: red reads as "bad" to most people.
  static const std::vector<ColorStop> stops = {{0.00, {215, 25, 28}},
                                               {0.25, {253, 174, 97}},
                                               {0.50, {255, 255, 191}},
                                               {0.75, {171, 217, 233}},
                                               {1.00, {44, 123, 182}}};
  return stops;
}

std::array<int, 3> inverted_color() { return {103, 0, 31}; }

std::array<int, 3> color_of(double sj) {
  if (!(sj > 0)) return inverted_color();  // also NaN
  const auto& stops = scaled_jacobian_stops();
  sj = std::min(sj, 1.0);
  for (std::size_t i = 1; i < stops.size(); ++i) {
    if (sj > stops[i].value) continue;
    const ColorStop& a = stops[i - 1];
    const ColorStop& b = stops[i];
    const double t = (sj - a.value) / (b.value - a.value);
    std::array<int, 3> rgb{};
    for (int c = 0; c < 3; ++c) {
      rgb[c] = static_cast<int>(std::lround(a.rgb[c] + t * (b.rgb[c] - a.rgb[c])));
    }
    return rgb;
  }
  return stops.back().rgb;
}

std::string hex_color(const std::array<int, 3>& rgb) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", rgb[0] & 0xff, rgb[1] & 0xff, rgb[2] & 0xff);
  return buf;
}

}  // namespace cooperage::report
