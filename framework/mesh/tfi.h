// Transfinite interpolation (TFI) of structured grids from their boundary
// (ALGORITHMS.md sec. 1; Gordon & Hall 1973; Thompson, Warsi, Mastin 1985):
//   2D: x(u,v) = (1-v)B + vT + (1-u)L + uR - [(1-u)(1-v)P00 + u(1-v)P10 + uvP11 + (1-u)vP01]
//   3D: faces - edges + corners (the Boolean sum of three linear projectors).
// Parameters come from arc-length fractions of the boundary so non-uniform
// boundary spacing carries into the interior.
#pragma once

#include "framework/geometry/types.h"

#include <vector>

namespace cooperage::mesh {

using geom::Vec3;

/// Cumulative arc-length fractions 0 = f_0 <= ... <= f_n = 1 of a polyline
/// (uniform i/n when the polyline has zero length).
std::vector<double> arc_fractions(const std::vector<Vec3>& points);

/// A structured (n+1) x (m+1) grid of points, point(i, j) = at[i * (m+1) + j].
struct Grid2 {
  int n = 0;
  int m = 0;
  std::vector<Vec3> at;
  // size_t arithmetic: i * (m + 1) overflows int at 65,535 x 65,536 (issue 21).
  size_t index(int i, int j) const {
    return static_cast<size_t>(i) * (static_cast<size_t>(m) + 1) + static_cast<size_t>(j);
  }
  Vec3& operator()(int i, int j) { return at[index(i, j)]; }
  const Vec3& operator()(int i, int j) const { return at[index(i, j)]; }
};

/// 2D TFI of a grid from its four sides, all given in increasing i or j:
/// bottom(i) = x(i, 0), top(i) = x(i, m), left(j) = x(0, j), right(j) = x(n, j),
/// with bottom.size() == top.size() == n+1 and left.size() == right.size() == m+1,
/// and matching corners. Interior parameters (u, v) solve
/// u = (1-v) fb(i) + v ft(i), v = (1-u) fl(j) + u fr(j) for the arc-length
/// fractions f of the four sides. Boundary points are reproduced exactly.
Grid2 tfi_2d(const std::vector<Vec3>& bottom, const std::vector<Vec3>& top,
             const std::vector<Vec3>& left, const std::vector<Vec3>& right);

/// A structured (ni+1) x (nj+1) x (nk+1) block of points.
struct Grid3 {
  int ni = 0, nj = 0, nk = 0;
  std::vector<Vec3> at;
  size_t index(int i, int j, int k) const {
    return (static_cast<size_t>(k) * static_cast<size_t>(nj + 1) + static_cast<size_t>(j)) *
               static_cast<size_t>(ni + 1) +
           static_cast<size_t>(i);
  }
  Vec3& operator()(int i, int j, int k) { return at[index(i, j, k)]; }
  const Vec3& operator()(int i, int j, int k) const { return at[index(i, j, k)]; }
  bool on_boundary(int i, int j, int k) const {
    return i == 0 || j == 0 || k == 0 || i == ni || j == nj || k == nk;
  }
};

/// 3D TFI: fills the interior points of `block` from its boundary points
/// (every point with i, j or k on the block boundary must be set). The
/// parameter u at (i, j, k) blends the arc-length fractions of the four
/// boundary i-lines through the faces j = 0, nJ and k = 0, nK; v, w likewise.
void tfi_3d(Grid3& block);

}  // namespace cooperage::mesh
