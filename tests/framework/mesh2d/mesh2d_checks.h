// Shared checks for framework/mesh2d tests: validity, conformity, boundary
// preservation, area and the Delaunay property away from constraints.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include "framework/mesh2d/cdt.h"
#include "framework/mesh2d/predicates.h"
#include "framework/mesh2d/triangulate.h"

namespace cooperage::mesh2d::test {

using Loops = std::vector<std::vector<Eigen::Vector2d>>;

inline double loops_area(const Loops& loops) {
  double a = 0.0;
  for (const auto& l : loops) {
    for (size_t i = 0; i < l.size(); ++i) {
      const auto& p = l[i];
      const auto& q = l[(i + 1) % l.size()];
      a += 0.5 * (p.x() * q.y() - p.y() * q.x());
    }
  }
  return a;
}

/// Points along the polygon `corners` with segments of length about h.
inline std::vector<Eigen::Vector2d> subdivide(const std::vector<Eigen::Vector2d>& corners,
                                              double h) {
  std::vector<Eigen::Vector2d> out;
  for (size_t i = 0; i < corners.size(); ++i) {
    const Eigen::Vector2d& a = corners[i];
    const Eigen::Vector2d& b = corners[(i + 1) % corners.size()];
    const int n = std::max(1, static_cast<int>(std::lround((b - a).norm() / h)));
    for (int k = 0; k < n; ++k) out.push_back(a + (b - a) * (static_cast<double>(k) / n));
  }
  return out;
}

inline std::vector<Eigen::Vector2d> circle(const Eigen::Vector2d& c, double r, int n, bool ccw) {
  std::vector<Eigen::Vector2d> out;
  for (int k = 0; k < n; ++k) {
    const double t = 2.0 * 3.14159265358979323846 * k / n * (ccw ? 1.0 : -1.0);
    out.push_back(c + r * Eigen::Vector2d(std::cos(t), std::sin(t)));
  }
  return out;
}

struct CheckOptions {
  bool delaunay = true;
};

/// Expects t to be a valid triangulation of loops (stops at the first fatal failure).
inline void expect_valid(const Loops& loops, const Triangulation2D& t, CheckOptions opt = {}) {
  size_t nb = 0;
  std::map<std::pair<int, int>, int> segments;  // directed boundary segments
  for (const auto& l : loops) {
    for (size_t i = 0; i < l.size(); ++i) {
      ASSERT_LT(nb + i, t.points.size());
      ASSERT_EQ(t.points[nb + i], l[i]) << "boundary point " << nb + i << " moved";
      segments[{static_cast<int>(nb + i), static_cast<int>(nb + (i + 1) % l.size())}] = 0;
    }
    nb += l.size();
  }
  ASSERT_EQ(t.boundary_count, nb);
  std::map<std::pair<int, int>, int> directed;
  double area = 0.0;
  for (const auto& tri : t.triangles) {
    const auto& a = t.points[static_cast<size_t>(tri[0])];
    const auto& b = t.points[static_cast<size_t>(tri[1])];
    const auto& c = t.points[static_cast<size_t>(tri[2])];
    ASSERT_GT(orient2d(a, b, c), 0.0) << "inverted or flat triangle";
    area += 0.5 * ((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x());
    for (int k = 0; k < 3; ++k) {
      const std::pair<int, int> e{tri[static_cast<size_t>(k)],
                                  tri[static_cast<size_t>((k + 1) % 3)]};
      ASSERT_EQ(++directed[e], 1) << "edge used twice in one direction";
    }
  }
  for (const auto& [e, n] : directed) {
    const bool boundary = segments.count(e) > 0;
    const bool twin = directed.count({e.second, e.first}) > 0;
    if (boundary) {
      ++segments[e];
      EXPECT_FALSE(twin) << "boundary segment with a triangle outside";
    } else {
      ASSERT_TRUE(twin) << "interior edge " << e.first << "-" << e.second << " has one triangle";
    }
  }
  for (const auto& [e, n] : segments) EXPECT_EQ(n, 1) << "boundary segment missing";
  const double expected = loops_area(loops);
  EXPECT_NEAR(area, expected, 1e-9 * std::abs(expected));
  if (!opt.delaunay) return;
  // Delaunay away from constraints: the opposite vertex of every interior
  // edge is not inside the circumcircle (up to the tie tolerance).
  std::map<std::pair<int, int>, int> apex;
  for (const auto& tri : t.triangles) {
    for (int k = 0; k < 3; ++k) {
      apex[{tri[static_cast<size_t>((k + 1) % 3)], tri[static_cast<size_t>((k + 2) % 3)]}] =
          tri[static_cast<size_t>(k)];
    }
  }
  int violations = 0;
  for (const auto& tri : t.triangles) {
    for (int k = 0; k < 3; ++k) {
      const int a = tri[static_cast<size_t>((k + 1) % 3)];
      const int b = tri[static_cast<size_t>((k + 2) % 3)];
      auto it = apex.find({b, a});
      if (it == apex.end()) continue;
      double perm = 0.0;
      const double det = incircle_fast(
          t.points[static_cast<size_t>(tri[0])], t.points[static_cast<size_t>(tri[1])],
          t.points[static_cast<size_t>(tri[2])], t.points[static_cast<size_t>(it->second)], perm);
      if (det > 2.0 * detail::kDelaunayTieTol * perm) ++violations;
    }
  }
  EXPECT_EQ(violations, 0) << "non-Delaunay interior edges";
}

}  // namespace cooperage::mesh2d::test
