#include "framework/mesh/corner_sine.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

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

double surface_scaled_jacobian(const std::vector<Vec3>& points, const int* corners, int count,
                               const Vec3& normal) {
  const double s = min_corner_sine(points, corners, count, normal);
  return count == 3 ? s * 2.0 / std::sqrt(3.0) : s;
}

SurfaceMeshQuality surface_mesh_quality(
    const std::vector<Vec3>& points, const std::vector<Quad>& quads, const std::vector<Tri>& tris,
    const std::function<Vec3(const Vec3& centroid, double size)>& normal_at, double floor) {
  SurfaceMeshQuality q;
  auto score = [&](const int* corners, int count) {
    Vec3 c = Vec3::Zero();
    for (int k = 0; k < count; ++k) c += at(points, corners[k]);
    c /= count;
    double size = 0;
    for (int k = 0; k < count; ++k) size = std::max(size, (at(points, corners[k]) - c).norm());
    const double s = surface_scaled_jacobian(points, corners, count, normal_at(c, size));
    q.min = std::min(q.min, s);
    if (!(s > 0)) ++q.inverted;
    if (s < floor) ++q.below;
  };
  for (const Quad& e : quads) score(e.data(), 4);
  for (const Tri& e : tris) score(e.data(), 3);
  return q;
}

}  // namespace cooperage::mesh
