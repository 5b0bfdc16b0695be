// The part of a barrel ring's motion that no affine map explains (a hole
// shrinking while the outer loop stays, a countersink's cone), carried from
// the boundary nodes of a cap mesh to its interior (Blacker 1996, sec. 6.1:
// "a least square weighted residual method ... which maintains the overall
// shape and quality of the mesh even for drastic distortions in geometry")
// by inverse-distance (Shepard, power 3) weights of the boundary nodes. The
// weights depend on the cap only: computed once per barrel and reused for
// every layer (issue 20, item 4). Value types only.
#pragma once

#include "schemes/cooper/least_squares_map.h"

#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace cooperage::cooper {

/// Residuals at most this size are noise, not motion: 1e-9 of the diagonal
/// of the points' bounding box. Affine motions leave none, so plain and
/// rigid sweeps skip the O(interior x boundary) interpolation.
double residual_tolerance(const Vec3* points, std::size_t count);

class ResidualField {
 public:
  /// \param[in] points  cap nodes, the first `boundary` of them on the boundary
  ResidualField(const std::vector<Vec3>& points, std::size_t boundary);

  /// Residuals of every node from those of the boundary nodes: out[k] = r[k]
  /// for k < boundary, the weighted mean of r at the interior nodes.
  void apply(const std::vector<Vec3>& r, std::vector<Vec3>& out) const;

  /// apply() for several fields at once: column c of `r` (boundary x m) is
  /// one coordinate of one field's boundary residuals; returns the
  /// (n - boundary) x m interior values. One pass over the weights serves
  /// all m columns (a matrix product): a large cap's weights do not stay in
  /// cache, and reading them once per layer was most of a curved barrel's
  /// sweep (issue 20). Each output depends on `r` and its column count
  /// only, not on the thread count.
  Eigen::MatrixXd interior(const Eigen::MatrixXd& r) const;

  std::size_t boundary() const { return boundary_; }

 private:
  std::vector<Vec3> points_;
  std::size_t boundary_ = 0;
  /// Normalised weights, (n - boundary) x boundary, row-major; empty when
  /// too large to keep (then recomputed on every call).
  std::vector<double> weights_;
};

/// Where the nodes of a cap mesh go when its boundary nodes are placed
/// already (sec. 6.1): `mapped[i]` is where a map puts node i (the first
/// `boundary_at.size()` are the boundary), and the boundary's residuals
/// (`boundary_at[k] - mapped[k]`) are carried inside by the weights of
/// `points` (the same nodes on the mesh they come from). The boundary lands
/// on `boundary_at`; a map that explains the boundary moves nothing else.
std::vector<Vec3> with_boundary_residuals(const std::vector<Vec3>& points,
                                          const std::vector<Vec3>& mapped,
                                          const std::vector<Vec3>& boundary_at);

}  // namespace cooperage::cooper
