// The one-barrel sweep with its safety net (Blacker 1996, sec. 6.2-6.3;
// docs/design.md, "Inverted elements are never silent").
#include "schemes/cooper/sweep_barrel.h"

#include <algorithm>
#include <sstream>
#include <utility>

namespace cooperage::cooper {
namespace {

// Sorted neighbour lists of the cap nodes over the cap element edges.
void cap_adjacency(const SweepInput& in, std::vector<int>& start, std::vector<int>& next) {
  std::vector<std::pair<int, int>> edges;
  edges.reserve(in.quads.size() * 8 + in.tris.size() * 6);
  auto add = [&](int a, int b) {
    edges.emplace_back(a, b);
    edges.emplace_back(b, a);
  };
  for (const auto& q : in.quads) {
    for (int k = 0; k < 4; ++k)
      add(q[static_cast<std::size_t>(k)], q[static_cast<std::size_t>((k + 1) % 4)]);
  }
  for (const auto& t : in.tris) {
    for (int k = 0; k < 3; ++k)
      add(t[static_cast<std::size_t>(k)], t[static_cast<std::size_t>((k + 1) % 3)]);
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  start.assign(static_cast<std::size_t>(in.cap_nodes) + 1, 0);
  for (const auto& e : edges) ++start[static_cast<std::size_t>(e.first) + 1];
  for (std::size_t i = 1; i < start.size(); ++i) start[i] += start[i - 1];
  next.clear();
  next.reserve(edges.size());
  for (const auto& e : edges) next.push_back(e.second);
}

// "hex 66 of layer 0, at (17.6, 5.7, 33), is inverted (...)": where it is,
// so that a person can find it in the part (its centre, 3 significant digits).
std::string describe_bad(const SweepInput& in, const SweepResult& out, long bad, double worst) {
  std::ostringstream s;
  const long per_layer_h = static_cast<long>(in.quads.size());
  const long total_h = per_layer_h * in.layers;
  Vec3 centre = Vec3::Zero();
  if (bad < total_h) {
    s << "hex " << bad % std::max(1L, per_layer_h) << " of layer "
      << bad / std::max(1L, per_layer_h);
    if (static_cast<size_t>(bad) < out.hexes.size()) {
      for (int n : out.hexes[static_cast<size_t>(bad)])
        centre += out.points[static_cast<size_t>(n)];
      centre /= 8.0;
    }
  } else {
    const long w = bad - total_h;
    const long per_layer_w = std::max(1L, static_cast<long>(in.tris.size()));
    s << "wedge " << w % per_layer_w << " of layer " << w / per_layer_w;
    if (static_cast<size_t>(w) < out.wedges.size()) {
      for (int n : out.wedges[static_cast<size_t>(w)]) centre += out.points[static_cast<size_t>(n)];
      centre /= 6.0;
    }
  }
  s.precision(3);
  s << ", at (" << centre.x() << ", " << centre.y() << ", " << centre.z() << "),";
  s.precision(6);
  s << " is inverted (minimum scaled Jacobian " << worst << ")";
  return s.str();
}

// Laplacian smoothing of the interior nodes of layer j; the target layer is
// re-projected and keeps its fixed targets.
void smooth_layer(const SweepInput& in, int j, int iterations, const std::vector<int>& start,
                  const std::vector<int>& next, std::vector<Vec3>& points) {
  const std::size_t n = static_cast<std::size_t>(in.cap_nodes);
  Vec3* layer = &points[static_cast<std::size_t>(j) * n];
  const bool target = j == in.layers;
  const bool fixed = target && in.has_fixed_target.size() == n;
  for (int it = 0; it < iterations; ++it) {
    for (std::size_t i = static_cast<std::size_t>(in.boundary); i < n; ++i) {
      if (fixed && in.has_fixed_target[i]) continue;
      const int b = start[i];
      const int e = start[i + 1];
      if (e == b) continue;
      Vec3 sum = Vec3::Zero();
      for (int k = b; k < e; ++k) sum += layer[next[static_cast<std::size_t>(k)]];
      layer[i] = sum / static_cast<double>(e - b);
      if (target && in.project_target) layer[i] = in.project_target(layer[i]);
    }
  }
}

}  // namespace

void smooth_layers(const SweepInput& in, int iterations, std::vector<Vec3>& points) {
  std::vector<int> start;
  std::vector<int> next;
  cap_adjacency(in, start, next);
  for (int j = 1; j <= in.layers; ++j) smooth_layer(in, j, iterations, start, next, points);
}

// A fixed target far from the projected source (a seam moved it, Blacker
// 1996 sec. 5.4) leaves its neighbours' target quads folded; smoothing the
// target cap and blending again spreads the move over the whole cap.
bool smooth_target_then_blend(const SweepInput& in, int iterations, std::vector<Vec3>& points) {
  std::vector<int> start;
  std::vector<int> next;
  cap_adjacency(in, start, next);
  smooth_layer(in, in.layers, iterations, start, next, points);
  std::string why;
  return blend_layers(in, points, why);
}

SweepResult sweep_barrel(const SweepInput& in, const SweepOptions& options) {
  SweepResult out;
  if (in.layers < 1 || in.boundary < 3 || in.cap_nodes < in.boundary ||
      in.source.size() != static_cast<std::size_t>(in.cap_nodes) ||
      in.ribs.size() !=
          static_cast<std::size_t>(in.boundary) * static_cast<std::size_t>(in.layers + 1)) {
    out.why = "inconsistent sweep input (layers, boundary, source or rib sizes)";
    return out;
  }
  std::string why;
  const bool placed = place_layer_nodes(in, out.points, why);
  make_elements(in, out.hexes, out.wedges);
  long bad = -1;
  if (placed) {
    out.min_scaled_jacobian = min_scaled_jacobian(
        out.points, out.hexes, out.wedges, options.min_scaled_jacobian, &bad, &out.scaled_jacobian);
    if (bad < 0 && out.min_scaled_jacobian >= options.improve_below) {
      out.ok = true;
      return out;
    }
  }
  // Fallbacks: a better placement by smoothing the target layer and blending
  // again, or by per-layer smoothing, ribs fixed; the best one is kept. When the
  // projection failed outright, seed the interior nodes with the source
  // positions shifted by the mean motion of their layer's rib ring.
  std::vector<Vec3> smoothed = out.points;
  if (!placed) {
    const std::size_t n = static_cast<std::size_t>(in.cap_nodes);
    const std::size_t J1 = static_cast<std::size_t>(in.layers) + 1;
    for (std::size_t j = 1; j < J1; ++j) {
      Vec3 shift = Vec3::Zero();
      for (std::size_t r = 0; r < static_cast<std::size_t>(in.boundary); ++r) {
        shift += in.ribs[r * J1 + j] - in.source[r];
      }
      shift /= static_cast<double>(in.boundary);
      for (std::size_t i = static_cast<std::size_t>(in.boundary); i < n; ++i) {
        if (j + 1 == J1 && in.has_fixed_target.size() == n && in.has_fixed_target[i]) {
          smoothed[j * n + i] = in.fixed_target[i];
        } else {
          smoothed[j * n + i] = in.source[i] + shift;
        }
      }
    }
  }
  if (placed) {
    std::vector<Vec3> relaxed = out.points;
    long bad_relaxed = -1;
    if (smooth_target_then_blend(in, options.smoothing_iterations, relaxed)) {
      const double worst_relaxed = min_scaled_jacobian(relaxed, out.hexes, out.wedges,
                                                       options.min_scaled_jacobian, &bad_relaxed);
      if (worst_relaxed > out.min_scaled_jacobian) {
        out.points.swap(relaxed);
        out.min_scaled_jacobian = worst_relaxed;
        out.smoothed = true;
        bad = bad_relaxed;
      }
    }
  }
  smooth_layers(in, options.smoothing_iterations, smoothed);
  long bad_smoothed = -1;
  const double worst_smoothed = min_scaled_jacobian(smoothed, out.hexes, out.wedges,
                                                    options.min_scaled_jacobian, &bad_smoothed);
  if (!placed || worst_smoothed > out.min_scaled_jacobian) {
    out.points.swap(smoothed);
    out.min_scaled_jacobian = worst_smoothed;
    out.smoothed = true;
    bad = bad_smoothed;
  }
  if (out.smoothed) out.scaled_jacobian = {};
  if (bad < 0) {
    out.ok = true;
    return out;
  }
  out.why = (placed ? std::string() : why + "; ") +
            describe_bad(in, out, bad, out.min_scaled_jacobian) +
            " after the least-squares projection and the smoothing fallback";
  return out;
}

}  // namespace cooperage::cooper
