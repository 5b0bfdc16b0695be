// The smallest corner sine of a quad or triangle about a reference normal:
// the scaled Jacobian of a surface element in the form the quad-dominant
// steps and cooper's cap smoothing compare, given node indices into one
// point array (framework/quality takes node coordinates instead).
#pragma once

#include "framework/mesh/mesh_db.h"

#include <vector>

namespace cooperage::mesh {

/// Smallest corner sine of the polygon (3 or 4 corners, listed
/// counter-clockwise about `normal`), signed by `normal`: the 2D / surface
/// scaled Jacobian of a quad (1 square, sin a rhombus of angle a, <= 0 at a
/// reflex or inverted corner); a triangle's is (sqrt 3 / 2) times Verdict's.
double min_corner_sine(const std::vector<Vec3>& points, const int* corners, int count,
                       const Vec3& normal);

}  // namespace cooperage::mesh
