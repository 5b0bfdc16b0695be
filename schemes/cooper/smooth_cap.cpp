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

}  // namespace cooperage::cooper
