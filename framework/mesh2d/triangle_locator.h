// Point location in a planar triangulation through a uniform grid of
// buckets: the triangle holding a point, with barycentric coordinates. A
// point just outside the triangulation (rounding on its boundary) gets the
// nearest triangle among the buckets around it, coordinates clamped.
#pragma once

#include <Eigen/Core>

#include <array>
#include <vector>

namespace cooperage::mesh2d {

class TriangleLocator {
 public:
  /// The triangles (counter-clockwise) over the points; both are copied.
  TriangleLocator(std::vector<Eigen::Vector2d> points, std::vector<std::array<int, 3>> triangles);

  struct Hit {
    int triangle = -1;                                  ///< -1 only when there are no triangles
    Eigen::Vector3d weights = Eigen::Vector3d::Zero();  ///< barycentric, >= 0, sum 1
  };
  /// The triangle holding x (or the nearest one).
  Hit locate(const Eigen::Vector2d& x) const;

  const std::vector<std::array<int, 3>>& triangles() const { return triangles_; }

 private:
  Eigen::Vector3d barycentric(int t, const Eigen::Vector2d& x) const;
  int cell(int i, int j) const { return j * nx_ + i; }

  std::vector<Eigen::Vector2d> points_;
  std::vector<std::array<int, 3>> triangles_;
  Eigen::Vector2d lo_ = Eigen::Vector2d::Zero();
  double cell_size_ = 1.0;
  int nx_ = 1, ny_ = 1;
  std::vector<int> start_;  ///< bucket c holds items[start_[c] .. start_[c + 1])
  std::vector<int> items_;
};

}  // namespace cooperage::mesh2d
