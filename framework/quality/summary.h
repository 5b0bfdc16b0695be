// MetricSummary: the statistics of one metric over a set of elements, as
// printed at the end of every run.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "framework/quality/metric.h"

namespace cooperage::quality {

/// Statistics of one metric over many elements.
struct MetricSummary {
  std::string metric;     ///< to_string(Metric), e.g. "scaled_jacobian"
  std::size_t count = 0;  ///< number of values
  double min = 0.0, mean = 0.0, max = 0.0, median = 0.0;  ///< 0 when count == 0
  /// 10 equal bins over [histogram_lo, histogram_hi]; values outside the
  /// range (including kDegenerate sentinels) are counted in the end bins;
  /// NaNs are not binned.
  std::vector<std::size_t> histogram;
  double histogram_lo = 0.0, histogram_hi = 0.0;
  /// Values outside [threshold_min, threshold_max] (either bound optional):
  /// below the minimum for higher-is-better metrics, above the maximum for
  /// the others. NaN counts as outside when any threshold is given.
  std::size_t below_threshold = 0;
  /// Values <= 0 for ScaledJacobian and Jacobian (inverted or degenerate
  /// elements); always 0 for the other metrics.
  std::size_t inverted = 0;
};

/// Number of histogram bins.
inline constexpr std::size_t kHistogramBins = 10;

/// Summarise `values` of `metric`.
/// Histogram range: natural_range(metric) when it has one (scaled Jacobian
/// [-1, 1]; skew, shape, relative size [0, 1]); otherwise the min..max of
/// the finite values below kDegenerate (a zero-width range puts every value
/// in the first bin). Median of an even count is the mean of the two middle
/// values. Deterministic: the mean is a sequential sum in input order.
MetricSummary summarize(Metric metric, const std::vector<double>& values,
                        std::optional<double> threshold_min = std::nullopt,
                        std::optional<double> threshold_max = std::nullopt);

}  // namespace cooperage::quality
