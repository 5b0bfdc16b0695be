#include "schemes/cooper/smooth_cap.h"

#include "framework/mesh/corner_sine.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>

namespace cooperage::cooper {

namespace {

template <size_t N>
double min_corner_quality(const std::vector<mesh::Vec3>& points,
                          const std::vector<std::array<int, N>>& cells, const mesh::Vec3& normal) {
  double worst = 1.0;
  for (const auto& c : cells) {
    worst = std::min(worst, mesh::min_corner_sine(points, c.data(), static_cast<int>(N), normal));
  }
  return worst;
}

}  // namespace

double min_quad_corner_quality(const std::vector<mesh::Vec3>& points,
                               const std::vector<mesh::Quad>& quads, const mesh::Vec3& normal) {
  return min_corner_quality(points, quads, normal);
}

double min_tri_corner_quality(const std::vector<mesh::Vec3>& points,
                              const std::vector<mesh::Tri>& tris, const mesh::Vec3& normal) {
  return min_corner_quality(points, tris, normal);
}

bool smooth_cap(std::vector<mesh::Vec3>& points, const std::vector<mesh::Quad>& quads,
                const std::vector<char>& movable, const mesh::Vec3& normal,
                const std::function<mesh::Vec3(const mesh::Vec3&)>& project, int iterations) {
  return smooth_cap(points, quads, {}, movable, normal, project, iterations);
}

// cite: Blacker 1996, sec. 6.1 (smoothing the subcaps of one exterior face).
bool smooth_cap(std::vector<mesh::Vec3>& points, const std::vector<mesh::Quad>& quads,
                const std::vector<mesh::Tri>& tris, const std::vector<char>& movable,
                const mesh::Vec3& normal,
                const std::function<mesh::Vec3(const mesh::Vec3&)>& project, int iterations) {
  std::vector<std::vector<int>> nbr(points.size());
  for (const auto& q : quads) {
    for (size_t k = 0; k < 4; ++k) {
      nbr[static_cast<size_t>(q[k])].push_back(q[(k + 1) % 4]);
      nbr[static_cast<size_t>(q[k])].push_back(q[(k + 3) % 4]);
    }
  }
  for (const auto& t : tris) {
    for (size_t k = 0; k < 3; ++k) {
      nbr[static_cast<size_t>(t[k])].push_back(t[(k + 1) % 3]);
      nbr[static_cast<size_t>(t[k])].push_back(t[(k + 2) % 3]);
    }
  }
  for (auto& n : nbr) {
    std::sort(n.begin(), n.end());
    n.erase(std::unique(n.begin(), n.end()), n.end());
  }
  const double before_quads = min_quad_corner_quality(points, quads, normal);
  const double before_tris = min_tri_corner_quality(points, tris, normal);
  std::vector<mesh::Vec3> trial = points;
  for (int it = 0; it < iterations; ++it) {
    for (size_t i = 0; i < trial.size(); ++i) {
      if (!movable[i] || nbr[i].empty()) continue;
      mesh::Vec3 sum = mesh::Vec3::Zero();
      for (int j : nbr[i]) sum += trial[static_cast<size_t>(j)];
      const mesh::Vec3 x = sum / static_cast<double>(nbr[i].size());
      trial[i] = project ? project(x) : x;
    }
  }
  if (min_quad_corner_quality(trial, quads, normal) < before_quads ||
      min_tri_corner_quality(trial, tris, normal) < before_tris) {
    return false;
  }
  points.swap(trial);
  return true;
}

// cite: Blacker 1996, sec. 6.1 (a smooth to optimize element quality).
bool smart_smooth_cap(std::vector<mesh::Vec3>& points, const std::vector<mesh::Quad>& quads,
                      const std::vector<mesh::Tri>& tris, const std::vector<char>& movable,
                      const mesh::Vec3& normal,
                      const std::function<mesh::Vec3(const mesh::Vec3&)>& project, int iterations) {
  const size_t n = points.size();
  std::vector<std::vector<int>> nbr(n), around_q(n), around_t(n);
  for (size_t f = 0; f < quads.size(); ++f) {
    for (size_t k = 0; k < 4; ++k) {
      const size_t v = static_cast<size_t>(quads[f][k]);
      nbr[v].push_back(quads[f][(k + 1) % 4]);
      nbr[v].push_back(quads[f][(k + 3) % 4]);
      around_q[v].push_back(static_cast<int>(f));
    }
  }
  for (size_t f = 0; f < tris.size(); ++f) {
    for (size_t k = 0; k < 3; ++k) {
      const size_t v = static_cast<size_t>(tris[f][k]);
      nbr[v].push_back(tris[f][(k + 1) % 3]);
      nbr[v].push_back(tris[f][(k + 2) % 3]);
      around_t[v].push_back(static_cast<int>(f));
    }
  }
  for (auto& list : nbr) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  auto local = [&](size_t v) {
    double worst = 1.0;
    for (int f : around_q[v])
      worst = std::min(
          worst, mesh::min_corner_sine(points, quads[static_cast<size_t>(f)].data(), 4, normal));
    for (int f : around_t[v])
      worst = std::min(
          worst, mesh::min_corner_sine(points, tris[static_cast<size_t>(f)].data(), 3, normal));
    return worst;
  };
  const double before = std::min(min_quad_corner_quality(points, quads, normal),
                                 min_tri_corner_quality(points, tris, normal));
  const std::vector<mesh::Vec3> start = points;
  for (int it = 0; it < iterations; ++it) {
    bool moved = false;
    for (size_t v = 0; v < n; ++v) {
      if (!movable[v] || nbr[v].empty()) continue;
      mesh::Vec3 sum = mesh::Vec3::Zero();
      for (int w : nbr[v]) sum += points[static_cast<size_t>(w)];
      const mesh::Vec3 x = sum / static_cast<double>(nbr[v].size());
      const mesh::Vec3 target = project ? project(x) : x;
      const double q0 = local(v);
      const mesh::Vec3 old = points[v];
      points[v] = target;
      if (local(v) + 1e-12 < q0) {
        points[v] = old;
      } else {
        moved = moved || (target - old).norm() > 0;
      }
    }
    if (!moved) break;
  }
  const double after = std::min(min_quad_corner_quality(points, quads, normal),
                                min_tri_corner_quality(points, tris, normal));
  if (after > before) return true;
  points = start;
  return false;
}

}  // namespace cooperage::cooper
