#include "schemes/pave/smooth_2d.h"

#include <algorithm>
#include <cmath>

namespace cooperage::pave::detail {
namespace {

using V2 = Eigen::Vector2d;

/// Node -> its quads in compressed rows; each entry holds the quad and its
/// other three corners counter-clockwise from the node (next, opposite,
/// previous), so that the quads around a node are evaluated without going
/// through the quad array. Rows list the quads in quad order.
struct Ring {
  struct Corner {
    int quad, next, opp, prev;
  };
  std::vector<int> start;
  std::vector<Corner> items;
  const Corner* begin(size_t i) const { return items.data() + start[i]; }
  const Corner* end(size_t i) const { return items.data() + start[i + 1]; }
};

Ring build_ring(size_t n, const std::vector<Quad>& quads) {
  Ring r;
  r.start.assign(n + 1, 0);
  for (const Quad& q : quads) {
    for (int v : q) ++r.start[static_cast<size_t>(v) + 1];
  }
  for (size_t i = 0; i < n; ++i) r.start[i + 1] += r.start[i];
  r.items.resize(static_cast<size_t>(r.start[n]));
  std::vector<int> fill(r.start.begin(), r.start.end() - 1);
  for (int k = 0; k < static_cast<int>(quads.size()); ++k) {
    const Quad& q = quads[static_cast<size_t>(k)];
    for (size_t c = 0; c < 4; ++c) {
      r.items[static_cast<size_t>(fill[static_cast<size_t>(q[c])]++)] =
          Ring::Corner{k, q[(c + 1) % 4], q[(c + 2) % 4], q[(c + 3) % 4]};
    }
  }
  return r;
}

struct Local {
  double worst = 2.0;
  double mean = 0.0;
};

/// Node i's quads as seen from i about to move (moving_corner_quad), taken
/// once while its neighbours stay put: a pattern search evaluates hundreds
/// of positions of one node.
void fix_ring(const std::vector<V2>& pts, const Ring& ring, size_t i,
              std::vector<MovingCornerQuad>& f) {
  f.clear();
  for (const Ring::Corner* c = ring.begin(i); c != ring.end(i); ++c) {
    f.push_back(moving_corner_quad(pts[static_cast<size_t>(c->next)],
                                   pts[static_cast<size_t>(c->opp)],
                                   pts[static_cast<size_t>(c->prev)]));
  }
}

/// Quality of node i's quads with i placed at x (f from fix_ring); the
/// quads' values go to out (one per ring entry).
Local local_quality(const std::vector<MovingCornerQuad>& f, const V2& x, double* out) {
  const size_t n = f.size();
  scaled_jacobians_at(f.data(), n, x, out);
  Local l;
  for (size_t q = 0; q < n; ++q) {
    l.worst = std::min(l.worst, out[q]);
    l.mean += out[q];
  }
  if (n > 0) l.mean /= static_cast<double>(n);
  return l;
}

/// local_quality of node i where it is, from the cached quad qualities.
Local cached_quality(const std::vector<double>& quality, const Ring& ring, size_t i) {
  Local l;
  const Ring::Corner* b = ring.begin(i);
  const Ring::Corner* e = ring.end(i);
  for (const Ring::Corner* c = b; c != e; ++c) {
    const double q = quality[static_cast<size_t>(c->quad)];
    l.worst = std::min(l.worst, q);
    l.mean += q;
  }
  if (e > b) l.mean /= static_cast<double>(e - b);
  return l;
}

/// Moves node i to x and stores its quads' qualities (computed at x).
void move_node(std::vector<V2>& pts, std::vector<double>& quality, const Ring& ring, size_t i,
               const V2& x, const double* values) {
  pts[i] = x;
  const Ring::Corner* b = ring.begin(i);
  for (const Ring::Corner* c = b; c != ring.end(i); ++c)
    quality[static_cast<size_t>(c->quad)] = values[c - b];
}

V2 target(const std::vector<V2>& pts, const Ring& ring, size_t i, double w) {
  V2 iso = V2::Zero();
  V2 lap = V2::Zero();
  double wsum = 0.0;
  const V2& xi = pts[i];
  for (const Ring::Corner* c = ring.begin(i); c != ring.end(i); ++c) {
    const V2& next = pts[static_cast<size_t>(c->next)];
    if (w != 0) {
      iso += next + pts[static_cast<size_t>(c->prev)] - pts[static_cast<size_t>(c->opp)];
    }
    // Each edge neighbour appears in two quads of an interior node: count it once per quad (next).
    const V2 d = next - xi;
    const double l = d.norm();
    lap += l * d;
    wsum += l;
  }
  const V2 lw = wsum > 0 ? V2(xi + lap / wsum) : xi;
  if (w == 0) return lw;
  iso /= static_cast<double>(ring.end(i) - ring.begin(i));
  return w * iso + (1 - w) * lw;
}

/// Worst corner area (cross product of the two corner edges) of node i's
/// quads with i placed at x: the objective of the untangling search.
double worst_corner_area(const std::vector<V2>& pts, const Ring& ring, size_t i, const V2& x) {
  double worst = 1e300;
  for (const Ring::Corner* c = ring.begin(i); c != ring.end(i); ++c) {
    const V2& a = pts[static_cast<size_t>(c->next)];
    const V2& b = pts[static_cast<size_t>(c->opp)];
    const V2& d = pts[static_cast<size_t>(c->prev)];
    // Corner v with next n and previous p: cross(n - v, p - v).
    worst = std::min({worst, cross2(a - x, d - x), cross2(b - a, x - a), cross2(d - b, a - b),
                      cross2(x - d, b - d)});
  }
  return worst;
}

const double kDirs[8][2] = {{1, 0},  {0.7071, 0.7071},   {0, 1},  {-0.7071, 0.7071},
                            {-1, 0}, {-0.7071, -0.7071}, {0, -1}, {0.7071, -0.7071}};

double mean_edge_at(const std::vector<V2>& pts, const Ring& ring, size_t i) {
  double len = 0.0;
  int cnt = 0;
  for (const Ring::Corner* c = ring.begin(i); c != ring.end(i); ++c) {
    len += (pts[static_cast<size_t>(c->next)] - pts[i]).norm();
    ++cnt;
  }
  return len / std::max(cnt, 1);
}

/// Untangling (Freitag & Plassmann 2000, "Local optimization-based
/// simplicial mesh untangling and improvement"): every free node of a quad
/// with a non-positive corner maximises the worst corner area of its quads.
void untangle(std::vector<V2>& pts, const std::vector<Quad>& quads, const std::vector<char>& fixed,
              const Ring& ring) {
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
      double best = worst_corner_area(pts, ring, i, pts[i]);
      double step = 0.3 * mean_edge_at(pts, ring, i);
      for (int level = 0; level < 10; ++level, step *= 0.5) {
        bool improved = true;
        for (int guard = 0; improved && guard < 20; ++guard) {
          improved = false;
          for (const auto& d : kDirs) {
            const V2 x = pts[i] + step * V2(d[0], d[1]);
            const double f = worst_corner_area(pts, ring, i, x);
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

int smooth_quads_2d(std::vector<V2>& pts, const std::vector<Quad>& quads,
                    const std::vector<char>& fixed, const SmoothOptions& opt) {
  const size_t n = pts.size();
  if (quads.empty()) return 0;
  const Ring ring = build_ring(n, quads);
  double mean_edge = 0.0;
  for (const Quad& q : quads) {
    for (int c = 0; c < 4; ++c) {
      mean_edge += (pts[static_cast<size_t>(q[static_cast<size_t>(c)])] -
                    pts[static_cast<size_t>(q[static_cast<size_t>((c + 1) % 4)])])
                       .norm();
    }
  }
  mean_edge /= 4.0 * static_cast<double>(quads.size());
  untangle(pts, quads, fixed, ring);
  std::vector<size_t> free_nodes;
  size_t widest = 0;
  for (size_t i = 0; i < n; ++i) {
    const size_t valence = static_cast<size_t>(ring.end(i) - ring.begin(i));
    widest = std::max(widest, valence);
    if (!fixed[i] && valence > 0) free_nodes.push_back(i);
  }
  // Quality of every quad, kept current as nodes move: a node's "before"
  // costs no evaluation.
  std::vector<double> quality(quads.size());
  for (size_t k = 0; k < quads.size(); ++k) quality[k] = scaled_jacobian_2d(pts, quads[k]);
  std::vector<double> values(widest);
  std::vector<MovingCornerQuad> fixed_part;
  fixed_part.reserve(widest);

  int sweeps = 0;
  for (int sweep = 0; sweep < opt.sweeps; ++sweep) {
    ++sweeps;
    double largest = 0.0;
    for (size_t i : free_nodes) {
      const V2 x0 = pts[i];
      const V2 x1 = target(pts, ring, i, opt.parallelogram_weight);
      const Local before = cached_quality(quality, ring, i);
      fix_ring(pts, ring, i, fixed_part);
      for (double f : {1.0, 0.5, 0.25}) {
        const V2 x = x0 + f * (x1 - x0);
        const Local after = local_quality(fixed_part, x, values.data());
        const bool ok = after.worst >= before.worst ||
                        (after.worst >= opt.keep_quality && after.mean > before.mean);
        if (ok) {
          move_node(pts, quality, ring, i, x, values.data());
          largest = std::max(largest, (x - x0).norm());
          break;
        }
      }
    }
    if (largest < opt.tolerance * mean_edge) break;
  }

  // Pattern search on the nodes of poor quads.
  // A node whose search found nothing and whose quads have not changed since
  // would find nothing again (the search reads only its quads), so it waits
  // until it or a node of its quads moves: the same result at a fraction of
  // the evaluations where a few poor quads stay poor every round.
  std::vector<char> stale(n, 0);
  for (int round = 0; round < opt.optimise_rounds; ++round) {
    bool any = false;
    for (size_t i : free_nodes) {
      if (stale[i]) continue;
      Local best = cached_quality(quality, ring, i);
      if (best.worst >= opt.optimise_below) continue;
      any = true;
      const V2 start = pts[i];
      fix_ring(pts, ring, i, fixed_part);
      double step = 0.2 * mean_edge_at(pts, ring, i);
      for (int level = 0; level < 8; ++level, step *= 0.5) {
        bool improved = true;
        for (int guard = 0; improved && guard < 10; ++guard) {
          improved = false;
          for (const auto& d : kDirs) {
            const V2 x = pts[i] + step * V2(d[0], d[1]);
            const Local l = local_quality(fixed_part, x, values.data());
            if (l.worst > best.worst + 1e-12) {
              best = l;
              move_node(pts, quality, ring, i, x, values.data());
              improved = true;
            }
          }
        }
      }
      if (pts[i] == start) {
        stale[i] = 1;
        continue;
      }
      for (const Ring::Corner* c = ring.begin(i); c != ring.end(i); ++c)
        for (int v : {c->next, c->opp, c->prev}) stale[static_cast<size_t>(v)] = 0;
    }
    if (!any) break;
  }

  // Polish: the nodes next to a quad below polish_below (near irregular
  // nodes, where the Laplacian places nodes by position, not by shape)
  // maximise the mean scaled Jacobian of their quads by a short pattern
  // search that never lowers their worst quad.
  for (int round = 0; round < opt.polish_rounds; ++round) {
    for (size_t i : free_nodes) {
      Local best = cached_quality(quality, ring, i);
      if (best.worst >= opt.polish_below) continue;
      // One pass of the 8 directions at 0.1 and at 0.05 mean edges: most of
      // the gain of a full search at a sixth of its cost.
      fix_ring(pts, ring, i, fixed_part);
      double step = 0.1 * mean_edge_at(pts, ring, i);
      for (int level = 0; level < 2; ++level, step *= 0.5) {
        for (const auto& d : kDirs) {
          const V2 x = pts[i] + step * V2(d[0], d[1]);
          const Local l = local_quality(fixed_part, x, values.data());
          if (l.worst >= best.worst && l.mean > best.mean + 1e-9) {
            best = l;
            move_node(pts, quality, ring, i, x, values.data());
          }
        }
      }
    }
  }
  return sweeps;
}

}  // namespace cooperage::pave::detail
