// Node spacing along a curve: uniform, geometric bias, or dual (symmetric)
// bias, as fractions of arc length. Nodes are then placed on the true curve
// at those arc lengths (place_curve_nodes).
#pragma once

#include "framework/geometry/evaluators.h"

#include <optional>
#include <vector>

namespace cooperage::mesh {

/// A local interval length along a curve: size[k] [model units] at arc-length
/// fraction at[k] (0 = at[0] < ... < at.back() = 1), linear in between.
struct SizeFunction {
  std::vector<double> at;
  std::vector<double> size;
  bool empty() const { return at.size() < 2; }
  /// The number of intervals of these sizes on a curve of the given length:
  /// the integral of ds / size(s).
  double intervals(double length) const;
};

struct CurveSpacing {
  /// Sized: nodes equidistributed under `sizes` (a small feature at an end
  /// grades the intervals from its size up to the element size).
  enum class Kind { Uniform, Geometric, Dual, Sized };
  Kind kind = Kind::Uniform;
  /// Ratio between neighbouring intervals (> 0), walking away from the start
  /// (Geometric) or from both ends toward the middle (Dual).
  double ratio = 1.0;
  /// First interval length [model units]; when set it decides the ratio.
  std::optional<double> first_size;
  /// Geometric only: measure from the end vertex instead.
  bool reverse = false;
  /// Sized only.
  SizeFunction sizes;
};

/// Arc-length fractions 0 = s_0 < s_1 < ... < s_n = 1 of n intervals on a
/// curve of the given length. Throws MeshingError(InvalidInput) for n < 1,
/// a non-positive ratio, or a first size that cannot fit.
std::vector<double> spacing_fractions(int n, double length, const CurveSpacing& spacing);

/// Curve parameters at the given arc-length fractions of the whole edge.
std::vector<double> parameters_at_fractions(const geom::CurveGeometry& curve,
                                            const std::vector<double>& fractions);

}  // namespace cooperage::mesh
