#include "framework/mesh2d/loop_parameters.h"
#include "framework/mesh2d/polygon_area.h"

#include "framework/core/error.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

namespace cooperage::mesh2d {
namespace {

using Eigen::Vector2d;
using geom::Vec3;

bool inside(const std::vector<Vector2d>& polygon, const Vector2d& q) {
  bool in = false;
  for (size_t k = 0, j = polygon.size() - 1; k < polygon.size(); j = k++) {
    const Vector2d& a = polygon[k];
    const Vector2d& b = polygon[j];
    if ((a.y() > q.y()) != (b.y() > q.y()) &&
        q.x() < (b.x() - a.x()) * (q.y() - a.y()) / (b.y() - a.y()) + a.x()) {
      in = !in;
    }
  }
  return in;
}

/// x shifted by whole periods to lie nearest to `near`, per closed direction.
Vector2d nearest_copy(Vector2d x, const Vector2d& near, const Vector2d& period) {
  for (int d = 0; d < 2; ++d) {
    if (period[d] > 0) x[d] -= period[d] * std::round((x[d] - near[d]) / period[d]);
  }
  return x;
}

class Walker {
 public:
  Walker(const geom::SurfaceGeometry& surface, int pole_points)
      : surface_(surface), pole_points_(std::max(2, pole_points)) {
    const auto [u, v] = surface.uv_bounds();
    lo_ = Vector2d(u.x(), v.x());
    hi_ = Vector2d(u.y(), v.y());
    for (int d = 0; d < 2; ++d) period_[d] = closed_period(surface, d);
  }

  const Vector2d& period() const { return period_; }

  /// The direction (0: u, 1: v) whose whole parameter line through uv is the
  /// single point p, or -1.
  int pole_direction(const Vec3& p, const Vector2d& uv, double tol) const {
    for (int d = 0; d < 2; ++d) {
      if (!(hi_[d] > lo_[d])) continue;
      bool collapsed = true;
      for (double f : {0.5, 0.0, 1.0, 0.25, 0.75}) {
        Vector2d q = uv;
        q[d] = lo_[d] + f * (hi_[d] - lo_[d]);
        if ((surface_.point(q) - p).norm() > tol) {
          collapsed = false;
          break;
        }
      }
      if (collapsed) return d;
    }
    return -1;
  }

  /// One loop's polygon for one choice of pole windings (shift[j] periods
  /// added to the exit of the j-th pole); false when a pole lies next to
  /// another pole (no direction to enter it from).
  bool walk(const std::vector<Vector2d>& raw, const std::vector<int>& pole_dir,
            const std::vector<int>& shift, std::vector<Vector2d>& uv, std::vector<int>& node,
            std::vector<char>& pole) const {
    const size_t n = raw.size();
    size_t start = 0;
    while (start < n && pole_dir[start] >= 0) ++start;
    if (start == n) return false;
    uv.clear();
    node.clear();
    pole.clear();
    size_t j = 0;
    for (size_t step = 0; step < n; ++step) {
      const size_t k = (start + step) % n;
      const int d = pole_dir[k];
      if (d < 0) {
        uv.push_back(uv.empty() ? raw[k] : nearest_copy(raw[k], uv.back(), period_));
        node.push_back(static_cast<int>(k));
        pole.push_back(0);
        continue;
      }
      const size_t next = (k + 1) % n;
      if (pole_dir[next] >= 0) return false;
      const int c = 1 - d;
      // Entered from the previous point's side; left towards the next node.
      Vector2d entry = uv.back();
      entry[c] = nearest_copy(raw[k], uv.back(), period_)[c];
      Vector2d exit = nearest_copy(raw[next], entry, period_);
      exit[d] += shift[j++] * period_[d];
      exit[c] = entry[c];
      for (int i = 0; i < pole_points_; ++i) {
        const double t = static_cast<double>(i) / (pole_points_ - 1);
        uv.push_back((1.0 - t) * entry + t * exit);
        node.push_back(static_cast<int>(k));
        pole.push_back(1);
      }
    }
    return true;
  }

  /// Whole turns the polygon makes around each closed direction.
  Eigen::Vector2i winding(const std::vector<Vector2d>& uv) const {
    const Vector2d closing = nearest_copy(uv.front(), uv.back(), period_);
    Eigen::Vector2i w(0, 0);
    for (int d = 0; d < 2; ++d) {
      if (period_[d] > 0)
        w[d] = static_cast<int>(std::lround((closing[d] - uv.front()[d]) / period_[d]));
    }
    return w;
  }

