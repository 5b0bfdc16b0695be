// The least-squares affine map between two node loops of a barrel (Blacker
// 1996, sec. 6.1-6.2 "least square weighted residual" projection; Knupp 1998;
// Roca, Sarrate, Huerta 2004). ALGORITHMS.md sec. 3. Value types only.
#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace cooperage::cooper {

using Vec3 = Eigen::Vector3d;

/// y = A (x - from_centre) + to_centre.
struct AffineMap {
  Eigen::Matrix3d A = Eigen::Matrix3d::Identity();
  Vec3 from_centre = Vec3::Zero();
  Vec3 to_centre = Vec3::Zero();
  bool ok = false;  ///< the normal equations were solvable and det A > 0

  Vec3 apply(const Vec3& x) const { return A * (x - from_centre) + to_centre; }
};

/// Pseudo-area vector 1/2 sum_k x_k x x_{k+1} of closed loops (holes walked
/// the other way subtract). `loop_starts` holds the first index of each loop
/// in `x` (first entry 0); a loop runs to the next start or to n.
Vec3 pseudo_area(const Vec3* x, std::size_t n, const std::vector<std::size_t>& loop_starts);

/// Least-squares affine map sending loop points from[k] to to[k] (k < n),
/// centred on the loops' centroids, with the Roca-Sarrate-Huerta term
/// |A v - w|^2, v = a_from / sqrt|a_from|, w = a_to / sqrt|a_to| (a: pseudo-
/// area vectors) that makes the normal equations regular for planar loops:
///   A (sum xh xh^T + v v^T) = sum yh xh^T + w v^T.
/// \param[in] from, to     n matching loop points [model units]
/// \param[in] loop_starts  first index of every loop (both sets share it)
/// \return the map; ok is false when the system is singular or det A <= 0.
AffineMap least_squares_map(const Vec3* from, const Vec3* to, std::size_t n,
                            const std::vector<std::size_t>& loop_starts);

}  // namespace cooperage::cooper
