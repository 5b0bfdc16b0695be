#include "framework/mesh/corner_untangle.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

namespace cooperage::mesh {
namespace {

// One corner's area as an affine function of the moving node's offset
// (s, t) along the tangent directions: a + b s + c t.
struct Affine {
  double a, b, c;
  double at(double s, double t) const { return a + b * s + c * t; }
};

// Signed area of quad q's corner k: the edges to its two neighbours.
double corner_area(const std::vector<Vec3>& x, const Quad& q, size_t k, const Vec3& n) {
  const Vec3& p = x[static_cast<size_t>(q[k])];
  const Vec3& next = x[static_cast<size_t>(q[(k + 1) % 4])];
  const Vec3& prev = x[static_cast<size_t>(q[(k + 3) % 4])];
  return (next - p).cross(prev - p).dot(n);
}

// Sum of max(0, beta - alpha) over the corners.
double shortfall(const std::vector<Affine>& corners, double beta, double s, double t) {
  double f = 0.0;
  for (const Affine& a : corners) f += std::max(0.0, beta - a.at(s, t));
  return f;
}

}  // namespace

bool untangle_corners(std::vector<Vec3>& x, std::vector<Vec3>& normals,
                      const std::vector<bool>& fixed, const std::vector<Quad>& quads,
                      const CornerProjector& project, const CornerUntangleOptions& options) {
  const size_t n = x.size();
  std::vector<std::vector<int>> incident(n);
  for (size_t q = 0; q < quads.size(); ++q)
    for (size_t k = 0; k < 4; ++k)
      incident[static_cast<size_t>(quads[q][k])].push_back(static_cast<int>(q));
  // A corner's normal: the mean of its quad's node normals (one plane per
  // quad, so the three corners a node touches agree).
  auto quad_normal = [&](const Quad& q) {
    Vec3 m = Vec3::Zero();
    for (int v : q) m += normals[static_cast<size_t>(v)];
    return m.normalized();
  };
  double total = 0.0;
  for (const Quad& q : quads)
    for (size_t k = 0; k < 4; ++k) total += std::abs(corner_area(x, q, k, quad_normal(q)));
  if (quads.empty() || !(total > 0.0)) return quads.empty();
  const double beta = options.beta_ratio * total / (4.0 * static_cast<double>(quads.size()));

  auto worst_corner = [&] {
    double m = std::numeric_limits<double>::max();
    for (const Quad& q : quads)
      for (size_t k = 0; k < 4; ++k) m = std::min(m, corner_area(x, q, k, quad_normal(q)));
    return m;
  };
  for (int sweep = 0; sweep < options.sweeps; ++sweep) {
    std::set<int> tangled;  // free nodes of quads with a corner below beta
    for (const Quad& q : quads) {
      const Vec3 nq = quad_normal(q);
      bool low = false;
      for (size_t k = 0; k < 4; ++k) low = low || corner_area(x, q, k, nq) < beta;
      if (!low) continue;
      for (int v : q)
        if (!fixed[static_cast<size_t>(v)]) tangled.insert(v);
    }
    if (tangled.empty()) break;
    bool moved = false;
    for (int vi : tangled) {
      const size_t v = static_cast<size_t>(vi);
      const Vec3 nv = normals[v];
      const Vec3 e1 = nv.unitOrthogonal();
      const Vec3 e2 = nv.cross(e1);
      // The corners this node's position enters, each affine in (s, t).
      std::vector<Affine> corners;
      const Vec3 origin = x[v];
      for (int qi : incident[v]) {
        const Quad& q = quads[static_cast<size_t>(qi)];
        const Vec3 nq = quad_normal(q);
        size_t at = 0;
        while (static_cast<size_t>(q[at]) != v) ++at;
        for (size_t k = 0; k < 4; ++k) {
          if (k == (at + 2) % 4) continue;  // the opposite corner does not see it
          const double a0 = corner_area(x, q, k, nq);
          x[v] = origin + e1;
          const double a1 = corner_area(x, q, k, nq);
          x[v] = origin + e2;
          const double a2 = corner_area(x, q, k, nq);
          x[v] = origin;
          corners.push_back({a0, a1 - a0, a2 - a0});
        }
      }
      const double now = shortfall(corners, beta, 0.0, 0.0);
      if (now <= 0.0) continue;
      // The minimum lies at a vertex of the lines a + b s + c t = beta.
      double best = now;
      std::vector<std::pair<double, double>> at_best;
      const double tiny = 1e-12 * beta;
      for (size_t i = 0; i < corners.size(); ++i) {
        for (size_t j = i + 1; j < corners.size(); ++j) {
          const Affine& p = corners[i];
          const Affine& r = corners[j];
          const double det = p.b * r.c - p.c * r.b;
          if (std::abs(det) <= 1e-12 * (std::abs(p.b * r.c) + std::abs(p.c * r.b))) continue;
          const double s = ((beta - p.a) * r.c - p.c * (beta - r.a)) / det;
          const double t = (p.b * (beta - r.a) - (beta - p.a) * r.b) / det;
          const double f = shortfall(corners, beta, s, t);
          if (f < best - tiny) {
            best = f;
            at_best.assign(1, {s, t});
          } else if (f <= best + tiny && !at_best.empty()) {
            at_best.emplace_back(s, t);
          }
        }
      }
      if (at_best.empty()) continue;
      // The minimisers form a convex set: the mean of its vertices is in it
      // (and, where the sum is zero, away from the lines that bound it).
      double s = 0.0, t = 0.0;
      for (const auto& [ps, pt] : at_best) {
        s += ps;
        t += pt;
      }
      s /= static_cast<double>(at_best.size());
      t /= static_cast<double>(at_best.size());
      const geom::SurfaceProjection pr = project(origin + s * e1 + t * e2, v);
      x[v] = pr.point;
      normals[v] = pr.normal;
      moved = true;
    }
    if (!moved) break;
  }
  return worst_corner() > 0.0;
}

}  // namespace cooperage::mesh
