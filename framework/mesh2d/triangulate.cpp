#include "framework/mesh2d/triangulate.h"
#include "framework/mesh2d/polygon_area.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "framework/core/error.h"
#include "framework/mesh2d/cdt.h"
#include "framework/mesh2d/predicates.h"
#include "framework/mesh2d/refine.h"

namespace cooperage::mesh2d {
namespace {

[[noreturn]] void bad_input(const std::string& message) {
  throw MeshingError(ErrorCode::InvalidInput, "triangulate: " + message);
}

}  // namespace

Triangulation2D triangulate(const std::vector<std::vector<Eigen::Vector2d>>& loops,
                            const RefineOptions& options) {
  if (loops.empty()) bad_input("no loops");
  if (!(options.size_scale > 0.0) || !(options.size_factor > 0.0)) bad_input("sizes must be > 0");
  Eigen::Vector2d lo = loops.front().empty() ? Eigen::Vector2d::Zero() : loops.front().front();
  Eigen::Vector2d hi = lo;
  size_t nb = 0;
  double area = 0.0;
  double hmin = std::numeric_limits<double>::infinity();
  for (size_t l = 0; l < loops.size(); ++l) {
    const auto& loop = loops[l];
    if (loop.size() < 3) bad_input("loop " + std::to_string(l) + " has fewer than 3 points");
    for (size_t i = 0; i < loop.size(); ++i) {
      if (!std::isfinite(loop[i].x()) || !std::isfinite(loop[i].y())) bad_input("non-finite point");
      lo = lo.cwiseMin(loop[i]);
      hi = hi.cwiseMax(loop[i]);
    }
    // A loop that turns back on itself (a point between its neighbours'
    // line and behind the previous one) overlaps itself: exact, in the
    // input's coordinates (the work frame below is rotated and rounds).
    for (size_t i = 0; i < loop.size(); ++i) {
      const auto& a = loop[(i + loop.size() - 1) % loop.size()];
      const auto& b = loop[i];
      const auto& c = loop[(i + 1) % loop.size()];
      if (orient2d(a, b, c) == 0.0 && (b - a).dot(c - b) < 0.0)
        bad_input("loop " + std::to_string(l) + " turns back on itself at point " +
                  std::to_string(i));
    }
    nb += loop.size();
    area += signed_area(loop);
  }
  if (!(area > 0.0)) bad_input("the loops enclose no area (outer loop must be counter-clockwise)");

  // Work in a frame attached to the input (origin at the first point, x along
  // the first segment), so that a rigidly moved input is computed on the same
  // numbers up to rounding, and ties fall the same way.
  const Eigen::Vector2d origin = loops.front().front();
  Eigen::Vector2d axis = loops.front()[1] - origin;
  if (!(axis.norm() > 0.0)) bad_input("repeated consecutive point");
  axis.normalize();
  auto to_local = [&](const Eigen::Vector2d& p) {
    const Eigen::Vector2d d = p - origin;
    return Eigen::Vector2d(d.dot(axis), axis.x() * d.y() - axis.y() * d.x());
  };
  auto to_global = [&](const Eigen::Vector2d& q) {
    return Eigen::Vector2d(origin + q.x() * axis + q.y() * Eigen::Vector2d(-axis.y(), axis.x()));
  };
  std::vector<std::vector<Eigen::Vector2d>> local(loops.size());
  lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  hi = -lo;
  for (size_t l = 0; l < loops.size(); ++l) {
    for (const auto& p : loops[l]) {
      local[l].push_back(to_local(p));
      lo = lo.cwiseMin(local[l].back());
      hi = hi.cwiseMax(local[l].back());
    }
  }

  detail::Cdt cdt;
  const Eigen::Vector2d mid = 0.5 * (lo + hi);
  const double D = std::max((hi - lo).maxCoeff(), 1e-300);
  cdt.init(mid + D * Eigen::Vector2d(-30, -30), mid + D * Eigen::Vector2d(30, -30),
           mid + D * Eigen::Vector2d(0, 30));
  cdt.tris.reserve(4 * nb + 16);
  // Boundary points carry the mean length of their two segments as size.
  std::vector<std::pair<int, int>> segments;
  for (const auto& loop : local) {
    const int first = static_cast<int>(cdt.pts.size());
    const size_t n = loop.size();
    for (size_t i = 0; i < n; ++i) {
      const double l0 = (loop[i] - loop[(i + n - 1) % n]).norm();
      const double l1 = (loop[(i + 1) % n] - loop[i]).norm();
      if (!(l1 > 0.0)) bad_input("repeated consecutive point");
      hmin = std::min(hmin, l1);
      const int v = cdt.add_point(loop[i], 0.5 * (l0 + l1));
      segments.emplace_back(v, first + static_cast<int>((i + 1) % n));
    }
  }
  int hint = 0;
  for (int v = 3; v < static_cast<int>(cdt.pts.size()); ++v) {
    const detail::Cdt::Location loc = cdt.locate(cdt.pts[static_cast<size_t>(v)], hint, false);
    if (loc.where == detail::Cdt::Where::OnVertex) bad_input("repeated point");
    if (!cdt.insert(v, loc)) bad_input("point could not be inserted (degenerate input)");
    hint = cdt.vtri[static_cast<size_t>(v)];
  }
  for (const auto& [a, b] : segments) cdt.insert_segment(a, b);
  cdt.mark_inside();
  // The domain lies left of every segment (outer loop CCW, holes CW): this
  // rejects wrongly oriented loops and holes outside the outer loop or nested.
  for (const auto& [a, b] : segments) {
    const auto [t, i] = cdt.find_edge(a, b);
    const detail::Tri& T = cdt.tris[static_cast<size_t>(t)];
    const bool left = T.v[static_cast<size_t>(detail::nxt(i))] == a;
    const int u = T.n[static_cast<size_t>(i)];
    const bool left_inside = left ? T.inside : (u >= 0 && cdt.tris[static_cast<size_t>(u)].inside);
    const bool right_inside = left ? (u >= 0 && cdt.tris[static_cast<size_t>(u)].inside) : T.inside;
    if (!left_inside || right_inside) {
      bad_input(
          "the domain is not on the left of every loop (outer loop counter-clockwise, "
          "holes clockwise and inside it, not nested)");
    }
  }
  cdt.make_delaunay();
  cdt.canonicalize();

  // Loop of each boundary point, to tell consecutive points of one loop.
  std::vector<std::pair<size_t, size_t>> where;  // (loop, index in loop)
  for (size_t l = 0; l < loops.size(); ++l)
    for (size_t i = 0; i < loops[l].size(); ++i) where.emplace_back(l, i);
  auto consecutive = [&](const std::array<int, 3>& v) {
    for (int k = 0; k < 3; ++k) {
      const auto [l, i] = where[static_cast<size_t>(v[static_cast<size_t>(k)])];
      const size_t n = loops[l].size();
      int neighbours = 0;
      for (int m = 0; m < 3; ++m) {
        const auto [l2, j] = where[static_cast<size_t>(v[static_cast<size_t>(m)])];
        neighbours += l2 == l && (j == (i + 1) % n || (j + 1) % n == i);
      }
      if (neighbours == 2) return true;  // v[k] sits between the other two
    }
    return false;
  };

  Triangulation2D out;
  if (options.refine) {
    size_t cap = options.max_points;
    if (cap == 0) {
      const double h = hmin * options.size_scale;
      cap = nb + 3 + static_cast<size_t>(std::min(4e8, 16.0 * area / (h * h))) + 1000;
    }
    const detail::RefineStats stats = detail::refine(cdt, options, cap + 3);
    out.rejected = stats.rejected;
    out.capped = stats.capped;
  }
  out.boundary_count = nb;
  out.points.reserve(cdt.pts.size() - 3);
  for (const auto& loop : loops) out.points.insert(out.points.end(), loop.begin(), loop.end());
  for (size_t i = 3 + nb; i < cdt.pts.size(); ++i) out.points.push_back(to_global(cdt.pts[i]));
  for (const detail::Tri& T : cdt.tris) {
    if (!T.inside) continue;
    out.triangles.push_back({T.v[0] - 3, T.v[1] - 3, T.v[2] - 3});
    // The work frame is rotated, so input points on one line may round to a
    // sliver there. Three consecutive points of a loop on a straight side
    // may give one (as before); three others with no area in the input's
    // own coordinates mean the loops touch (found by
    // fuzz/fuzz_triangulate.cpp; issue 21).
    const auto& v = out.triangles.back();
    if (static_cast<size_t>(std::max({v[0], v[1], v[2]})) < nb && !consecutive(v) &&
        !(orient2d(out.points[static_cast<size_t>(v[0])], out.points[static_cast<size_t>(v[1])],
                   out.points[static_cast<size_t>(v[2])]) > 0.0))
      bad_input("the loops touch (three boundary points on a line form a triangle)");
  }
  return out;
}

double min_angle_deg(const Triangulation2D& t) {
  double best = 180.0;
  for (const auto& tri : t.triangles) {
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector2d& p = t.points[static_cast<size_t>(tri[static_cast<size_t>(k)])];
      const Eigen::Vector2d a =
          t.points[static_cast<size_t>(tri[static_cast<size_t>((k + 1) % 3)])] - p;
      const Eigen::Vector2d b =
          t.points[static_cast<size_t>(tri[static_cast<size_t>((k + 2) % 3)])] - p;
      const double ang = std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
      best = std::min(best, ang * 180.0 / 3.14159265358979323846);
    }
  }
  return best;
}

}  // namespace cooperage::mesh2d
