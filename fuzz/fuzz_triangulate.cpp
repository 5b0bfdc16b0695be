// Fuzz target: the 2D constrained triangulator (framework/mesh2d) on loops
// decoded from the bytes, at scales 1e-6 to 1e6, away from the origin by up
// to 1e4 times their size (a face's chart; loops of 1e-12 of their distance
// from the origin are beyond double precision once refined).
// Loops are oriented as the contract asks (outer counter-clockwise, holes
// clockwise); crossing or touching loops must end in MeshingError. A result
// must keep the input points first and unchanged, use valid indices and
// hold counter-clockwise triangles only.
#include "framework/core/error.h"
#include "framework/mesh2d/predicates.h"
#include "framework/mesh2d/triangulate.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <vector>

namespace {

class Bytes {
 public:
  Bytes(const std::uint8_t* data, std::size_t size) : p_(data), end_(data + size) {}
  bool more(std::size_t n) const { return static_cast<std::size_t>(end_ - p_) >= n; }
  std::uint8_t byte() { return more(1) ? *p_++ : 0; }
  std::int16_t int16() {
    const auto lo = byte();
    const auto hi = byte();
    return static_cast<std::int16_t>(static_cast<std::uint16_t>(lo | (hi << 8)));
  }

 private:
  const std::uint8_t* p_;
  const std::uint8_t* end_;
};

double signed_area(const std::vector<Eigen::Vector2d>& loop) {
  double a = 0;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const auto& p = loop[i];
    const auto& q = loop[(i + 1) % loop.size()];
    a += p.x() * q.y() - q.x() * p.y();
  }
  return 0.5 * a;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Bytes in(data, size);
  const double scale = std::pow(10.0, static_cast<int>(in.byte() % 13) - 6);
  const double offset = scale * (std::pow(10.0, static_cast<int>(in.byte() % 5)) - 1.0);
  const std::uint8_t flags = in.byte();
  const int n_loops = 1 + (flags >> 1) % 3;
  std::vector<std::vector<Eigen::Vector2d>> loops;
  for (int l = 0; l < n_loops && in.more(1); ++l) {
    const int n = 3 + in.byte() % 40;
    std::vector<Eigen::Vector2d> loop;
    for (int i = 0; i < n && in.more(4); ++i) {
      const double x = in.int16() / 32768.0 * scale + offset;
      const double y = in.int16() / 32768.0 * scale + offset;
      loop.emplace_back(x, y);
    }
    if (loop.size() < 3) break;
    const double a = signed_area(loop);
    if ((l == 0) != (a > 0)) std::reverse(loop.begin(), loop.end());
    loops.push_back(std::move(loop));
  }
  if (loops.empty()) return 0;
  cooperage::mesh2d::RefineOptions options;
  options.refine = (flags & 1) != 0;
  options.max_points = 20000;
  try {
    const auto t = cooperage::mesh2d::triangulate(loops, options);
    std::size_t k = 0;
    for (const auto& loop : loops)
      for (const auto& p : loop)
        if (k >= t.points.size() || t.points[k++] != p) std::abort();
    if (t.boundary_count != k) std::abort();
    for (const auto& tri : t.triangles) {
      for (int v : tri)
        if (v < 0 || static_cast<std::size_t>(v) >= t.points.size()) std::abort();
      const auto& a = t.points[static_cast<std::size_t>(tri[0])];
      const auto& b = t.points[static_cast<std::size_t>(tri[1])];
      const auto& c = t.points[static_cast<std::size_t>(tri[2])];
      if (!(cooperage::mesh2d::orient2d(a, b, c) > 0)) std::abort();  // exact sign
    }
  } catch (const cooperage::MeshingError&) {
  }
  return 0;
}
