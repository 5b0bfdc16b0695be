#include "schemes/cooper/untangle_cap.h"

#include "schemes/cooper/smooth_cap.h"

#include "framework/mesh/corner_sine.h"
#include "framework/mesh/improve_split_nodes.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace cooperage::cooper {
namespace {

using Vec2 = Eigen::Vector2d;

// A corner this close to its floor (relative) counts as on it.
constexpr double kAtFloor = 1e-9;
// Newton's steps are damped by this fraction of the Hessian's trace: a node
// with two nearly parallel active corners has a nearly singular Hessian,
// whose undamped steps shoot far along the free direction and come back by
// halving, so that rounding chose the step (campaign seed 4 case 159, size
// 10.3: a moved part's untangled cap was 0.2 from the part's, 1.9 after
// raise_worst_elements; seed 7 case 50 inverted a hex as built only).
constexpr double kDamping = 1e-3;

double cross2(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

// One corner of a face: the node, the next and the previous one
// (counter-clockwise), and the area its corner must reach.
struct Corner {
  int at = 0, next = 0, prev = 0;
  double floor = 0;
};

template <class Face>
void add_corners(const std::vector<Face>& faces, std::vector<Corner>& out) {
  for (const Face& f : faces) {
    const size_t n = f.size();
    for (size_t k = 0; k < n; ++k) out.push_back({f[k], f[(k + 1) % n], f[(k + n - 1) % n], 0.0});
  }
}

// The corner's area (cross product of its two edges) with node v at x.
double area(const Corner& c, const std::vector<Vec2>& xy, int v, const Vec2& x) {
  auto at = [&](int n) -> const Vec2& { return n == v ? x : xy[static_cast<size_t>(n)]; };
  const Vec2& o = at(c.at);
  return cross2(at(c.next) - o, at(c.prev) - o);
}

double signed_total(const std::vector<Corner>& corners, const std::vector<Vec2>& xy) {
  // The shoelace sum over every face's edges (each corner to the next).
  double sum = 0;
  for (const Corner& c : corners)
    sum += cross2(xy[static_cast<size_t>(c.at)], xy[static_cast<size_t>(c.next)]);
  return 0.5 * sum;
}

// Knupp's objective at node v placed at x: sum of max(0, floor - area)^2.
double objective(const std::vector<Corner>& corners, const std::vector<int>& mine,
                 const std::vector<Vec2>& xy, int v, const Vec2& x) {
  double g = 0;
  for (int c : mine) {
    const double d =
        corners[static_cast<size_t>(c)].floor - area(corners[static_cast<size_t>(c)], xy, v, x);
    if (d > 0) g += d * d;
  }
  return g;
}

// Newton steps on the node's convex, piecewise quadratic objective (every
// corner area is linear in the node's position), halved until it drops.
Vec2 minimise(const std::vector<Corner>& corners, const std::vector<int>& mine,
              const std::vector<Vec2>& xy, int v) {
  Vec2 x = xy[static_cast<size_t>(v)];
  double g = objective(corners, mine, xy, v, x);
  for (int step = 0; step < 8 && g > 0; ++step) {
    Vec2 grad = Vec2::Zero();
    Eigen::Matrix2d hess = Eigen::Matrix2d::Zero();
    for (int ci : mine) {
      const Corner& c = corners[static_cast<size_t>(ci)];
      const double a = area(c, xy, v, x);
      const double d = c.floor - a;
      // A corner on its floor (where a neighbour's minimisation left it)
      // shapes the step whichever side of it rounding put it.
      if (d <= -kAtFloor * c.floor) continue;
      // The area is linear in x: its gradient from two unit differences.
      const Vec2 da(area(c, xy, v, x + Vec2(1, 0)) - a, area(c, xy, v, x + Vec2(0, 1)) - a);
      grad -= 2 * std::max(d, 0.0) * da;
      hess += 2 * da * da.transpose();
    }
    const double scale = hess.trace();
    if (!(scale > 0)) break;
    const Vec2 dir = -(hess + kDamping * scale * Eigen::Matrix2d::Identity()).ldlt().solve(grad);
    bool dropped = false;
    for (double t = 1.0; t > 1e-4; t *= 0.5) {
      const Vec2 y = x + t * dir;
      const double gy = objective(corners, mine, xy, v, y);
      if (gy < g) {
        x = y;
        g = gy;
        dropped = true;
        break;
      }
    }
    if (!dropped) break;
  }
  return x;
}

}  // namespace

bool untangle_cap(std::vector<mesh::Vec3>& points, const std::vector<mesh::Vec3>& source,
                  const std::vector<mesh::Quad>& quads, const std::vector<mesh::Tri>& tris,
                  const std::vector<char>& movable, const mesh::Vec3& normal,
                  const std::function<mesh::Vec3(const mesh::Vec3&)>& project) {
  const size_t n = points.size();
  if (source.size() != n || movable.size() != n || normal.norm() == 0) return false;
  const mesh::Vec3 w = normal.normalized();
  const mesh::Vec3 e1 = w.unitOrthogonal();
  const mesh::Vec3 e2 = w.cross(e1);
  auto plane = [&](const std::vector<mesh::Vec3>& p) {
    std::vector<Vec2> xy(p.size());
    for (size_t i = 0; i < p.size(); ++i) xy[i] = Vec2(p[i].dot(e1), p[i].dot(e2));
    return xy;
  };
  std::vector<Corner> corners;
  add_corners(quads, corners);
  add_corners(tris, corners);
  std::vector<std::vector<int>> mine(n);  // corners each node is part of
  for (size_t c = 0; c < corners.size(); ++c) {
    for (int v : {corners[c].at, corners[c].next, corners[c].prev})
      mine[static_cast<size_t>(v)].push_back(static_cast<int>(c));
  }
  const std::vector<Vec2> from = plane(source);
  std::vector<Vec2> xy = plane(points);
  const double from_total = signed_total(corners, from);
  const double ratio = from_total > 0 ? std::max(0.0, signed_total(corners, xy) / from_total) : 0;
  std::vector<double> from_area(corners.size());
  for (size_t c = 0; c < corners.size(); ++c)
    from_area[c] = std::max(0.0, area(corners[c], from, -1, Vec2::Zero()));

  auto worst = [&] {
    return std::min(min_quad_corner_quality(points, quads, w),
                    min_tri_corner_quality(points, tris, w));
  };
  const double before = worst();
  const std::vector<mesh::Vec3> start = points;
  long visits = 0;  // node minimisations, at most 200 per node over all floors
  for (double fraction : {0.25, 0.05, 0.01}) {
    for (size_t c = 0; c < corners.size(); ++c) corners[c].floor = fraction * ratio * from_area[c];
    for (int sweep = 0; sweep < 200 && visits < 200 * static_cast<long>(n); ++sweep) {
      // The movable nodes of faces with a corner under its floor, in order.
      // The minimisations leave corners on their floors, where rounding
      // alone would decide (and a moved part decide otherwise): a corner
      // within kAtFloor of its floor has reached it.
      std::vector<char> todo(n, 0);
      bool any = false;
      for (const Corner& c : corners) {
        if (area(c, xy, -1, Vec2::Zero()) >= c.floor * (1 - kAtFloor)) continue;
        for (int v : {c.at, c.next, c.prev}) {
          if (movable[static_cast<size_t>(v)]) {
            todo[static_cast<size_t>(v)] = 1;
            any = true;
          }
        }
      }
      if (!any) break;
      bool moved = false;
      for (size_t v = 0; v < n; ++v) {
        if (!todo[v]) continue;
        ++visits;
        const Vec2 x = minimise(corners, mine[v], xy, static_cast<int>(v));
        const Vec2 d = x - xy[v];
        if (d.squaredNorm() == 0) continue;
        const mesh::Vec3 moved_to = points[v] + d.x() * e1 + d.y() * e2;
        points[v] = project ? project(moved_to) : moved_to;
        xy[v] = Vec2(points[v].dot(e1), points[v].dot(e2));
        moved = true;
      }
      if (!moved) break;
    }
    if (worst() > 0) break;
  }
  // Then the free nodes of poor faces raise their worst corners (the
  // untangling leaves corners just over their floors): the compass search
  // along the directions to their neighbours of framework/mesh, so that a
  // rigidly moved cap moves the same way.
  if (worst() > 0) {
    constexpr double kPoor = 0.3;
    std::vector<char> poor(n, 0);
    auto mark = [&](const auto& face) {
      if (mesh::min_corner_sine(points, face.data(), static_cast<int>(face.size()), w) >= kPoor)
        return;
      for (int v : face) poor[static_cast<size_t>(v)] = movable[static_cast<size_t>(v)];
    };
    for (const mesh::Quad& q : quads) mark(q);
    for (const mesh::Tri& t : tris) mark(t);
    std::vector<int> targets;
    for (size_t v = 0; v < n; ++v)
      if (poor[v]) targets.push_back(static_cast<int>(v));
    const auto onto = [&](const mesh::Vec3& x) { return project ? project(x) : x; };
    mesh::raise_worst_elements(points, quads, tris, targets, onto, -2.0, 3);
  }
  if (worst() > before) return true;
  points = start;
  return false;
}

}  // namespace cooperage::cooper
