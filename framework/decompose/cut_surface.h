// Cutting surfaces as the decomposition reasons about them: signed distance,
// the span of a point set across a cut, and a description for a person.
#pragma once

#include "framework/geometry/occ/solid_pieces.h"

#include <string>
#include <vector>

namespace cooperage::decompose {

using occ::CutSurface;

/// Signed distance of p from the cut (plane: positive on the normal's side;
/// cylinder and cone: positive outside).
double signed_distance(const CutSurface& cut, const geom::Vec3& p);

/// Smallest and largest signed distance of the points from the cut.
struct Span {
  double below = 0.0;  ///< min signed distance (<= 0 when some point is below)
  double above = 0.0;  ///< max signed distance
};
Span span(const CutSurface& cut, const std::vector<geom::Vec3>& points);

/// Whether two cuts are the same surface within `tol` (model units).
bool same_surface(const CutSurface& a, const CutSurface& b, double tol);

/// "plane z = 2.5", "plane through (1 2 0) normal (0.6 0.8 0)",
/// "cylinder r = 3 about the axis through (0 0 0) along z".
std::string describe(const CutSurface& cut);

}  // namespace cooperage::decompose
