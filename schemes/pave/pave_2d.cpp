#include "schemes/pave/pave_2d.h"

#include "framework/core/error.h"
#include "schemes/pave/cdt_2d.h"
#include "schemes/pave/cleanup_2d.h"
#include "schemes/pave/coarse_loops.h"
#include "schemes/pave/parity_paths.h"
#include "schemes/pave/recombine.h"
#include "schemes/pave/split_to_quads.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>  // clock_gettime (POSIX)
#include <cstdlib>
#include <cstdint>
#include <unordered_map>
#include <unordered_set>
#include <stdexcept>
#include <string>

namespace cooperage::pave {
namespace {

using V2 = Eigen::Vector2d;

[[noreturn]] void invalid(const std::string& message) {
  throw MeshingError(ErrorCode::InvalidInput, message);
}
[[noreturn]] void failed(const std::string& message) {
  throw MeshingError(ErrorCode::MeshingFailed, message);
}

double signed_area(const std::vector<V2>& P, const std::vector<int>& loop) {
  double a = 0.0;
  for (size_t k = 0; k < loop.size(); ++k) {
    a += detail::cross2(P[static_cast<size_t>(loop[k])],
                        P[static_cast<size_t>(loop[(k + 1) % loop.size()])]);
  }
  return 0.5 * a;
}

/// A rigid frame fixed by the input itself (first node, first edge) plus a
/// scale, with coordinates snapped to a fine lattice, so that a rotated or
/// translated input gives bit-identical working coordinates. The lattice
/// (2^-30 of the reach) must be far coarser than a rotation's rounding: a
/// coordinate near a lattice boundary snaps either way, and on regular
/// polygons (cocircular points) the exact predicates then break ties
/// differently. At 2^-40 a regular annulus rotated at random gave another
/// mesh 22 times in 40.
struct CanonicalFrame {
  V2 origin, ex;
  double scale = 1.0;
  static constexpr double kQuantum = 1.0 / 1073741824.0;  // 2^-30

  V2 to(const V2& p) const {
    const V2 d = (p - origin) / scale;
    V2 r(d.dot(ex), detail::cross2(ex, d));
    return V2(std::round(r.x() / kQuantum) * kQuantum, std::round(r.y() / kQuantum) * kQuantum);
  }
  V2 from(const V2& r) const { return origin + scale * (r.x() * ex + r.y() * V2(-ex.y(), ex.x())); }
};

/// This thread's CPU time [s] (std::clock() would count every thread of the
/// process: the pipeline meshes several surfaces at once).
double thread_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

/// Adds the thread CPU time since the last lap to *slot (no-op without stats).
class Laps {
 public:
  explicit Laps(PaveStats* stats) : stats_(stats), last_(stats ? thread_seconds() : 0.0) {}
  void lap(double PaveStats::*slot) {
    if (stats_ == nullptr) return;
    const double now = thread_seconds();
    stats_->*slot += now - last_;
    last_ = now;
  }

