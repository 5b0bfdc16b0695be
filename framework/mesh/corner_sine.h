// The corner-sine quality of surface elements: the one set of helpers the
// schemes use to score quads and triangles on a surface (the scaled
// Jacobian of a surface element against a reference normal, Verdict's
// definition), given node indices into one point array.
#pragma once

#include "framework/mesh/mesh_db.h"

#include <cstddef>
#include <functional>
#include <vector>

namespace cooperage::mesh {

/// Smallest corner sine of the polygon (3 or 4 corners, listed
/// counter-clockwise about `normal`), signed by `normal`: the 2D / surface
/// scaled Jacobian of a quad (1 square, sin a rhombus of angle a, <= 0 at a
/// reflex or inverted corner); a triangle's is (sqrt 3 / 2) times Verdict's.
double min_corner_sine(const std::vector<Vec3>& points, const int* corners, int count,
                       const Vec3& normal);

/// Verdict's scaled Jacobian of a surface element against `normal`: a
/// quad's min_corner_sine; a triangle's times 2 / sqrt 3 (equilateral 1).
double surface_scaled_jacobian(const std::vector<Vec3>& points, const int* corners, int count,
                               const Vec3& normal);

/// The worst element of a surface mesh.
struct SurfaceMeshQuality {
  double min = 1.0;          ///< smallest scaled Jacobian (1 when there is no element)
  std::size_t inverted = 0;  ///< elements with a scaled Jacobian <= 0
  std::size_t below = 0;     ///< elements below the `floor` given
};

/// Scores every quad and triangle with surface_scaled_jacobian() against
/// normal_at(its centroid, its size) (e.g. the surface normal at the closest
/// point; the size, the largest distance of a corner from the centroid,
/// bounds how far that point can be: geom::ProjectionWalk's reach).
/// Elements are scored in order, quads first.
SurfaceMeshQuality surface_mesh_quality(
    const std::vector<Vec3>& points, const std::vector<Quad>& quads, const std::vector<Tri>& tris,
    const std::function<Vec3(const Vec3& centroid, double size)>& normal_at, double floor = 0.0);

}  // namespace cooperage::mesh
