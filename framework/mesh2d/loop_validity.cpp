// invalid_loops() of surface_chart.h: segment contacts through a grid of
// buckets, exact orientation tests (predicates.h).
#include "framework/mesh2d/predicates.h"
#include "framework/mesh2d/polygon_area.h"
#include "framework/mesh2d/surface_chart.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <string>

namespace cooperage::mesh2d {
namespace {

using Eigen::Vector2d;

bool point_in(const std::vector<Vector2d>& polygon, const Vector2d& q) {
  bool in = false;
  for (size_t k = 0, j = polygon.size() - 1; k < polygon.size(); j = k++) {
    const Vector2d& a = polygon[k];
    const Vector2d& b = polygon[j];
    if ((a.y() > q.y()) != (b.y() > q.y())) {
      // q.x < x of the edge at q.y, decided exactly: the edge's direction
      // upward and q on its left.
      const bool up = b.y() > a.y();
      const double o = up ? orient2d(a, b, q) : orient2d(b, a, q);
      if (o > 0) in = !in;
    }
  }
  return in;
}

}  // namespace

std::string invalid_loops(const std::vector<std::vector<Vector2d>>& loops) {
  if (loops.empty()) return "no loop";
  struct Segment {
    int loop, index;
  };
  std::vector<Segment> segments;
  Eigen::AlignedBox2d box;
  double length = 0.0;
  for (size_t l = 0; l < loops.size(); ++l) {
    const auto& p = loops[l];
    if (p.size() < 3) return "loop " + std::to_string(l) + " has fewer than 3 points";
    for (size_t k = 0; k < p.size(); ++k) {
      if (!p[k].allFinite()) return "loop " + std::to_string(l) + " has a point that is not finite";
      if (p[k] == p[(k + 1) % p.size()]) {
        return "loop " + std::to_string(l) + " has two equal consecutive points";
      }
      box.extend(p[k]);
      length += (p[(k + 1) % p.size()] - p[k]).norm();
      segments.push_back({static_cast<int>(l), static_cast<int>(k)});
    }
  }
  auto a_of = [&](const Segment& s) {
    return loops[static_cast<size_t>(s.loop)][static_cast<size_t>(s.index)];
  };
  auto b_of = [&](const Segment& s) {
    const auto& p = loops[static_cast<size_t>(s.loop)];
    return p[(static_cast<size_t>(s.index) + 1) % p.size()];
  };
  // Buckets about two mean segment lengths wide.
  const double cell = std::max({2.0 * length / static_cast<double>(segments.size()),
                                box.sizes().maxCoeff() / 1024.0, 1e-300});
  const int nx = std::max(1, static_cast<int>(box.sizes().x() / cell) + 1);
  const int ny = std::max(1, static_cast<int>(box.sizes().y() / cell) + 1);
  std::vector<std::vector<int>> buckets(static_cast<size_t>(nx) * static_cast<size_t>(ny));
  auto index = [&](double v, double lo, int n) {
    return std::clamp(static_cast<int>((v - lo) / cell), 0, n - 1);
  };
  for (size_t s = 0; s < segments.size(); ++s) {
    const Vector2d a = a_of(segments[s]), b = b_of(segments[s]);
    for (int j = index(std::min(a.y(), b.y()), box.min().y(), ny);
         j <= index(std::max(a.y(), b.y()), box.min().y(), ny); ++j) {
      for (int i = index(std::min(a.x(), b.x()), box.min().x(), nx);
           i <= index(std::max(a.x(), b.x()), box.min().x(), nx); ++i) {
        buckets[static_cast<size_t>(j) * static_cast<size_t>(nx) + static_cast<size_t>(i)]
            .push_back(static_cast<int>(s));
      }
    }
  }
  for (const auto& bucket : buckets) {
    for (size_t x = 0; x < bucket.size(); ++x) {
      for (size_t y = x + 1; y < bucket.size(); ++y) {
        const Segment& s = segments[static_cast<size_t>(bucket[x])];
        const Segment& t = segments[static_cast<size_t>(bucket[y])];
        const Vector2d a = a_of(s), b = b_of(s), c = a_of(t), d = b_of(t);
        const int n = static_cast<int>(loops[static_cast<size_t>(s.loop)].size());
        const bool same = s.loop == t.loop;
        const bool next = same && (t.index == (s.index + 1) % n);
        const bool prev = same && (s.index == (t.index + 1) % n);
        if (next || prev) {
          // Neighbours share one end; they must not fold back onto each other.
          const Vector2d shared = next ? b : a;
          const Vector2d far_s = next ? a : b, far_t = next ? d : c;
          if (orient2d(shared, far_s, far_t) == 0 && (far_s - shared).dot(far_t - shared) > 0) {
            return "loop " + std::to_string(s.loop) + " folds back on itself";
          }
          continue;
        }
        if (segments_touch(a, b, c, d)) {
          return same ? "loop " + std::to_string(s.loop) + " touches or crosses itself"
                      : "loops " + std::to_string(std::min(s.loop, t.loop)) + " and " +
                            std::to_string(std::max(s.loop, t.loop)) + " touch or cross";
        }
      }
    }
  }
  if (!(signed_area(loops[0]) > 0)) return "the outer loop is not counter-clockwise";
  for (size_t l = 1; l < loops.size(); ++l) {
    if (!(signed_area(loops[l]) < 0)) return "hole loop " + std::to_string(l) + " is not clockwise";
    if (!point_in(loops[0], loops[l][0]))
      return "hole loop " + std::to_string(l) + " lies outside the outer loop";
    for (size_t m = 1; m < loops.size(); ++m) {
      if (m != l && point_in(loops[m], loops[l][0])) {
        return "hole loop " + std::to_string(l) + " lies inside hole loop " + std::to_string(m);
      }
    }
  }
  return {};
}

}  // namespace cooperage::mesh2d
