#include "framework/mesh2d/parity_ear.h"

#include <cmath>

namespace cooperage::mesh2d {
namespace {

// Inside or on the boundary of the counter-clockwise triangle abc.
bool in_triangle(const Point2& a, const Point2& b, const Point2& c, const Point2& x) {
  return orient2d(a, b, x) >= 0 && orient2d(b, c, x) >= 0 && orient2d(c, a, x) >= 0;
}

bool is_ear(const std::vector<std::vector<Point2>>& loops, size_t l, size_t i) {
  const auto& loop = loops[l];
  const size_t n = loop.size();
  const size_t ip = (i + n - 1) % n, in = (i + 1) % n;
  const Point2 &a = loop[ip], &b = loop[i], &c = loop[in];
  if (!(orient2d(a, b, c) > 0)) return false;  // reflex or straight
  for (size_t m = 0; m < loops.size(); ++m) {
    const auto& other = loops[m];
    const size_t k = other.size();
    for (size_t j = 0; j < k; ++j) {
      const bool corner = m == l && (j == ip || j == i || j == in);
      if (!corner && in_triangle(a, b, c, other[j])) return false;
      // The chord a-c against every edge not at a or c.
      const size_t jn = (j + 1) % k;
      const bool at_chord = m == l && (j == ip || jn == ip || j == in || jn == in);
      if (!at_chord && segments_touch(a, c, other[j], other[jn])) return false;
    }
  }
  return true;
}

}  // namespace

std::optional<Ear> parity_ear(const std::vector<std::vector<Point2>>& loops) {
  std::optional<Ear> best;
  double best_off = 0;
  for (size_t l = 0; l < loops.size(); ++l) {
    const auto& loop = loops[l];
    const size_t n = loop.size();
    if (n < 5) continue;  // the rest of the loop must still bound an area
    for (size_t i = 0; i < n; ++i) {
      const Point2 u = loop[(i + n - 1) % n] - loop[i], v = loop[(i + 1) % n] - loop[i];
      const double angle = std::atan2(std::abs(u.x() * v.y() - u.y() * v.x()), u.dot(v));
      const double off = std::abs(angle - M_PI / 3);
      if (best && off >= best_off) continue;
      if (!is_ear(loops, l, i)) continue;
      best = Ear{l, i};
      best_off = off;
    }
  }
  return best;
}

}  // namespace cooperage::mesh2d