 private:
  const geom::SurfaceGeometry& surface_;
  int pole_points_;
  Vector2d lo_, hi_;
  Vector2d period_ = Vector2d::Zero();
};

/// +1 when S_u x S_v agrees with the natural normal along the nodes, else -1.
double orientation(const geom::SurfaceGeometry& surface,
                   const std::vector<std::vector<Vector2d>>& raw,
                   const std::vector<std::vector<int>>& pole_dir) {
  const auto [u, v] = surface.uv_bounds();
  const double hu = 1e-6 * std::max(u.y() - u.x(), 1e-12);
  const double hv = 1e-6 * std::max(v.y() - v.x(), 1e-12);
  double sum = 0.0;
  for (size_t l = 0; l < raw.size(); ++l) {
    for (size_t k = 0; k < raw[l].size(); ++k) {
      if (pole_dir[l][k] >= 0) continue;
      const Vector2d& x = raw[l][k];
      const Vec3 su = surface.point(x + Vector2d(hu, 0)) - surface.point(x - Vector2d(hu, 0));
      const Vec3 sv = surface.point(x + Vector2d(0, hv)) - surface.point(x - Vector2d(0, hv));
      const Vec3 n = su.cross(sv);
      const double len = n.norm();
      if (len > 0) sum += n.dot(surface.normal(x)) / len;
    }
  }
  return sum < 0 ? -1.0 : 1.0;
}

/// A face that comes back close to itself (a thin B-spline strip bent
/// round, real-cad occt_bottle's shoulder) can give a node two feet on the
/// surface; the global projector may take the far one, and the loop then
/// jumps across the parameter plane and back (a self-crossing polygon). A
/// node whose parameters lie far from both neighbours while the neighbours
/// lie close together is projected again from their midpoint, and the new
/// foot is kept when it is as close to the node as the first.
void repair_stray_projections(const geom::SurfaceGeometry& surface,
                              const std::vector<std::vector<Vec3>>& loops,
                              const std::vector<std::vector<int>>& pole_dir, double tol,
                              std::vector<std::vector<Vector2d>>& raw) {
  for (size_t l = 0; l < loops.size(); ++l) {
    const size_t n = raw[l].size();
    if (n < 3) continue;
    for (size_t k = 0; k < n; ++k) {
      if (pole_dir[l][k] >= 0) continue;
      const size_t a = (k + n - 1) % n, b = (k + 1) % n;
      if (pole_dir[l][a] >= 0 || pole_dir[l][b] >= 0) continue;
      const Vector2d& pa = raw[l][a];
      const Vector2d& pb = raw[l][b];
      const double across = (pa - pb).norm();
      const double away = std::min((raw[l][k] - pa).norm(), (raw[l][k] - pb).norm());
      if (!(away > 4.0 * across + 1e-12)) continue;
      const Vec3& p = loops[l][k];
      const geom::SurfaceProjection near = surface.project_near(p, 0.5 * (pa + pb));
      const double first = (surface.point(raw[l][k]) - p).norm();
      if (near.distance <= std::max(first, tol) &&
          std::min((near.uv - pa).norm(), (near.uv - pb).norm()) < away)
        raw[l][k] = near.uv;
    }
  }
}

}  // namespace

double closed_period(const geom::SurfaceGeometry& surface, int dir) {
  // Surfaces of revolution close after a full turn of u (and a torus of v
  // too) whatever the face's parameter box: a face may span more than one
  // turn (a thread) or less (a patch).
  using geom::SurfaceType;
  constexpr double kTwoPi = 6.283185307179586;
  const SurfaceType type = surface.type();
  if (dir == 0 &&
      (type == SurfaceType::Cylinder || type == SurfaceType::Cone || type == SurfaceType::Sphere ||
       type == SurfaceType::Torus || type == SurfaceType::Revolution)) {
    return kTwoPi;
  }
  if (dir == 1 && type == SurfaceType::Torus) return kTwoPi;
  if (!closed_direction(surface, dir)) return 0.0;
  const auto [u, v] = surface.uv_bounds();
  return dir == 0 ? u.y() - u.x() : v.y() - v.x();
}

bool closed_direction(const geom::SurfaceGeometry& surface, int dir) {
  const auto [u, v] = surface.uv_bounds();
  const Vector2d lo(u.x(), v.x()), hi(u.y(), v.y());
  if (!(hi[dir] > lo[dir])) return false;
  const int other = 1 - dir;
  double scale = 0.0, gap = 0.0;
  for (int k = 0; k < 3; ++k) {
    Vector2d a = lo;
    a[other] = lo[other] + (hi[other] - lo[other]) * (0.2 + 0.3 * k);
    Vector2d b = a, m = a;
    b[dir] = hi[dir];
    m[dir] = 0.5 * (lo[dir] + hi[dir]);
    const Vec3 pa = surface.point(a);
    gap = std::max(gap, (pa - surface.point(b)).norm());
    scale = std::max(scale, (pa - surface.point(m)).norm());
  }
  return scale > 0 && gap <= 1e-7 * scale;
}

LoopParameters loop_parameters(const geom::SurfaceGeometry& surface,
                               const std::vector<std::vector<Vec3>>& loops, int pole_points) {
  const Walker walker(surface, pole_points);
  geom::BoundingBox box;
  for (const auto& loop : loops) {
    for (const Vec3& p : loop) box.add(p);
  }
  const double tol = 1e-7 * std::max(box.diagonal(), 1e-300);

  std::vector<std::vector<Vector2d>> raw(loops.size());
  std::vector<std::vector<int>> pole_dir(loops.size());
  for (size_t l = 0; l < loops.size(); ++l) {
    for (const Vec3& p : loops[l]) {
      const Vector2d uv = surface.project(p).uv;
      raw[l].push_back(uv);
      pole_dir[l].push_back(walker.pole_direction(p, uv, tol));
    }
  }
  repair_stray_projections(surface, loops, pole_dir, tol, raw);
  const double sigma = orientation(surface, raw, pole_dir);

  LoopParameters out;
  out.period = walker.period();
  out.orientation = sigma;
  out.uv.resize(loops.size());
  out.node.resize(loops.size());
  out.pole.resize(loops.size());
  for (size_t l = 0; l < loops.size(); ++l) {
    int poles = 0;
    for (int d : pole_dir[l]) poles += d >= 0 ? 1 : 0;
    if (poles > 4) {
      throw MeshingError(ErrorCode::MeshingFailed, "loop " + std::to_string(l) + " has " +
                                                       std::to_string(poles) +
                                                       " poles; at most 4 are supported");
    }
    // Every combination of pole windings in {-1, 0, +1} periods: the loop
    // must not wind around the surface; among those, the largest area of
    // the expected orientation (outer loop counter-clockwise about the
    // normal, holes clockwise).
    const double expected = l == 0 ? sigma : -sigma;
    double best = -std::numeric_limits<double>::infinity();
    std::vector<int> shift(static_cast<size_t>(poles), -1);
    std::vector<Vector2d> uv;
    std::vector<int> node;
    std::vector<char> pole;
    for (;;) {
      if (walker.walk(raw[l], pole_dir[l], shift, uv, node, pole) &&
          walker.winding(uv) == Eigen::Vector2i(0, 0)) {
        const double score = expected * signed_area(uv);
        if (score > best) {
          best = score;
          out.uv[l] = uv;
          out.node[l] = node;
          out.pole[l] = pole;
        }
      }
      size_t j = 0;
      while (j < shift.size() && shift[j] == 1) shift[j++] = -1;
      if (j == shift.size()) break;
      ++shift[j];
    }
    if (out.uv[l].empty()) {
      throw MeshingError(ErrorCode::MeshingFailed,
                         "loop " + std::to_string(l) +
                             " winds around the closed surface (no seam curve), so it is no "
                             "polygon in the parameter plane");
    }
  }
  // Holes: by whole periods into the outer loop.
  const auto& outer = out.uv.front();
  Vector2d centre = Vector2d::Zero();
  for (const Vector2d& p : outer) centre += p;
  centre /= static_cast<double>(outer.size());
  for (size_t l = 1; l < out.uv.size(); ++l) {
    auto& hole = out.uv[l];
    size_t probe = 0;
    while (probe + 1 < hole.size() && out.pole[l][probe]) ++probe;
    Vector2d hole_centre = Vector2d::Zero();
    for (const Vector2d& p : hole) hole_centre += p;
    hole_centre /= static_cast<double>(hole.size());
    Vector2d best_shift = Vector2d::Zero();
    double best_distance = std::numeric_limits<double>::infinity();
    bool found = false;
    for (int a = -2; a <= 2 && !found; ++a) {
      for (int b = -2; b <= 2 && !found; ++b) {
        if ((a != 0 && out.period.x() == 0) || (b != 0 && out.period.y() == 0)) continue;
        const Vector2d s(a * out.period.x(), b * out.period.y());
        if (inside(outer, hole[probe] + s)) {
          best_shift = s;
          found = true;
        } else if ((hole_centre + s - centre).norm() < best_distance) {
          best_distance = (hole_centre + s - centre).norm();
          best_shift = s;
        }
      }
    }
    for (Vector2d& p : hole) p += best_shift;
  }
  return out;
}

}  // namespace cooperage::mesh2d