 private:
  PaveStats* stats_;
  double last_;
};

/// The last line of defence: the quads must tile the domain exactly. Every
/// loop edge is used once in its direction and never against it, every
/// other edge once in each direction, and the quads' area is the loops' area.
void check_tiling(const std::vector<V2>& P, const std::vector<std::vector<int>>& loops,
                  const std::vector<detail::Quad>& quads) {
  // The directed quad edges in compressed rows by their start node (a hash
  // map of all edges thrashes the cache on large meshes; a row holds ~4).
  const size_t n = P.size();
  std::vector<int> start(n + 1, 0);
  for (const auto& q : quads) {
    for (int v : q) ++start[static_cast<size_t>(v) + 1];
  }
  for (size_t i = 0; i < n; ++i) start[i + 1] += start[i];
  std::vector<int> to(static_cast<size_t>(start[n]));
  std::vector<int> fill(start.begin(), start.end() - 1);
  auto has = [&](int a, int b) {
    for (int k = start[static_cast<size_t>(a)]; k < fill[static_cast<size_t>(a)]; ++k) {
      if (to[static_cast<size_t>(k)] == b) return true;
    }
    return false;
  };
  double area = 0.0;
  for (const auto& q : quads) {
    for (int c = 0; c < 4; ++c) {
      const int a = q[static_cast<size_t>(c)], b = q[static_cast<size_t>((c + 1) % 4)];
      if (has(a, b)) failed("two quads share an edge in the same direction");
      to[static_cast<size_t>(fill[static_cast<size_t>(a)]++)] = b;
    }
    area += 0.5 * detail::cross2(P[static_cast<size_t>(q[2])] - P[static_cast<size_t>(q[0])],
                                 P[static_cast<size_t>(q[3])] - P[static_cast<size_t>(q[1])]);
  }
  size_t boundary_edges = 0;
  double loop_area = 0.0;
  for (const auto& l : loops) {
    for (size_t k = 0; k < l.size(); ++k) {
      const int a = l[k], b = l[(k + 1) % l.size()];
      if (!has(a, b) || has(b, a)) failed("a boundary edge is not covered exactly once");
      loop_area += 0.5 * detail::cross2(P[static_cast<size_t>(a)], P[static_cast<size_t>(b)]);
      ++boundary_edges;
    }
  }
  size_t unpaired = 0;
  for (size_t a = 0; a < n; ++a) {
    for (int k = start[a]; k < fill[a]; ++k) {
      if (!has(to[static_cast<size_t>(k)], static_cast<int>(a))) ++unpaired;
    }
  }
  if (unpaired != boundary_edges) failed("the quads leave a gap or overlap (free interior edge)");
  if (std::abs(area - loop_area) > 1e-9 * std::max(std::abs(loop_area), 1e-300) + 1e-12) {
    failed("the quads do not tile the domain (area mismatch)");
  }
}

/// The smoothed points of the unsmoothed meshes an earlier attempt smoothed:
/// retry settings often change nothing on a face (no tip near the angles
/// they move, no four-node hole), and smoothing is most of an attempt's time
/// and depends on nothing but the mesh and its smoothing options, which all
/// attempts share.
struct SmoothMemo {
  struct Entry {
    std::vector<V2> before, after;
    std::vector<detail::Quad> quads;
    int sweeps = 0;
  };
  std::vector<Entry> entries;
};

/// Steps (b)-(f) on the canonical points P (the nb loop nodes first) with
/// one set of options; returns the quads and extends P.
std::vector<detail::Quad> mesh_once(std::vector<V2>& P, const std::vector<std::vector<int>>& ids,
                                    int nb, const PaveOptions& options, SmoothMemo& memo) {
  Laps laps(options.stats);
  std::vector<detail::Quad> quads;
  if (ids.size() == 1 && ids[0].size() == 4) {
    if (detail::scaled_jacobian_2d(P, {0, 1, 2, 3}) > 1e-6) {
      quads.push_back({0, 1, 2, 3});
    } else {
      // A four-node loop with a reflex corner (a dart: an imprinted sliver
      // between two features) is no quad; a quad inside it, joined to each
      // corner, splits the reflex angle. Smoothing places the inner nodes.
      V2 centre = V2::Zero();
      for (int i = 0; i < 4; ++i) centre += 0.25 * P[static_cast<size_t>(i)];
      for (int i = 0; i < 4; ++i) P.push_back(0.5 * (P[static_cast<size_t>(i)] + centre));
      for (int i = 0; i < 4; ++i) quads.push_back({i, (i + 1) % 4, 4 + (i + 1) % 4, 4 + i});
      quads.push_back({4, 5, 6, 7});
    }
  } else {
    // (b) coarse loops; small holes first get a ring of quads.
    std::vector<std::vector<int>> work = ids;
    for (size_t l = 0; l < work.size(); ++l) {
      if (work[l].size() != 4) continue;
      work[l] = detail::ring_around_small_hole(work[l], options.ring_width, P, quads);
    }
    for (size_t l = 0; l < work.size(); ++l) {
      std::vector<int>& loop = work[l];
      std::vector<std::vector<int>> others;
      for (size_t o = 0; o < work.size(); ++o) {
        if (o != l) others.push_back(work[o]);
      }
      for (int pass = 0; pass < 4; ++pass) {
        std::vector<int> wrapped =
            detail::wrap_reflex_tips(loop, options.tip_angle * M_PI / 180.0, nb, P, quads,
                                     options.corner_angle * M_PI / 180.0, others);
        if (wrapped.size() == loop.size()) break;
        loop = std::move(wrapped);
      }
    }
    detail::CoarseBoundary coarse;
    try {
      coarse = detail::coarse_boundary(P, work, options.boundary_rows, options.odd_edge_rank,
                                       options.corner_angle * M_PI / 180.0, options.frontal);
    } catch (const std::runtime_error& err) {
      failed(err.what());
    }
    laps.lap(&PaveStats::boundary);

    // (c) refined constrained Delaunay triangulation of the coarse loops.
    detail::CdtInput in;
    in.points = coarse.points;
    in.sizes = coarse.sizes;
    in.loops = coarse.loops;
    in.min_triangles = coarse.min_cells;
    in.seeds = coarse.seeds;
    in.seed_from = coarse.seed_from;
    in.seed_sizes = coarse.seed_sizes;
    in.max_radius = options.max_radius;
    in.frontal = options.frontal;
    in.accept_radius = options.accept_radius;
    detail::Triangulation2D tri;
    try {
      tri = detail::constrained_delaunay(in);
    } catch (const std::runtime_error& err) {
      failed(std::string("triangulation of the boundary failed (") + err.what() +
             "); the loops may touch or cross");
    }
    laps.lap(&PaveStats::triangulate);
    // (d) recombination, (e) all-quad split.
    std::vector<detail::Cell> cells =
        detail::recombine(tri, options.recombine_quality, coarse.min_cells);
    detail::split_loop_triangles(cells, tri.points, coarse.loops, coarse.odd_edges,
                                 detail::LoopTriangles::OddEars);

    std::unordered_set<std::uint64_t> no_midpoint;
    try {
      no_midpoint = detail::parity_paths(cells, coarse.odd_edges);
    } catch (const std::runtime_error& first) {
      // Boundary triangles walled the odd edges in: open them all and retry.
      if (detail::split_loop_triangles(cells, tri.points, coarse.loops, coarse.odd_edges,
                                       detail::LoopTriangles::All) == 0)
        failed(first.what());
      try {
        no_midpoint = detail::parity_paths(cells, coarse.odd_edges);
      } catch (const std::runtime_error& err) {
        failed(err.what());
      }
    }
    std::vector<int> fine_of_coarse(tri.points.size(), -1);
    for (size_t c = 0; c < coarse.fine_of_coarse.size(); ++c)
      fine_of_coarse[c] = coarse.fine_of_coarse[c];
    laps.lap(&PaveStats::recombine);
    detail::split_to_quads(cells, tri.points, fine_of_coarse, coarse.midpoint, P, quads,
                           no_midpoint);
    laps.lap(&PaveStats::split);
  }

  // (f) cleanup and smoothing.
  std::vector<char> fixed(P.size(), 0);
  for (int i = 0; i < nb; ++i) fixed[static_cast<size_t>(i)] = 1;
  if (options.cleanup && options.halfedge_cleanup) {
    try {
      detail::halfedge_cleanup(P, quads, fixed, options.halfedge);
    } catch (const std::runtime_error& err) {
      failed(err.what());
    }
  } else if (options.cleanup) {
    detail::remove_doublets(P, quads, fixed);
    for (int pass = 0; pass < 3 && detail::collapse_diamonds(P, quads, fixed) > 0; ++pass) {
    }
    detail::remove_doublets(P, quads, fixed);
  }
  laps.lap(&PaveStats::cleanup);
  const auto same = std::find_if(memo.entries.begin(), memo.entries.end(),
                                 [&](const auto& e) { return e.quads == quads && e.before == P; });
  if (same != memo.entries.end()) {
    P = same->after;
    if (options.stats != nullptr) options.stats->sweeps = same->sweeps;
  } else {
    SmoothMemo::Entry entry{P, {}, quads, 0};
    entry.sweeps = detail::smooth_quads_2d(P, quads, fixed, options.smooth);
    entry.after = P;
    if (options.stats != nullptr) options.stats->sweeps = entry.sweeps;
    memo.entries.push_back(std::move(entry));
  }
  laps.lap(&PaveStats::smooth);
  for (size_t k = 0; k < quads.size(); ++k) {
    if (options.check_inversion && !(detail::scaled_jacobian_2d(P, quads[k]) > 1e-6)) {
      failed("quad " + std::to_string(k) + " is inverted or degenerate after smoothing");
    }
  }

  if (options.check_inversion) check_tiling(P, ids, quads);
  laps.lap(&PaveStats::check);
  return quads;
}

/// Other first nodes of the outer loop pave_2d tries when the first folds.
constexpr size_t kRetryStarts = 6;

/// A frontal mesh this good is kept without trying the other coarse
/// triangulation: a circumcentre mesh's median is ~0.98 (8-11 irregular
/// nodes per 100 quads), so it could only win by its minimum, and a 45
/// degree corner (0.707) is the usual floor of both on large faces.
constexpr double kFrontalGoodMedian = 0.98;
constexpr double kFrontalGoodWorst = 0.7;

/// Worst and median scaled Jacobian of a mesh, to choose between attempts.
struct MeshScore {
  double worst = -2.0;  // below any scaled Jacobian: no mesh yet
  double median = -2.0;
  /// Above the floor beats below it; below it, the worst quad decides;
  /// above it, the median plus a quarter of the worst (both goals count).
  bool better_than(const MeshScore& o, double floor) const {
    if ((worst >= floor) != (o.worst >= floor)) return worst >= floor;
    if (worst < floor) return worst > o.worst;
    return median + 0.25 * worst > o.median + 0.25 * o.worst;
  }
};

MeshScore score_mesh(const std::vector<V2>& P, const std::vector<detail::Quad>& quads) {
  MeshScore s;
  if (quads.empty()) return s;
  std::vector<double> q(quads.size());
  for (size_t k = 0; k < quads.size(); ++k) q[k] = detail::scaled_jacobian_2d(P, quads[k]);
  s.worst = *std::min_element(q.begin(), q.end());
  auto mid = q.begin() + static_cast<std::ptrdiff_t>(q.size() / 2);
  std::nth_element(q.begin(), mid, q.end());
  s.median = *mid;
  return s;
}

// pave_2d with the canonical frame of the outer loop's first node.
QuadMesh2D pave_2d_once(const std::vector<std::vector<V2>>& loops, const PaveOptions& options) {
  if (loops.empty()) invalid("no boundary loop");
  size_t total = 0;
  for (const auto& l : loops) total += l.size();
  if (total % 2 != 0) {
    invalid("odd number of boundary nodes (" + std::to_string(total) +
            "): no all-quad mesh exists; the boundary interval count must be even");
  }
  for (size_t l = 0; l < loops.size(); ++l) {
    if (loops[l].size() < 4) {
      invalid("loop " + std::to_string(l) + " has " + std::to_string(loops[l].size()) +
              " boundary nodes; pave needs at least 4 on every loop");
    }
  }

  // (a) canonical frame.
  CanonicalFrame frame;
  frame.origin = loops[0][0];
  const V2 e = loops[0][1] - loops[0][0];
  if (!(e.norm() > 0)) invalid("the first two boundary nodes coincide");
  frame.ex = e.normalized();
  // A rotation-invariant scale: the largest distance from the first node.
  double reach = 0.0;
  for (const auto& l : loops) {
    for (const auto& p : l) reach = std::max(reach, (p - frame.origin).norm());
  }
  frame.scale = std::max(reach, 1e-300);
  std::vector<V2> P0;
  P0.reserve(total);
  std::vector<std::vector<int>> ids(loops.size());
  for (size_t l = 0; l < loops.size(); ++l) {
    for (const V2& p : loops[l]) {
      ids[l].push_back(static_cast<int>(P0.size()));
      P0.push_back(frame.to(p));
    }
  }
  const int nb = static_cast<int>(P0.size());
  if (signed_area(P0, ids[0]) <= 0) invalid("the outer loop is not counter-clockwise");
  for (size_t l = 1; l < ids.size(); ++l) {
    if (signed_area(P0, ids[l]) >= 0)
      invalid("hole loop " + std::to_string(l) + " is not clockwise");
  }

  for (size_t l = 1; l < ids.size(); ++l) {
    // Crossing number of the hole's first node against the outer loop.
    const V2 q = P0[static_cast<size_t>(ids[l][0])];
    bool in = false;
    const auto& o = ids[0];
    for (size_t k = 0, j = o.size() - 1; k < o.size(); j = k++) {
      const V2 a = P0[static_cast<size_t>(o[k])], b = P0[static_cast<size_t>(o[j])];
      if ((a.y() > q.y()) != (b.y() > q.y()) &&
          q.x() < (b.x() - a.x()) * (q.y() - a.y()) / (b.y() - a.y()) + a.x()) {
        in = !in;
      }
    }
    if (!in) invalid("hole loop " + std::to_string(l) + " lies outside the outer loop");
  }

  if (ids.size() > 1 && ids[0].size() == 4)
    invalid("an outer loop of 4 nodes cannot surround holes; give it at least 6");

  // Two coarse triangulations first: the frontal one (rows of right
  // triangles, near-structured where the loops allow) and plain
  // circumcentre refinement (better where fronts of mismatched spacing
  // collide in a narrow region); the better mesh is kept, and the second is
  // not tried when the frontal mesh is already very good. A mesh below
  // options.retry_below is retried (circumcentre refinement) with other
  // settings: wrapping more tips,
  // a narrower ring around 4-node holes, no tip wrapping and one parity per
  // loop, stricter recombination (fewer, better quads); then the first two
  // again with the finer triangulation of earlier versions (a coarse
  // triangulation can be too coarse for a thin feature).
  std::vector<PaveOptions> attempts(4, options);
  attempts[1].tip_angle = 200.0;
  attempts[1].ring_width = 0.5;
  attempts[2].tip_angle = 360.0;
  attempts[2].recombine_quality = 0.6;
  attempts[2].corner_angle = 0.0;  // one parity per loop: fewer odd edges
  attempts[3].tip_angle = 180.0;
  attempts[3].ring_width = 0.35;
  attempts[3].recombine_quality = 0.9;
  for (size_t k = 0; k < attempts.size(); ++k) attempts[k].odd_edge_rank = static_cast<int>(k);
  for (size_t k = 0; k < 2; ++k) {
    attempts.push_back(attempts[k]);
    attempts.back().max_radius = std::min(options.max_radius, 0.64);
  }
  // Retries refine by circumcentres: that chain met every random face.
  for (auto& a : attempts) a.frontal = false;
  const bool both_triangulations = options.frontal;
  if (both_triangulations) {
    PaveOptions frontal = attempts[0];
    frontal.frontal = true;
    attempts.insert(attempts.begin(), frontal);
  }
  std::vector<V2> P;
  std::vector<detail::Quad> quads;
  MeshScore best;
  if (options.stats != nullptr) *options.stats = PaveStats{};
  SmoothMemo memo;
  for (size_t k = 0; k < attempts.size(); ++k) {
    if (options.stats != nullptr) ++options.stats->attempts;
    std::vector<V2> Pk = P0;
    try {
      std::vector<detail::Quad> qk = mesh_once(Pk, ids, nb, attempts[k], memo);
      const MeshScore score = score_mesh(Pk, qk);
      if (score.better_than(best, options.retry_below)) {
        best = score;
        P = std::move(Pk);
        quads = std::move(qk);
        if (options.stats != nullptr) options.stats->kept = static_cast<int>(k);
      }
    } catch (const MeshingError& err) {
      if (err.code() != ErrorCode::MeshingFailed) throw;
      // Without the checks a failure is shown at once, unless the
      // circumcentre attempt is still to come.
      if (!options.check_inversion && !(both_triangulations && k == 0)) throw;
      if (k + 1 == attempts.size() && quads.empty()) throw;
    }
    if (both_triangulations && k == 0) {
      const bool very_good = best.median >= kFrontalGoodMedian &&
                             best.worst >= std::max(kFrontalGoodWorst, options.retry_below);
      if (very_good) break;
      continue;
    }
    if (best.worst >= options.retry_below) break;
  }
  if (quads.empty()) failed("no attempt gave a mesh");

  QuadMesh2D out;
  out.boundary_count = nb;
  out.points.resize(P.size());
  for (size_t l = 0, i = 0; l < loops.size(); ++l) {
    for (const V2& p : loops[l]) out.points[i++] = p;
  }
  for (size_t i = static_cast<size_t>(nb); i < P.size(); ++i) out.points[i] = frame.from(P[i]);
  out.quads = std::move(quads);
  return out;
}

}  // namespace

QuadMesh2D pave_2d(const std::vector<std::vector<V2>>& loops, const PaveOptions& options) {
  try {
    return pave_2d_once(loops, options);
  } catch (const MeshingError& err) {
    if (err.code() != ErrorCode::MeshingFailed || !options.check_inversion) throw;
    // The frame (and so every snapped coordinate, the coarse picks and the
    // triangulation) hangs on the outer loop's first node, and a sliver
    // face can fold from one start and not from the next (a crescent of 12
    // nodes with tips of 28 and 40 degrees: 4 of the 12 starts fold). So
    // the next starts are tried, in order, before the failure stands; the
    // boundary keeps the caller's numbering.
    const size_t n0 = loops.front().size();
    for (size_t r = 1; r < std::min<size_t>(n0, kRetryStarts + 1); ++r) {
      std::vector<std::vector<V2>> turned = loops;
      std::rotate(turned.front().begin(), turned.front().begin() + static_cast<long>(r),
                  turned.front().end());
      QuadMesh2D m;
      try {
        m = pave_2d_once(turned, options);
      } catch (const MeshingError& again) {
        if (again.code() != ErrorCode::MeshingFailed) throw;
        continue;
      }
      // Turned outer index i is the caller's (i + r) mod n0.
      std::vector<V2> outer(m.points.begin(), m.points.begin() + static_cast<long>(n0));
      for (size_t i = 0; i < n0; ++i) m.points[(i + r) % n0] = outer[i];
      for (auto& q : m.quads) {
        for (int& v : q) {
          if (v < static_cast<int>(n0)) v = static_cast<int>((static_cast<size_t>(v) + r) % n0);
        }
      }
      return m;
    }
    throw;
  }
}

}  // namespace cooperage::pave
