#include "schemes/submap/untangle.h"

#include <algorithm>
#include <limits>
#include <set>

namespace cooperage::submap {
namespace {

constexpr double kGain = 1e-9;  // an improvement smaller than this is noise

}  // namespace

double untangle_quads(std::vector<Vec3>& x, std::vector<Vec3>& normals,
                      const std::vector<bool>& fixed, const std::vector<mesh::Quad>& quads,
                      const Projector& project, const UntangleOptions& options) {
  const size_t n = x.size();
  std::vector<std::vector<int>> incident(n);
  for (size_t q = 0; q < quads.size(); ++q)
    for (size_t k = 0; k < 4; ++k)
      incident[static_cast<size_t>(quads[q][k])].push_back(static_cast<int>(q));
  auto quality = [&](int q) {
    return quad_scaled_jacobian(x, normals, quads[static_cast<size_t>(q)]);
  };
  auto worst_at = [&](size_t v) {
    double m = std::numeric_limits<double>::max();
    for (int q : incident[v]) m = std::min(m, quality(q));
    return m;
  };
  auto worst = [&] {
    double m = std::numeric_limits<double>::max();
    for (size_t q = 0; q < quads.size(); ++q) m = std::min(m, quality(static_cast<int>(q)));
    return quads.empty() ? 1.0 : m;
  };
  for (int sweep = 0; sweep < options.sweeps; ++sweep) {
    // The free nodes of poor quads and of the quads around them, in
    // ascending order (deterministic).
    std::set<int> near;
    for (size_t q = 0; q < quads.size(); ++q) {
      if (quality(static_cast<int>(q)) >= options.target) continue;
      for (int v : quads[q]) {
        for (int r : incident[static_cast<size_t>(v)])
          for (int u : quads[static_cast<size_t>(r)]) near.insert(u);
      }
    }
    if (near.empty()) break;
    bool moved = false;
    for (int vi : near) {
      const size_t v = static_cast<size_t>(vi);
      if (fixed[v]) continue;
      // Candidates: the parallelogram completion of each quad at the node
      // (a + c - b, b the opposite corner), their mean, and steps towards
      // the mean.
      std::vector<Vec3> candidates;
      Vec3 mean = Vec3::Zero();
      for (int q : incident[v]) {
        const mesh::Quad& c = quads[static_cast<size_t>(q)];
        size_t k = 0;
        while (static_cast<size_t>(c[k]) != v) ++k;
        const Vec3 p = x[static_cast<size_t>(c[(k + 1) % 4])] +
                       x[static_cast<size_t>(c[(k + 3) % 4])] -
                       x[static_cast<size_t>(c[(k + 2) % 4])];
        candidates.push_back(p);
        mean += p;
      }
      mean /= static_cast<double>(incident[v].size());
      // and the plain Laplacian (the mean of the quads' corners).
      Vec3 centre = Vec3::Zero();
      for (int q : incident[v])
        for (int u : quads[static_cast<size_t>(q)]) centre += x[static_cast<size_t>(u)];
      centre /= 4.0 * static_cast<double>(incident[v].size());
      for (double t : {1.0, 0.5, 0.25}) {
        candidates.push_back(x[v] + t * (mean - x[v]));
        candidates.push_back(x[v] + t * (centre - x[v]));
      }
      const Vec3 old_x = x[v], old_n = normals[v];
      double best = worst_at(v);
      Vec3 best_x = old_x, best_n = old_n;
      for (const Vec3& c : candidates) {
        const geom::SurfaceProjection pr = project(c, v);
        x[v] = pr.point;
        normals[v] = pr.normal;
        const double m = worst_at(v);
        if (m > best + kGain) {
          best = m;
          best_x = pr.point;
          best_n = pr.normal;
        }
      }
      x[v] = best_x;
      normals[v] = best_n;
      moved = moved || best_x != old_x;
    }
    if (!moved) break;
  }
  return worst();
}

}  // namespace cooperage::submap
