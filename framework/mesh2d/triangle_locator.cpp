#include "framework/mesh2d/triangle_locator.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

namespace cooperage::mesh2d {

TriangleLocator::TriangleLocator(std::vector<Eigen::Vector2d> points,
                                 std::vector<std::array<int, 3>> triangles)
    : points_(std::move(points)), triangles_(std::move(triangles)) {
  if (triangles_.empty()) return;
  Eigen::AlignedBox2d box;
  for (const auto& t : triangles_) {
    for (int v : t) box.extend(points_[static_cast<size_t>(v)]);
  }
  lo_ = box.min();
  const Eigen::Vector2d size = box.sizes();
  // About one triangle per bucket.
  const double area = std::max(size.x() * size.y(), 1e-300);
  cell_size_ = std::sqrt(area / static_cast<double>(triangles_.size()));
  cell_size_ = std::max({cell_size_, size.x() / 2048.0, size.y() / 2048.0, 1e-300});
  nx_ = std::max(1, static_cast<int>(std::ceil(size.x() / cell_size_)) + 1);
  ny_ = std::max(1, static_cast<int>(std::ceil(size.y() / cell_size_)) + 1);
  std::vector<int> count(static_cast<size_t>(nx_ * ny_) + 1, 0);
  auto range = [&](const std::array<int, 3>& t, int& i0, int& i1, int& j0, int& j1) {
    Eigen::AlignedBox2d b;
    for (int v : t) b.extend(points_[static_cast<size_t>(v)]);
    i0 = std::clamp(static_cast<int>((b.min().x() - lo_.x()) / cell_size_), 0, nx_ - 1);
    i1 = std::clamp(static_cast<int>((b.max().x() - lo_.x()) / cell_size_), 0, nx_ - 1);
    j0 = std::clamp(static_cast<int>((b.min().y() - lo_.y()) / cell_size_), 0, ny_ - 1);
    j1 = std::clamp(static_cast<int>((b.max().y() - lo_.y()) / cell_size_), 0, ny_ - 1);
  };
  for (const auto& t : triangles_) {
    int i0, i1, j0, j1;
    range(t, i0, i1, j0, j1);
    for (int j = j0; j <= j1; ++j) {
      for (int i = i0; i <= i1; ++i) ++count[static_cast<size_t>(cell(i, j)) + 1];
    }
  }
  for (size_t c = 1; c < count.size(); ++c) count[c] += count[c - 1];
  start_ = count;
  items_.resize(static_cast<size_t>(count.back()));
  for (size_t k = 0; k < triangles_.size(); ++k) {
    int i0, i1, j0, j1;
    range(triangles_[k], i0, i1, j0, j1);
    for (int j = j0; j <= j1; ++j) {
      for (int i = i0; i <= i1; ++i)
        items_[static_cast<size_t>(count[static_cast<size_t>(cell(i, j))]++)] = static_cast<int>(k);
    }
  }
}

Eigen::Vector3d TriangleLocator::barycentric(int t, const Eigen::Vector2d& x) const {
  const auto& tri = triangles_[static_cast<size_t>(t)];
  const Eigen::Vector2d& a = points_[static_cast<size_t>(tri[0])];
  const Eigen::Vector2d& b = points_[static_cast<size_t>(tri[1])];
  const Eigen::Vector2d& c = points_[static_cast<size_t>(tri[2])];
  auto cross = [](const Eigen::Vector2d& p, const Eigen::Vector2d& q) {
    return p.x() * q.y() - p.y() * q.x();
  };
  const double area = cross(b - a, c - a);
  if (!(area != 0)) return Eigen::Vector3d(1.0 / 3, 1.0 / 3, 1.0 / 3);
  const double wa = cross(b - x, c - x) / area;
  const double wb = cross(c - x, a - x) / area;
  return Eigen::Vector3d(wa, wb, 1.0 - wa - wb);
}

TriangleLocator::Hit TriangleLocator::locate(const Eigen::Vector2d& x) const {
  Hit best;
  if (triangles_.empty()) return best;
  const int ci =
      std::clamp(static_cast<int>(std::floor((x.x() - lo_.x()) / cell_size_)), 0, nx_ - 1);
  const int cj =
      std::clamp(static_cast<int>(std::floor((x.y() - lo_.y()) / cell_size_)), 0, ny_ - 1);
  // Rings of buckets around x until a triangle holds it; the triangle whose
  // most negative barycentric coordinate is largest otherwise.
  double best_score = -std::numeric_limits<double>::infinity();
  const int max_ring = std::max(nx_, ny_);
  for (int ring = 0; ring <= max_ring; ++ring) {
    for (int j = cj - ring; j <= cj + ring; ++j) {
      for (int i = ci - ring; i <= ci + ring; ++i) {
        if (std::max(std::abs(i - ci), std::abs(j - cj)) != ring) continue;
        if (i < 0 || j < 0 || i >= nx_ || j >= ny_) continue;
        const int c = cell(i, j);
        for (int k = start_[static_cast<size_t>(c)]; k < start_[static_cast<size_t>(c) + 1]; ++k) {
          const int t = items_[static_cast<size_t>(k)];
          const Eigen::Vector3d w = barycentric(t, x);
          const double score = w.minCoeff();
          if (score > best_score || (score == best_score && t < best.triangle)) {
            best_score = score;
            best.triangle = t;
            best.weights = w;
          }
        }
      }
    }
    if (best_score >= 0) break;
    if (best.triangle >= 0 && ring >= 1) break;  // nearest among the buckets around x
  }
  Eigen::Vector3d w = best.weights.cwiseMax(0.0);
  const double sum = w.sum();
  best.weights = sum > 0 ? Eigen::Vector3d(w / sum) : Eigen::Vector3d(1.0 / 3, 1.0 / 3, 1.0 / 3);
  return best;
}

}  // namespace cooperage::mesh2d
