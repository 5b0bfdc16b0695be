// Signed area of a closed 2D polygon (shoelace formula), shared by the 2D
// layer's loop checks, charts and triangulation.
#pragma once

#include <Eigen/Core>

#include <vector>

namespace cooperage::mesh2d {

/// Positive when the loop runs counter-clockwise.
inline double signed_area(const std::vector<Eigen::Vector2d>& loop) {
  double a = 0.0;
  for (size_t i = 0; i < loop.size(); ++i) {
    const Eigen::Vector2d& p = loop[i];
    const Eigen::Vector2d& q = loop[(i + 1) % loop.size()];
    a += p.x() * q.y() - p.y() * q.x();
  }
  return 0.5 * a;
}

}  // namespace cooperage::mesh2d
