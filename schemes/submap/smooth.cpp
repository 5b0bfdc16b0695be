#include "schemes/submap/smooth.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <vector>

namespace cooperage::submap {
namespace {

constexpr double kQualityNoise = 1e-12;

}  // namespace

double quad_scaled_jacobian(const std::array<Vec3, 4>& p, const std::array<Vec3, 4>& normals) {
  double q = 1.0;
  for (size_t k = 0; k < 4; ++k) {
    const Vec3 a = p[(k + 1) % 4] - p[k];
    const Vec3 b = p[(k + 3) % 4] - p[k];
    const double la = a.norm(), lb = b.norm();
    if (la <= 0.0 || lb <= 0.0) return -1.0;
    q = std::min(q, a.cross(b).dot(normals[k]) / (la * lb));
  }
  return q;
}

double quad_scaled_jacobian(const std::vector<Vec3>& x, const std::vector<Vec3>& normals,
                            const mesh::Quad& q) {
  std::array<Vec3, 4> p, nn;
  for (size_t k = 0; k < 4; ++k) {
    p[k] = x[static_cast<size_t>(q[k])];
    nn[k] = normals[static_cast<size_t>(q[k])];
  }
  return quad_scaled_jacobian(p, nn);
}

void smooth_quads(std::vector<Vec3>& x, std::vector<Vec3>& normals, const std::vector<bool>& fixed,
                  const std::vector<mesh::Quad>& quads, const Projector& project,
                  const SmoothOptions& options) {
  const size_t n = x.size();
  // Edge neighbours ascending (the Laplacian sums them in that order) and
  // the quads at each node.
  std::vector<std::vector<int>> neighbours(n);
  std::vector<std::vector<int>> incident(n);
  for (size_t q = 0; q < quads.size(); ++q) {
    for (size_t k = 0; k < 4; ++k) {
      const int a = quads[q][k], b = quads[q][(k + 1) % 4];
      neighbours[static_cast<size_t>(a)].push_back(b);
      neighbours[static_cast<size_t>(b)].push_back(a);
      incident[static_cast<size_t>(a)].push_back(static_cast<int>(q));
    }
  }
  for (auto& row : neighbours) {
    std::sort(row.begin(), row.end());
    row.erase(std::unique(row.begin(), row.end()), row.end());
  }
  auto quality = [&](int q) {
    return quad_scaled_jacobian(x, normals, quads[static_cast<size_t>(q)]);
  };
  // Every quad's quality, kept current as nodes move: a node's "before" is
  // read, not computed again.
  std::vector<double> current(quads.size());
  for (size_t q = 0; q < quads.size(); ++q) current[q] = quality(static_cast<int>(q));
  std::vector<double> after;
  for (int sweep = 0; sweep < options.sweeps; ++sweep) {
    bool moved = false;
    for (size_t v = 0; v < n; ++v) {
      if (fixed[v] || neighbours[v].empty()) continue;
      // Length-weighted Laplacian: long edges pull harder, evening out sizes.
      Vec3 acc = Vec3::Zero();
      double wsum = 0.0;
      for (int u : neighbours[v]) {
        const double w = (x[static_cast<size_t>(u)] - x[v]).norm();
        acc += w * x[static_cast<size_t>(u)];
        wsum += w;
      }
      if (wsum <= 0.0) continue;
      // Already where the Laplacian wants it (an even lattice): no projection,
      // no quality check, nothing to do. The tolerance is relative to the
      // mean edge length, so the decision does not depend on placement.
      const double mean_edge = wsum / static_cast<double>(neighbours[v].size());
      if ((acc / wsum - x[v]).norm() <= 1e-12 * mean_edge) continue;
      const geom::SurfaceProjection pr = project(acc / wsum, v);
      // On a curved face the Laplacian point of an even lattice lies off the
      // surface and projects back onto the node: that is a fixed point too.
      // Without this test every sweep "moved" every node of a cylinder's
      // lattice and checked its quads again (issue 20).
      if ((pr.point - x[v]).norm() <= 1e-12 * mean_edge) continue;
      moved = true;
      const Vec3 old_x = x[v], old_n = normals[v];
      x[v] = pr.point;
      normals[v] = pr.normal;
      bool accept = true;
      after.clear();
      for (size_t k = 0; k < incident[v].size() && accept; ++k) {
        const int q = incident[v][k];
        after.push_back(quality(q));
        // A move that leaves a bad quad as it was (within noise) is taken,
        // so a rigid transform of the model cannot flip the decision.
        if (after.back() < options.min_quality &&
            after.back() < current[static_cast<size_t>(q)] - kQualityNoise)
          accept = false;
      }
      if (accept) {
        for (size_t k = 0; k < incident[v].size(); ++k)
          current[static_cast<size_t>(incident[v][k])] = after[k];
      } else {
        x[v] = old_x;
        normals[v] = old_n;
      }
    }
    if (!moved) break;  // a fixed point: further sweeps change nothing
  }
}

}  // namespace cooperage::submap
