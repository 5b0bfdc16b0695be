#include "framework/quality/summary.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cooperage::quality {

MetricSummary summarize(Metric metric, const std::vector<double>& values,
                        std::optional<double> threshold_min, std::optional<double> threshold_max) {
  MetricSummary s;
  s.metric = std::string(to_string(metric));
  s.count = values.size();
  s.histogram.assign(kHistogramBins, 0);

  // Histogram range.
  if (auto r = natural_range(metric)) {
    s.histogram_lo = r->lo;
    s.histogram_hi = r->hi;
  } else {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (double v : values) {
      if (std::isfinite(v) && std::abs(v) < kDegenerate) {
        lo = std::min(lo, v);
        hi = std::max(hi, v);
      }
    }
    if (lo <= hi) {
      s.histogram_lo = lo;
      s.histogram_hi = hi;
    }
  }

  if (values.empty()) return s;

  const bool counts_inverted = metric == Metric::ScaledJacobian || metric == Metric::Jacobian;
  double sum = 0.0;
  s.min = std::numeric_limits<double>::infinity();
  s.max = -s.min;
  std::vector<double> sorted;
  sorted.reserve(values.size());
  const double width = s.histogram_hi - s.histogram_lo;
  for (double v : values) {
    sum += v;
    if (!std::isnan(v)) {
      s.min = std::min(s.min, v);
      s.max = std::max(s.max, v);
      sorted.push_back(v);
      std::size_t bin = 0;
      if (width > 0.0) {
        const double t = (v - s.histogram_lo) / width * static_cast<double>(kHistogramBins);
        if (t >= static_cast<double>(kHistogramBins)) {
          bin = kHistogramBins - 1;
        } else if (t > 0.0) {
          bin = static_cast<std::size_t>(t);
        }
      }
      ++s.histogram[bin];
    }
    const bool below = threshold_min && !(v >= *threshold_min);
    const bool above = threshold_max && !(v <= *threshold_max);
    if (below || above) ++s.below_threshold;
    if (counts_inverted && v <= 0.0) ++s.inverted;
  }
  s.mean = sum / static_cast<double>(values.size());
  if (sorted.empty()) {
    s.min = s.max = s.median = std::numeric_limits<double>::quiet_NaN();
    return s;
  }
  // Median by selection, O(n): the upper middle, and for an even count the
  // largest value below it.
  const std::size_t n = sorted.size();
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(n / 2),
                   sorted.end());
  const double upper = sorted[n / 2];
  if (n % 2 == 1) {
    s.median = upper;
  } else {
    const double lower =
        *std::max_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(n / 2));
    s.median = 0.5 * (lower + upper);
  }
  return s;
}

}  // namespace cooperage::quality
