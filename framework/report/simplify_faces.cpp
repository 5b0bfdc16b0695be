#include "framework/report/simplify_faces.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>

namespace cooperage::report {
namespace {

using Face = std::array<int, 4>;

struct FaceHash {
  std::size_t operator()(const Face& f) const {
    std::size_t h = 1469598103934665603ull;
    for (int v : f) h = (h ^ static_cast<std::size_t>(static_cast<unsigned>(v))) * 1099511628211ull;
    return h;
  }
};

// The cluster of every point for a grid of `cells` cells along the longest
// side; clusters are numbered in order of first appearance.
std::vector<int> cluster_points(const std::vector<Eigen::Vector3d>& points, int cells,
                                int& cluster_count) {
  Eigen::Vector3d lo = points.front(), hi = points.front();
  for (const auto& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double extent = std::max((hi - lo).maxCoeff(), 1e-300);
  const double cell = extent / cells;
  std::unordered_map<std::int64_t, int> ids;
  std::vector<int> cluster(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    std::int64_t key = 0;
    for (int c = 0; c < 3; ++c) {
      const auto k = static_cast<std::int64_t>(
          std::min<double>(std::floor((points[i][c] - lo[c]) / cell), cells - 1));
      key = key * (cells + 1) + k;
    }
    cluster[i] = ids.emplace(key, static_cast<int>(ids.size())).first->second;
  }
  cluster_count = static_cast<int>(ids.size());
  return cluster;
}

// Faces over clusters: consecutive repeats removed, fewer than three
// distinct corners dropped (their value goes to the kept faces at their
// clusters), duplicates (same corner set) merged keeping the lowest value.
// Output in order of first appearance.
void collapse_faces(const FaceSoup& in, const std::vector<int>& cluster, int cluster_count,
                    std::vector<Face>& faces, std::vector<double>& values) {
  faces.clear();
  values.clear();
  std::vector<double> collapsed(static_cast<std::size_t>(cluster_count),
                                std::numeric_limits<double>::infinity());
  std::unordered_map<Face, std::size_t, FaceHash> seen;
  seen.reserve(in.faces.size());
  for (std::size_t f = 0; f < in.faces.size(); ++f) {
    const Face& face = in.faces[f];
    const int n = face[3] < 0 ? 3 : 4;
    int corners[4];
    int m = 0;
    for (int k = 0; k < n; ++k) {
      const int c = cluster[static_cast<std::size_t>(face[k])];
      if (m > 0 && corners[m - 1] == c) continue;
      corners[m++] = c;
    }
    while (m > 1 && corners[m - 1] == corners[0]) --m;
    if (m < 3) {
      // A collapsed face passes its value to the faces around it.
      for (int k = 0; k < m; ++k) {
        double& v = collapsed[static_cast<std::size_t>(corners[k])];
        v = std::min(v, in.values[f]);
      }
      continue;
    }
    Face out{corners[0], corners[1], corners[2], m == 4 ? corners[3] : -1};
    if (m == 4 && (out[0] == out[2] || out[1] == out[3])) continue;  // bow tie
    Face key = out;
    std::sort(key.begin(), key.end());
    const auto [it, fresh] = seen.emplace(key, faces.size());
    if (fresh) {
      faces.push_back(out);
      values.push_back(in.values[f]);
    } else {
      values[it->second] = std::min(values[it->second], in.values[f]);
    }
  }
  for (std::size_t f = 0; f < faces.size(); ++f) {
    for (int c : faces[f]) {
      if (c >= 0) values[f] = std::min(values[f], collapsed[static_cast<std::size_t>(c)]);
    }
  }
}

}  // namespace

FaceSoup simplify_faces(const FaceSoup& in, std::size_t max_faces) {
  if (in.faces.size() <= max_faces || in.points.empty()) return in;
  std::vector<Face> faces;
  std::vector<double> values;
  int clusters = 0;
  // The face count grows with the grid resolution (not strictly, but
  // closely enough for a picture): bisect for the finest grid in budget.
  int lo = 1, hi = 4096;
  while (lo < hi) {
    const int mid = (lo + hi + 1) / 2;
    const std::vector<int> cluster = cluster_points(in.points, mid, clusters);
    collapse_faces(in, cluster, clusters, faces, values);
    if (faces.size() <= max_faces)
      lo = mid;
    else
      hi = mid - 1;
  }
  const std::vector<int> cluster = cluster_points(in.points, lo, clusters);
  collapse_faces(in, cluster, clusters, faces, values);
  // Each used cluster becomes one point at the mean of its members.
  std::vector<int> used(static_cast<std::size_t>(clusters), -1);
  FaceSoup out;
  for (Face& f : faces) {
    for (int& c : f) {
      if (c < 0) continue;
      int& u = used[static_cast<std::size_t>(c)];
      if (u < 0) {
        u = static_cast<int>(out.points.size());
        out.points.emplace_back(0, 0, 0);
      }
      c = u;
    }
  }
  std::vector<int> members(out.points.size(), 0);
  for (std::size_t i = 0; i < in.points.size(); ++i) {
    const int u = used[static_cast<std::size_t>(cluster[i])];
    if (u < 0) continue;
    out.points[static_cast<std::size_t>(u)] += in.points[i];
    ++members[static_cast<std::size_t>(u)];
  }
  for (std::size_t c = 0; c < out.points.size(); ++c) out.points[c] /= members[c];
  out.faces = std::move(faces);
  out.values = std::move(values);
  return out;
}

}  // namespace cooperage::report
