#include "schemes/cooper/least_squares_map.h"

#include <Eigen/Dense>
#include <Eigen/Geometry>

#include <cmath>

namespace cooperage::cooper {

Vec3 pseudo_area(const Vec3* x, std::size_t n, const std::vector<std::size_t>& loop_starts) {
  Vec3 a = Vec3::Zero();
  for (std::size_t l = 0; l < loop_starts.size(); ++l) {
    const std::size_t b = loop_starts[l];
    const std::size_t e = l + 1 < loop_starts.size() ? loop_starts[l + 1] : n;
    for (std::size_t k = b; k < e; ++k) {
      const std::size_t next = k + 1 < e ? k + 1 : b;
      a += x[k].cross(x[next]);
    }
  }
  return 0.5 * a;
}

// cite: Roca, Sarrate, Huerta 2004 (least-squares affine mapping with the
// pseudo-area correction); ALGORITHMS.md sec. 3.
AffineMap least_squares_map(const Vec3* from, const Vec3* to, std::size_t n,
                            const std::vector<std::size_t>& loop_starts) {
  AffineMap map;
  if (n == 0) return map;
  Vec3 cf = Vec3::Zero();
  Vec3 ct = Vec3::Zero();
  for (std::size_t k = 0; k < n; ++k) {
    cf += from[k];
    ct += to[k];
  }
  cf /= static_cast<double>(n);
  ct /= static_cast<double>(n);
  map.from_centre = cf;
  map.to_centre = ct;

  Eigen::Matrix3d M = Eigen::Matrix3d::Zero();  // sum xh xh^T + v v^T
  Eigen::Matrix3d N = Eigen::Matrix3d::Zero();  // sum yh xh^T + w v^T
  for (std::size_t k = 0; k < n; ++k) {
    const Vec3 xh = from[k] - cf;
    const Vec3 yh = to[k] - ct;
    M.noalias() += xh * xh.transpose();
    N.noalias() += yh * xh.transpose();
  }
  const Vec3 af = pseudo_area(from, n, loop_starts);
  const Vec3 at = pseudo_area(to, n, loop_starts);
  const double nf = af.norm();
  const double nt = at.norm();
  if (nf > 0 && nt > 0) {
    const Vec3 v = af / std::sqrt(nf);
    const Vec3 w = at / std::sqrt(nt);
    M.noalias() += v * v.transpose();
    N.noalias() += w * v.transpose();
  }
  // A M = N  <=>  M A^T = N^T (M symmetric positive definite when regular).
  Eigen::LDLT<Eigen::Matrix3d> ldlt(M);
  if (ldlt.info() != Eigen::Success || !ldlt.isPositive()) return map;
  const double scale = M.trace();
  if (!(scale > 0) || std::abs(ldlt.vectorD().minCoeff()) < 1e-14 * scale) return map;
  map.A = ldlt.solve(N.transpose()).transpose();
  map.ok = map.A.allFinite() && map.A.determinant() > 0;
  return map;
}

}  // namespace cooperage::cooper
