#include "framework/mesh/curve_spacing.h"

#include "framework/core/error.h"

#include <algorithm>
#include <cmath>

namespace cooperage::mesh {
namespace {

// Relative interval lengths for ratio r, before normalisation.
std::vector<double> weights(int n, double r, CurveSpacing::Kind kind) {
  std::vector<double> w(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) {
    const int k = kind == CurveSpacing::Kind::Dual ? std::min(i, n - 1 - i) : i;
    w[static_cast<size_t>(i)] = std::pow(r, k);
  }
  return w;
}

double first_fraction(int n, double r, CurveSpacing::Kind kind) {
  const auto w = weights(n, r, kind);
  double sum = 0;
  for (double x : w) sum += x;
  return w.front() / sum;
}

// The ratio whose first interval is `target` of the whole length. The first
// fraction falls monotonically as r grows, so bisection in log r suffices.
double ratio_for_first(int n, double target, CurveSpacing::Kind kind) {
  double lo = 1e-6, hi = 1e6;
  if (target >= first_fraction(n, lo, kind) || target <= first_fraction(n, hi, kind)) {
    throw MeshingError(ErrorCode::InvalidInput, "a first interval of " + std::to_string(target) +
                                                    " of the curve length cannot be reached with " +
                                                    std::to_string(n) + " intervals");
  }
  for (int it = 0; it < 200; ++it) {
    const double mid = std::sqrt(lo * hi);
    (first_fraction(n, mid, kind) > target ? lo : hi) = mid;
  }
  return std::sqrt(lo * hi);
}

/// The integral of ds / size over the piece [at[k], at[k+1]] up to fraction
/// t of it (size linear on the piece).
double piece_integral(double length, double h0, double h1, double t) {
  const double d = h1 - h0;
  if (std::abs(d) < 1e-9 * std::max(h0, h1)) return t * length / h0;
  return length / d * std::log1p(d * t / h0);
}

/// Node fractions of n intervals equidistributed under the size function.
std::vector<double> sized_fractions(int n, double length, const SizeFunction& f) {
  const size_t m = f.at.size();
  std::vector<double> cumulative(m, 0.0);
  for (size_t k = 0; k + 1 < m; ++k) {
    const double piece = (f.at[k + 1] - f.at[k]) * length;
    cumulative[k + 1] = cumulative[k] + piece_integral(piece, f.size[k], f.size[k + 1], 1.0);
  }
  std::vector<double> s(static_cast<size_t>(n) + 1, 0.0);
  s.back() = 1.0;
  size_t k = 0;
  for (int i = 1; i < n; ++i) {
    const double target = cumulative.back() * i / n;
    while (k + 2 < m && cumulative[k + 1] < target) ++k;
    const double piece = (f.at[k + 1] - f.at[k]) * length;
    const double h0 = f.size[k], h1 = f.size[k + 1], need = target - cumulative[k];
    const double d = h1 - h0;
    double t = std::abs(d) < 1e-9 * std::max(h0, h1) ? need * h0 / piece
                                                     : h0 / d * std::expm1(need * d / piece);
    t = std::clamp(t, 0.0, 1.0);
    s[static_cast<size_t>(i)] =
        std::max(s[static_cast<size_t>(i) - 1], f.at[k] + t * (f.at[k + 1] - f.at[k]));
  }
  return s;
}

}  // namespace

double SizeFunction::intervals(double length) const {
  double total = 0.0;
  for (size_t k = 0; k + 1 < at.size(); ++k) {
    total += piece_integral((at[k + 1] - at[k]) * length, size[k], size[k + 1], 1.0);
  }
  return total;
}

std::vector<double> spacing_fractions(int n, double length, const CurveSpacing& spacing) {
  if (n < 1) throw MeshingError(ErrorCode::InvalidInput, "a curve needs at least 1 interval");
  if (spacing.kind == CurveSpacing::Kind::Sized && n > 1 && !spacing.sizes.empty() && length > 0) {
    return sized_fractions(n, length, spacing.sizes);
  }
  std::vector<double> s(static_cast<size_t>(n) + 1, 0.0);
  if (spacing.kind == CurveSpacing::Kind::Uniform || spacing.kind == CurveSpacing::Kind::Sized ||
      n == 1) {
    for (int i = 0; i <= n; ++i) s[static_cast<size_t>(i)] = static_cast<double>(i) / n;
    return s;
  }
  double r = spacing.ratio;
  if (spacing.first_size) {
    if (!(*spacing.first_size > 0) || !(length > 0)) {
      throw MeshingError(ErrorCode::InvalidInput, "first interval size must be positive");
    }
    r = ratio_for_first(n, *spacing.first_size / length, spacing.kind);
  }
  if (!(r > 0) || !std::isfinite(r)) {
    throw MeshingError(ErrorCode::InvalidInput, "bias ratio must be positive");
  }
  const auto w = weights(n, r, spacing.kind);
  double total = 0;
  for (double x : w) total += x;
  for (int i = 0; i < n; ++i)
    s[static_cast<size_t>(i) + 1] = s[static_cast<size_t>(i)] + w[static_cast<size_t>(i)] / total;
  s.back() = 1.0;
  if (spacing.kind == CurveSpacing::Kind::Geometric && spacing.reverse) {
    std::vector<double> rev(s.size());
    for (size_t i = 0; i < s.size(); ++i) rev[i] = 1.0 - s[s.size() - 1 - i];
    return rev;
  }
  return s;
}

std::vector<double> parameters_at_fractions(const geom::CurveGeometry& curve,
                                            const std::vector<double>& fractions) {
  const auto [t0, t1] = curve.range();
  const double length = curve.length();
  std::vector<double> t(fractions.size());
  for (size_t i = 0; i < fractions.size(); ++i) {
    if (i == 0) {
      t[i] = t0;
    } else if (i + 1 == fractions.size()) {
      t[i] = t1;
    } else {
      t[i] = curve.parameter_at_length(fractions[i] * length);
    }
  }
  return t;
}

}  // namespace cooperage::mesh
