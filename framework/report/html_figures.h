// The figures of the HTML report: SVG histograms and colour legend, and the
// pictures' data for the inline viewer. Internal to framework/report.
#pragma once

#include <string>
#include <vector>

#include "framework/report/mesh_pictures.h"

namespace cooperage::report::detail {

/// Bins of the scaled Jacobian histograms over [-1, 1].
inline constexpr int kHistogramBins = 40;

/// Counts of `values` in kHistogramBins equal bins over [-1, 1]; values
/// outside (never, for a scaled Jacobian) go to the end bins, NaN nowhere.
std::vector<std::size_t> histogram_counts(const std::vector<double>& values);

/// An SVG histogram of scaled Jacobians, bars in the colour of their bin.
/// @param[in] values  one per element
/// @param[in] label   accessible name of the figure
std::string histogram_svg(const std::vector<double>& values, const std::string& label);

/// An SVG colour bar of the scale with the inverted swatch.
std::string legend_svg();

/// The JSON the viewer reads: the colour stops and, per picture, quantised
/// points (uint16 per coordinate over the picture's box), faces (4 indices,
/// the 4th all ones for a triangle), scaled Jacobians (uint8 over [-1, 1]),
/// all base64, and the marked elements.
std::string pictures_json(const std::vector<Picture>& pictures);

/// The viewer script (plain JavaScript, no dependencies) and the page style.
const char* viewer_script();
const char* page_style();
/// Records script errors on <html data-errors> (first thing in <head>).
const char* error_probe_script();

}  // namespace cooperage::report::detail
