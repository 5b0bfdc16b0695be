// Quality triangulation of a planar polygonal domain with holes: a
// constrained Delaunay triangulation (CDT) of the boundary loops, then
// Delaunay refinement by circumcentre insertion (Ruppert 1995; Shewchuk
// 1997/2002) that never splits a boundary segment, so the boundary nodes
// given are exactly the boundary nodes of the result.
//
// Because segments are never split, a circumcentre that would encroach a
// segment (lie in its diametral circle) or lies beyond it is rejected and the
// ideal apex of that segment (equilateral, on the domain side) is tried
// instead; when that fails too the triangle is left as it is. The minimum
// angle bound therefore holds away from small input angles and from
// segments much longer than the local size, not everywhere.
// cite: J. Ruppert, "A Delaunay refinement algorithm for quality 2-dimensional
// mesh generation", J. Algorithms 18 (1995); J. R. Shewchuk, "Delaunay
// refinement algorithms for triangular mesh generation", CGTA 22 (2002).
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <vector>

namespace cooperage::mesh2d {

/// Settings of triangulate().
struct RefineOptions {
  /// Triangles with a smaller angle are split (degrees; above ~33 the
  /// refinement may not terminate and is cut off by max_points).
  double min_angle_deg = 30.0;
  /// Triangles whose longest edge exceeds size_factor x the local size are
  /// split. The local size interpolates the boundary segment lengths: each
  /// boundary node carries the mean length of its two segments, new nodes
  /// the linear interpolation over the triangle they fall in, so sizes grade
  /// between loops of different spacing.
  double size_factor = 1.3;
  /// Multiplies the interpolated size (> 0); 0.5 gives twice as many edges across.
  double size_scale = 1.0;
  /// Hard cap on the number of points (0: automatic, from area / smallest size).
  std::size_t max_points = 0;
  /// false: the constrained Delaunay triangulation of the loops only.
  bool refine = true;
};

/// Result of triangulate(). points[0 .. boundary_count) are the input loop
/// points in input order, unchanged; later points are new interior points.
struct Triangulation2D {
  std::vector<Eigen::Vector2d> points;
  std::vector<std::array<int, 3>> triangles;  ///< counter-clockwise
  std::size_t boundary_count = 0;
  std::size_t rejected = 0;  ///< refinement candidates rejected (encroachment, too close)
  bool capped = false;       ///< max_points stopped the refinement
};

/// Triangulates the domain bounded by `loops`: the outer loop counter-clockwise,
/// holes clockwise, each a closed ring without repeating its first point,
/// at least 3 points, loops disjoint and not self-intersecting.
/// Deterministic: every choice depends on the input order and on geometric
/// tests with ties resolved by fixed relative tolerances, so a rigidly moved
/// input gives the same connectivity.
/// Throws cooperage::MeshingError(InvalidInput) for a loop with fewer than 3
/// points, repeated points, or boundaries that touch or cross.
Triangulation2D triangulate(const std::vector<std::vector<Eigen::Vector2d>>& loops,
                            const RefineOptions& options = {});

/// Minimum interior angle of the triangles [degrees] (180 when empty).
double min_angle_deg(const Triangulation2D& t);

}  // namespace cooperage::mesh2d
