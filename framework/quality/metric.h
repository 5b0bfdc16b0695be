// Metric and ElementType: the names, directions and acceptable ranges of the
// Verdict-equivalent quality metrics in framework/quality.
//
// cite: C. J. Stimpson, C. D. Ernst, P. Knupp, P. P. Pebay, D. Thompson,
// "The Verdict Geometric Quality Library", SAND2007-1751 (the Verdict
// manual), and the code of sandialabs/verdict (V_HexMetric.cpp,
// V_WedgeMetric.cpp, V_QuadMetric.cpp, V_TriMetric.cpp). Acceptable ranges
// are the ones Cubit and the Verdict manual print.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace cooperage::quality {

/// Value returned for degenerate input where Verdict returns VERDICT_DBL_MAX
/// (1e30 in Verdict): zero-length edges, zero determinants in a ratio.
inline constexpr double kDegenerate = 1.0e30;

/// Element types with node order as in Exodus II / VTK (see the per-type headers).
enum class ElementType { Tri, Quad, Wedge, Hex };

/// The metrics of the quality report.
enum class Metric {
  ScaledJacobian,
  Jacobian,
  Skew,
  Taper,
  AspectFrobenius,  ///< hex/quad/wedge: max aspect Frobenius; tri: aspect Frobenius
  EdgeRatio,
  Shape,
  RelativeSize,  ///< Verdict's relative_size_squared
};

/// All metrics in enum order (for loops in reports and tests).
inline constexpr Metric kAllMetrics[] = {
    Metric::ScaledJacobian,  Metric::Jacobian,  Metric::Skew,  Metric::Taper,
    Metric::AspectFrobenius, Metric::EdgeRatio, Metric::Shape, Metric::RelativeSize};

/// "scaled_jacobian", "jacobian", "skew", "taper", "aspect_frobenius",
/// "edge_ratio", "shape", "relative_size".
std::string_view to_string(Metric metric);
/// Inverse of to_string(Metric); std::nullopt for an unknown name.
std::optional<Metric> metric_from_string(std::string_view name);

/// "tri", "quad", "wedge", "hex".
std::string_view to_string(ElementType type);
/// Inverse of to_string(ElementType); std::nullopt for an unknown name.
std::optional<ElementType> element_type_from_string(std::string_view name);

/// Number of corner nodes: 3, 4, 6, 8.
int node_count(ElementType type);

/// True if a larger value means a better element (scaled Jacobian, Jacobian,
/// shape, relative size); false for skew, taper, aspect Frobenius, edge ratio.
bool higher_is_better(Metric metric);

/// True if Verdict defines `metric` for `type` (and so does Cooperage).
/// Undefined pairs: wedge skew/taper/relative size, tri skew/taper.
/// The tri Jacobian is a Cooperage extension (2 x signed area, the value
/// Verdict's quad_jacobian returns for a collapsed quad); it is defined here.
bool is_defined(Metric metric, ElementType type);

/// Closed interval [lo, hi]; hi may be +infinity.
struct Range {
  double lo = 0.0;
  double hi = 0.0;
  bool contains(double v) const { return v >= lo && v <= hi; }
};

/// Cubit's / the Verdict manual's acceptable range of `metric` on `type`;
/// std::nullopt when none is published (edge ratio and aspect Frobenius of
/// hexes and wedges, Jacobian bounds above) or the metric is undefined.
std::optional<Range> acceptable_range(Metric metric, ElementType type);

/// The range a report's histogram spans when the metric has a natural one
/// (scaled Jacobian [-1, 1]; skew, shape, relative size [0, 1]); std::nullopt
/// for unbounded metrics, whose histogram spans the data's finite min..max.
std::optional<Range> natural_range(Metric metric);

/// Every value `metric` can take on any element (degenerate elements aside):
/// scaled Jacobian [-1, 1]; skew, shape, relative size [0, 1]; taper
/// [0, inf); aspect Frobenius and edge ratio [1, inf); Jacobian unbounded.
/// A quality threshold outside it can never be met (or never be missed).
Range attainable_range(Metric metric);

}  // namespace cooperage::quality
