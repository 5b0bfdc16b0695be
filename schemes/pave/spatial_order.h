// Spatial ordering of 2D points along a Hilbert curve, so that elements and
// nodes that are close in the plane are close in memory (the steps after
// the triangulation walk node and element arrays by index; scattered
// indices make them memory-bound on large meshes).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

namespace cooperage::pave::detail {

/// Index of the cell (x, y) along the Hilbert curve filling a 2^bits x 2^bits
/// grid (the classic rotate-and-flip iteration; bits <= 31).
inline std::uint64_t hilbert_index(std::uint32_t x, std::uint32_t y, int bits) {
  const std::uint32_t n = std::uint32_t{1} << bits;
  std::uint64_t d = 0;
  for (std::uint32_t s = n >> 1; s > 0; s >>= 1) {
    const std::uint32_t rx = (x & s) ? 1u : 0u;
    const std::uint32_t ry = (y & s) ? 1u : 0u;
    d += static_cast<std::uint64_t>(s) * s * ((3u * rx) ^ ry);
    if (ry == 0) {  // rotate the quadrant
      if (rx == 1) {
        x = n - 1 - x;
        y = n - 1 - y;
      }
      std::swap(x, y);
    }
  }
  return d;
}

/// Hilbert keys of points on a 2^16 grid over `box` (deterministic: a
/// function of the coordinates only).
class HilbertKeys {
 public:
  explicit HilbertKeys(const Eigen::AlignedBox2d& box) : lo_(box.min()) {
    const double extent = std::max(box.sizes().maxCoeff(), 1e-300);
    scale_ = static_cast<double>((1u << kBits) - 1) / extent;
  }
  std::uint64_t operator()(const Eigen::Vector2d& p) const {
    const auto cell = [&](double v) {
      const double c = std::clamp(v * scale_, 0.0, static_cast<double>((1u << kBits) - 1));
      return static_cast<std::uint32_t>(c);
    };
    return hilbert_index(cell(p.x() - lo_.x()), cell(p.y() - lo_.y()), kBits);
  }

 private:
  static constexpr int kBits = 16;
  Eigen::Vector2d lo_;
  double scale_ = 1.0;
};

}  // namespace cooperage::pave::detail
