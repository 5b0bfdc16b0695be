#include "schemes/pave/smooth_2d.h"

#include <algorithm>
#include <cmath>

namespace cooperage::pave::detail {
namespace {

using V2 = Eigen::Vector2d;

/// Node -> (quad, corner) incidence in compressed rows.
struct Incidence {
  std::vector<int> start;
  std::vector<std::pair<int, int>> items;
};

Incidence build_incidence(size_t n, const std::vector<Quad>& quads) {
  Incidence inc;
  inc.start.assign(n + 1, 0);
  for (const Quad& q : quads) {
    for (int v : q) ++inc.start[static_cast<size_t>(v) + 1];
  }
  for (size_t i = 0; i < n; ++i) inc.start[i + 1] += inc.start[i];
  inc.items.resize(static_cast<size_t>(inc.start[n]));
  std::vector<int> fill(inc.start.begin(), inc.start.end() - 1);
  for (int k = 0; k < static_cast<int>(quads.size()); ++k) {
    for (int c = 0; c < 4; ++c) {
      const size_t v = static_cast<size_t>(quads[static_cast<size_t>(k)][static_cast<size_t>(c)]);
      inc.items[static_cast<size_t>(fill[v]++)] = {k, c};
    }
  }
  return inc;
}

struct Local {
  double worst = 2.0;
  double mean = 0.0;
};

/// Quality of node i's quads with i placed at x.
Local local_quality(std::vector<V2>& pts, const std::vector<Quad>& quads, const Incidence& inc,
                    size_t i, const V2& x) {
  const V2 saved = pts[i];
  pts[i] = x;
  Local l;
  const int b = inc.start[i], e = inc.start[i + 1];
  for (int k = b; k < e; ++k) {
    const double q = scaled_jacobian_2d(pts, quads[static_cast<size_t>(inc.items[static_cast<size_t>(k)].first)]);
    l.worst = std::min(l.worst, q);
    l.mean += q;
  }
  if (e > b) l.mean /= (e - b);
  pts[i] = saved;
  return l;
}

V2 target(const std::vector<V2>& pts, const std::vector<Quad>& quads, const Incidence& inc, size_t i, double w) {
  V2 iso = V2::Zero();
  V2 lap = V2::Zero();
  double wsum = 0.0;
  const int b = inc.start[i], e = inc.start[i + 1];
  const V2& xi = pts[i];
  for (int k = b; k < e; ++k) {
    const auto [qi, c] = inc.items[static_cast<size_t>(k)];
    const Quad& q = quads[static_cast<size_t>(qi)];
    const V2& next = pts[static_cast<size_t>(q[static_cast<size_t>((c + 1) % 4)])];
    const V2& prev = pts[static_cast<size_t>(q[static_cast<size_t>((c + 3) % 4)])];
    const V2& opp = pts[static_cast<size_t>(q[static_cast<size_t>((c + 2) % 4)])];
    iso += next + prev - opp;
    // Each edge neighbour appears in two quads of an interior node: count it once per quad (next).
    const V2 d = next - xi;
    const double l = d.norm();
    lap += l * d;
    wsum += l;
  }
  iso /= (e - b);
  const V2 lw = wsum > 0 ? V2(xi + lap / wsum) : xi;
  return w * iso + (1 - w) * lw;
}

/// Worst corner area (cross product of the two corner edges) of node i's
/// quads with i placed at x: the objective of the untangling search.
double worst_corner_area(std::vector<V2>& pts, const std::vector<Quad>& quads, const Incidence& inc,
                         size_t i, const V2& x) {
  const V2 saved = pts[i];
  pts[i] = x;
  double worst = 1e300;
  for (int k = inc.start[i]; k < inc.start[i + 1]; ++k) {
    const Quad& q = quads[static_cast<size_t>(inc.items[static_cast<size_t>(k)].first)];
    for (int c = 0; c < 4; ++c) {
      const V2& p = pts[static_cast<size_t>(q[static_cast<size_t>(c)])];
      const V2 e0 = pts[static_cast<size_t>(q[static_cast<size_t>((c + 1) % 4)])] - p;
      const V2 e1 = pts[static_cast<size_t>(q[static_cast<size_t>((c + 3) % 4)])] - p;
      worst = std::min(worst, cross2(e0, e1));
    }
  }
  pts[i] = saved;
  return worst;
}

const double kDirs[8][2] = {{1, 0}, {0.7071, 0.7071}, {0, 1}, {-0.7071, 0.7071},
                            {-1, 0}, {-0.7071, -0.7071}, {0, -1}, {0.7071, -0.7071}};

double mean_edge_at(const std::vector<V2>& pts, const std::vector<Quad>& quads, const Incidence& inc, size_t i) {
  double len = 0.0;
  int cnt = 0;
  for (int k = inc.start[i]; k < inc.start[i + 1]; ++k) {
    const auto [qi, c] = inc.items[static_cast<size_t>(k)];
    len += (pts[static_cast<size_t>(quads[static_cast<size_t>(qi)][static_cast<size_t>((c + 1) % 4)])] - pts[i]).norm();
    ++cnt;
  }
  return len / std::max(cnt, 1);
}

/// Untangling (Freitag & Plassmann 2000, "Local optimization-based
/// simplicial mesh untangling and improvement"): every free node of a quad
/// with a non-positive corner maximises the worst corner area of its quads.
void untangle(std::vector<V2>& pts, const std::vector<Quad>& quads, const std::vector<char>& fixed,
              const Incidence& inc) {
  for (int round = 0; round < 30; ++round) {
    std::vector<char> todo(pts.size(), 0);
    bool any = false;
    for (const Quad& q : quads) {
      if (scaled_jacobian_2d(pts, q) > 0.02) continue;
      for (int v : q) {
        if (!fixed[static_cast<size_t>(v)]) todo[static_cast<size_t>(v)] = 1;
      }
      any = true;
    }
    if (!any) return;
    for (size_t i = 0; i < pts.size(); ++i) {
      if (!todo[i]) continue;
      double best = worst_corner_area(pts, quads, inc, i, pts[i]);
      double step = 0.3 * mean_edge_at(pts, quads, inc, i);
      for (int level = 0; level < 10; ++level, step *= 0.5) {
        bool improved = true;
        for (int guard = 0; improved && guard < 20; ++guard) {
          improved = false;
          for (const auto& d : kDirs) {
            const V2 x = pts[i] + step * V2(d[0], d[1]);
            const double f = worst_corner_area(pts, quads, inc, i, x);
            if (f > best) {
              best = f;
              pts[i] = x;
              improved = true;
            }
          }
        }
      }
    }
  }
}

}  // namespace

int smooth_quads_2d(std::vector<V2>& pts, const std::vector<Quad>& quads, const std::vector<char>& fixed,
                     const SmoothOptions& opt) {
  const size_t n = pts.size();
  if (quads.empty()) return 0;
  const Incidence inc = build_incidence(n, quads);
  double mean_edge = 0.0;
  for (const Quad& q : quads) {
    for (int c = 0; c < 4; ++c) {
      mean_edge += (pts[static_cast<size_t>(q[static_cast<size_t>(c)])] -
                    pts[static_cast<size_t>(q[static_cast<size_t>((c + 1) % 4)])]).norm();
    }
  }
  mean_edge /= 4.0 * static_cast<double>(quads.size());
  untangle(pts, quads, fixed, inc);
  std::vector<size_t> free_nodes;
  for (size_t i = 0; i < n; ++i) {
    if (!fixed[i] && inc.start[i + 1] > inc.start[i]) free_nodes.push_back(i);
  }

  int sweeps = 0;
  for (int sweep = 0; sweep < opt.sweeps; ++sweep) {
    ++sweeps;
    double largest = 0.0;
    for (size_t i : free_nodes) {
      const V2 x0 = pts[i];
      const V2 x1 = target(pts, quads, inc, i, opt.parallelogram_weight);
      const Local before = local_quality(pts, quads, inc, i, x0);
      for (double f : {1.0, 0.5, 0.25}) {
        const V2 x = x0 + f * (x1 - x0);
        const Local after = local_quality(pts, quads, inc, i, x);
        const bool ok = after.worst >= before.worst ||
                        (after.worst >= opt.keep_quality && after.mean > before.mean);
        if (ok) {
          pts[i] = x;
          largest = std::max(largest, (x - x0).norm());
          break;
        }
      }
    }
    if (largest < opt.tolerance * mean_edge) break;
  }

  // Pattern search on the nodes of poor quads.
  for (int round = 0; round < opt.optimise_rounds; ++round) {
    bool any = false;
    for (size_t i : free_nodes) {
      Local best = local_quality(pts, quads, inc, i, pts[i]);
      if (best.worst >= opt.optimise_below) continue;
      any = true;
      double step = 0.2 * mean_edge_at(pts, quads, inc, i);
      for (int level = 0; level < 8; ++level, step *= 0.5) {
        bool improved = true;
        for (int guard = 0; improved && guard < 10; ++guard) {
          improved = false;
          for (const auto& d : kDirs) {
            const V2 x = pts[i] + step * V2(d[0], d[1]);
            const Local l = local_quality(pts, quads, inc, i, x);
            if (l.worst > best.worst + 1e-12) {
              best = l;
              pts[i] = x;
              improved = true;
            }
          }
        }
      }
    }
    if (!any) break;
  }
  return sweeps;
}

}  // namespace cooperage::pave::detail
