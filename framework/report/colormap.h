// The colour scale of the report: scaled Jacobian -> colour, shared by the
// SVG histograms (C++) and the mesh pictures (the viewer reads the same stops
// from the report's data, so the two never disagree).
#pragma once

#include <array>
#include <string>
#include <vector>

namespace cooperage::report {

struct ColorStop {
  double value;  ///< scaled Jacobian in [0, 1]
  std::array<int, 3> rgb;
};

/// Red (poor, near 0) through yellow to blue (ideal, 1); piecewise linear.
const std::vector<ColorStop>& scaled_jacobian_stops();

/// Colour of elements with scaled Jacobian <= 0 (inverted or degenerate).
std::array<int, 3> inverted_color();

/// The colour of a scaled Jacobian value (clamped to [0, 1] above zero).
std::array<int, 3> color_of(double scaled_jacobian);

/// "#rrggbb".
std::string hex_color(const std::array<int, 3>& rgb);

}  // namespace cooperage::report
