#include "framework/mesh/corner_sine.h"

#include <Eigen/Geometry>

#include <algorithm>

namespace cooperage::mesh {
namespace {

const Vec3& at(const std::vector<Vec3>& points, int n) { return points[static_cast<size_t>(n)]; }

}  // namespace

double min_corner_sine(const std::vector<Vec3>& points, const int* corners, int count,
                       const Vec3& normal) {
  const double n = normal.norm();
  if (!(n > 0)) return -1.0;
  double m = 1.0;
  for (int k = 0; k < count; ++k) {
    const Vec3& p = at(points, corners[k]);
    const Vec3 in = p - at(points, corners[(k + count - 1) % count]);
    const Vec3 out = at(points, corners[(k + 1) % count]) - p;
    const double l = in.norm() * out.norm();
    if (!(l > 0)) return -1.0;
    m = std::min(m, in.cross(out).dot(normal) / (l * n));
  }
  return m;
}

}  // namespace cooperage::mesh
