// Least-squares conformal map of a triangulated surface patch onto the plane
// (LSCM): the piecewise-linear map whose gradient is as close as possible to
// a rotation times a scale on every triangle, i.e. that keeps angles. A
// surface mesher that works in the plane then sees the surface's angles,
// which is what the scaled Jacobian measures, wherever the parameterisation
// (u, v) is distorted (cone apexes, sphere poles, B-spline patches with
// uneven knots).
// cite: B. Levy, S. Petitjean, N. Ray, J. Maillot, "Least squares conformal
// maps for automatic texture atlas generation", ACM TOG 21 (SIGGRAPH 2002),
// sec. 3 (the energy) and sec. 3.3 (two pinned vertices).
#pragma once

#include <Eigen/Core>

#include <array>
#include <vector>

namespace cooperage::mesh2d {

/// Flattens a triangle mesh (a disk, or a disk with holes) conformally.
/// \param[in] points     3D vertex positions
/// \param[in] triangles  counter-clockwise about the side the plane is seen
///                       from (the surface's normal); triangles with zero
///                       area contribute nothing
/// \param[in] pin0,pin1  two distinct vertices, held at (0, 0) and
///                       (|points[pin1] - points[pin0]|, 0); far apart is best
/// \return one 2D position per point (points used by no triangle stay at the
///         origin). Deterministic. Throws MeshingError(MeshingFailed) when the
///         linear system is singular (e.g. a vertex only in flat triangles).
std::vector<Eigen::Vector2d> conformal_map(const std::vector<Eigen::Vector3d>& points,
                                           const std::vector<std::array<int, 3>>& triangles,
                                           int pin0, int pin1);

/// max over triangles of sigma_max / sigma_min of the affine map from the
/// triangle in `flat` to the triangle in `points` (1 for a similarity: the
/// map keeps angles); triangles degenerate in either are skipped. Infinity
/// when a triangle is inverted in `flat` (its orientation disagrees with
/// the others').
double max_conformal_distortion(const std::vector<Eigen::Vector3d>& points,
                                const std::vector<Eigen::Vector2d>& flat,
                                const std::vector<std::array<int, 3>>& triangles);

}  // namespace cooperage::mesh2d
