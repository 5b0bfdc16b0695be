#include "schemes/pave/coarse_loops.h"

#include "schemes/pave/corner_picks.h"
#include "schemes/pave/split_to_quads.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace cooperage::pave::detail {

namespace {
/// Reflex corners of holes above this [rad] stay with the corner template
/// (PaveOptions::tip_angle's default, 250 deg).
constexpr double kHoleReflexLimit = 250.0 * M_PI / 180.0;
/// Coarse loops with at least this many vertices count an odd edge at the
/// full coarse size in their point sizes.
constexpr size_t kOddFullSizeFrom = 8;
}  // namespace

double skipped_quality(const std::vector<Eigen::Vector2d>& P, const std::vector<int>& L,
                       size_t offset) {
  double worst = 1.0;
  for (size_t k = 1 - offset; k < L.size(); k += 2)
    worst = std::min(worst, std::sin(0.5 * interior_angle(P, L, k)));
  return worst;
}

size_t choose_parity(const std::vector<Eigen::Vector2d>& P, const std::vector<int>& L) {
  const double q0 = skipped_quality(P, L, 0), q1 = skipped_quality(P, L, 1);
  if (std::abs(q0 - q1) > 1e-9) return q1 > q0 ? 1 : 0;
  // Tie: emphasise strong corners as coarse vertices.
  double score[2] = {0.0, 0.0};
  for (size_t k = 0; k < L.size(); ++k) {
    const double turn = M_PI - interior_angle(P, L, k);
    score[k % 2] += turn * turn;
  }
  return score[1] > score[0] * (1.0 + 1e-9) ? 1 : 0;
}

namespace {

// Paving's corner template at tip p between a and b: the new loop path a',
// q1, q2, q3, b' (three quads around p, each taking a third of its angle
// theta).
std::array<Eigen::Vector2d, 5> corner_template(const Eigen::Vector2d& a, const Eigen::Vector2d& p,
                                               const Eigen::Vector2d& b, double theta) {
  const double h = 0.5 * ((a - p).norm() + (b - p).norm());
  const Eigen::Vector2d u = (b - p).normalized();
  auto dir = [&](double ang) {
    return Eigen::Vector2d(u.x() * std::cos(ang) - u.y() * std::sin(ang),
                           u.x() * std::sin(ang) + u.y() * std::cos(ang));
  };
  const Eigen::Vector2d q3 = p + h * dir(theta / 3), q1 = p + h * dir(2 * theta / 3);
  const Eigen::Vector2d q2 = p + 1.3 * h * dir(theta / 2);
  return {a + (q1 - p), q1, q2, q3, b + (q3 - p)};
}

bool segments_cross(const Eigen::Vector2d& p0, const Eigen::Vector2d& p1, const Eigen::Vector2d& q0,
                    const Eigen::Vector2d& q1) {
  const double d1 = cross2(q1 - q0, p0 - q0), d2 = cross2(q1 - q0, p1 - q0);
  const double d3 = cross2(p1 - p0, q0 - p0), d4 = cross2(p1 - p0, q1 - p0);
  return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0));
}

// Whether the template's region a, a', q1, q2, q3, b', b, p stays clear of
// the loops (edges not at a, p or b): a hole next to a notch's reflex corner
// lies closer than the template reaches, and its loop would cross the
// template's, which no triangulation can recover.
bool template_clear(const std::vector<Eigen::Vector2d>& P,
                    const std::vector<std::vector<int>>& loops, int ia, int ip, int ib,
                    const std::array<Eigen::Vector2d, 5>& t) {
  const Eigen::Vector2d a = P[static_cast<size_t>(ia)], p = P[static_cast<size_t>(ip)],
                        b = P[static_cast<size_t>(ib)];
  const std::array<Eigen::Vector2d, 8> region{a, t[0], t[1], t[2], t[3], t[4], b, p};
  for (const auto& loop : loops) {
    const size_t m = loop.size();
    for (size_t k = 0; k < m; ++k) {
      const int i0 = loop[k], i1 = loop[(k + 1) % m];
      const bool at_tip = i0 == ia || i0 == ip || i0 == ib || i1 == ia || i1 == ip || i1 == ib;
      const Eigen::Vector2d q0 = P[static_cast<size_t>(i0)], q1 = P[static_cast<size_t>(i1)];
      for (size_t j = 0; j + 1 < 7; ++j) {
        if (!at_tip && segments_cross(region[j], region[j + 1], q0, q1)) return false;
      }
      if (i0 == ia || i0 == ip || i0 == ib) continue;
      bool in = false;  // crossing number of q0 against the region
      for (size_t j = 0, i = region.size() - 1; j < region.size(); i = j++) {
        const Eigen::Vector2d &r = region[j], &s = region[i];
        if ((r.y() > q0.y()) != (s.y() > q0.y()) &&
            q0.x() < (s.x() - r.x()) * (q0.y() - r.y()) / (s.y() - r.y()) + r.x())
          in = !in;
      }
      if (in) return false;
    }
  }
  return true;
}

}  // namespace

std::vector<int> wrap_reflex_tips(const std::vector<int>& L, double limit, int first_new,
                                  std::vector<Eigen::Vector2d>& P, std::vector<Quad>& quads,
                                  double corner_angle,
                                  const std::vector<std::vector<int>>& other_loops) {
  const size_t n = L.size();
  if (n % 2 != 0) return L;  // odd loops are left as they are
  // The nodes coarse_boundary() will skip (it picks the same way).
  std::vector<char> skipped(n, 1);
  try {
    for (size_t k : loop_picks(P, L, 0, corner_angle)) skipped[k] = 0;
  } catch (const std::runtime_error&) {
    return L;  // coarse_boundary() reports it
  }
  std::vector<std::vector<int>> loops = other_loops;
  loops.push_back(L);
  std::vector<char> wrap(n, 0);
  std::vector<std::array<Eigen::Vector2d, 5>> shape(n);
  bool any = false;
  for (size_t k = 0; k < n; ++k) {
    // Neighbouring tips share a node: wrap one per pass.
    if (skipped[k] && L[k] < first_new && interior_angle(P, L, k) > limit &&
        !(k >= 2 && wrap[k - 2]) && !(k + 2 >= n && wrap[(k + 2) % n])) {
      const int ia = L[(k + n - 1) % n], ip = L[k], ib = L[(k + 1) % n];
      shape[k] = corner_template(P[static_cast<size_t>(ia)], P[static_cast<size_t>(ip)],
                                 P[static_cast<size_t>(ib)], interior_angle(P, L, k));
      if (!template_clear(P, loops, ia, ip, ib, shape[k])) continue;
      wrap[k] = any = true;
    }
  }
  if (!any) return L;
  std::vector<int> out;
  for (size_t k = 0; k < n; ++k) {
    if (!wrap[k]) {
      out.push_back(L[k]);
      continue;
    }
    // The loop a, p, b becomes a, a', q1, q2, q3, b', b.
    const int ia = L[(k + n - 1) % n], ip = L[k], ib = L[(k + 1) % n];
    const auto add = [&](const Eigen::Vector2d& x) {
      P.push_back(x);
      return static_cast<int>(P.size()) - 1;
    };
    const auto& t = shape[k];
    const int n3 = add(t[3]), n2 = add(t[2]), n1 = add(t[1]);
    const int na = add(t[0]), nb = add(t[4]);
    quads.push_back({ip, ib, nb, n3});
    quads.push_back({ip, n3, n2, n1});
    quads.push_back({ia, ip, n1, na});
    // out already ends with a (or will start with it); insert the new path.
    for (int v : {na, n1, n2, n3, nb}) out.push_back(v);
  }
  return out;
}

bool coarse_loop_valid(const std::vector<Eigen::Vector2d>& P, const std::vector<int>& L,
                       size_t offset) {
  double fine = 0.0, coarse = 0.0;
  const size_t n = L.size();
  for (size_t k = 0; k < n; ++k) {
    fine += cross2(P[static_cast<size_t>(L[k])], P[static_cast<size_t>(L[(k + 1) % n])]);
  }
  for (size_t k = offset; k < n; k += 2) {
    coarse += cross2(P[static_cast<size_t>(L[k])], P[static_cast<size_t>(L[(k + 2) % n])]);
  }
  // Same orientation, and not folded flat.
  return fine * coarse > 0 && std::abs(coarse) > 0.05 * std::abs(fine);
}

namespace {

/// Signed area of the polygon of the picked loop nodes, times 2.
double picked_area(const std::vector<Eigen::Vector2d>& P, const std::vector<int>& L,
                   const std::vector<size_t>& picks) {
  double a = 0.0;
  for (size_t j = 0; j < picks.size(); ++j) {
    a += cross2(P[static_cast<size_t>(L[picks[j]])],
                P[static_cast<size_t>(L[picks[(j + 1) % picks.size()]])]);
  }
  return a;
}

/// Coarse vertices of an odd loop: s, s + 2, ..., s + n - 1; the last coarse
/// edge spans one fine edge (an odd edge). s is the rank-th best start by
/// the worst skipped node (rank > 0: retries move the odd edge).
std::vector<size_t> odd_loop_picks(const std::vector<Eigen::Vector2d>& P, const std::vector<int>& L,
                                   int rank) {
  const size_t n = L.size();
  std::vector<double> q(n);
  for (size_t k = 0; k < n; ++k) q[k] = std::sin(0.5 * interior_angle(P, L, k));
  double fine = 0.0;
  for (size_t k = 0; k < n; ++k)
    fine += cross2(P[static_cast<size_t>(L[k])], P[static_cast<size_t>(L[(k + 1) % n])]);
  const size_t stride = std::max<size_t>(1, n / 400);
  std::vector<std::pair<double, size_t>> ranked;
  for (size_t s = 0; s < n; s += stride) {
    double worst = 1.0;
    for (size_t k = s + 1; k + 1 < s + n; k += 2) worst = std::min(worst, q[k % n]);
    std::vector<size_t> picks;
    for (size_t k = s; k < s + n; k += 2) picks.push_back(k % n);
    const double coarse = picked_area(P, L, picks);
    if (fine * coarse > 0 && std::abs(coarse) > 0.05 * std::abs(fine))
      ranked.emplace_back(-worst, s);
  }
  if (ranked.empty()) {
    throw std::runtime_error(
        "an odd loop of " + std::to_string(n) +
        " nodes is too coarse for its shape (its every-other-node polygon folds)");
  }
  std::stable_sort(ranked.begin(), ranked.end());
  const size_t best =
      ranked[std::min(static_cast<size_t>(std::max(rank, 0)) * 3, ranked.size() - 1)].second;
  std::vector<size_t> picks;
  for (size_t k = best; k < best + n; k += 2) picks.push_back(k % n);
  return picks;
}

}  // namespace

namespace {

/// Whether two coarse edges of the picked polygon that share no vertex
/// cross. Skipping a node can cut across a sliver of the face (a cone's
/// flank running into a wall at 8 degrees: the chord over the skipped node
/// passes beyond the loop's other side), and no triangulation recovers a
/// boundary that crosses itself. Edges are swept in order of their least x.
bool picks_cross(const std::vector<Eigen::Vector2d>& P, const std::vector<int>& L,
                 const std::vector<size_t>& picks) {
  const size_t m = picks.size();
  if (m < 4) return false;
  const auto at = [&](size_t j) { return P[static_cast<size_t>(L[picks[j % m]])]; };
  std::vector<std::pair<double, size_t>> order(m);  // (least x, edge j -> j + 1)
  for (size_t j = 0; j < m; ++j) order[j] = {std::min(at(j).x(), at(j + 1).x()), j};
  std::sort(order.begin(), order.end());
  for (size_t a = 0; a < m; ++a) {
    const size_t i = order[a].second;
    const double right = std::max(at(i).x(), at(i + 1).x());
    for (size_t b = a + 1; b < m && order[b].first <= right; ++b) {
      const size_t k = order[b].second;
      if (k == i || (k + 1) % m == i || (i + 1) % m == k) continue;  // share a vertex
      if (segments_cross(at(i), at(i + 1), at(k), at(k + 1))) return true;
    }
  }
  return false;
}

/// The picks of an even loop at `offset`.
std::vector<size_t> every_other(size_t n, size_t offset) {
  std::vector<size_t> picks;
  for (size_t k = offset; k < n; k += 2) picks.push_back(k);
  return picks;
}

}  // namespace

std::vector<size_t> loop_picks(const std::vector<Eigen::Vector2d>& P, const std::vector<int>& L,
                               int odd_rank, double corner_angle) {
  std::vector<size_t> picks = preferred_picks(P, L, odd_rank, corner_angle);
  if (!picks_cross(P, L, picks)) return picks;
  // A crossing coarse loop fails the triangulation for sure: the picks that
  // do not cross, of a single parity, rather than the best skipped node.
  const size_t n = L.size();
  if (n % 2 == 0) {
    for (size_t offset : {size_t{0}, size_t{1}}) {
      std::vector<size_t> plain = every_other(n, offset);
      if (coarse_loop_valid(P, L, offset) && !picks_cross(P, L, plain)) return plain;
    }
  } else {
    for (int rank = 0; rank < 8; ++rank) {
      std::vector<size_t> odd = odd_loop_picks(P, L, rank);
      if (!picks_cross(P, L, odd)) return odd;
    }
  }
  return picks;  // the triangulation reports it
}

std::vector<size_t> preferred_picks(const std::vector<Eigen::Vector2d>& P,
                                    const std::vector<int>& L, int odd_rank, double corner_angle) {
  const size_t n = L.size();
  std::vector<size_t> picks;
  if (n % 2 == 0) {
    size_t offset = choose_parity(P, L);
    if (!coarse_loop_valid(P, L, offset)) {
      offset = 1 - offset;
      if (!coarse_loop_valid(P, L, offset)) {
        throw std::runtime_error(
            "a loop of " + std::to_string(n) +
            " nodes is too coarse for its shape (its every-other-node polygon folds)");
      }
    }
    picks = every_other(n, offset);
  } else {
    picks = odd_loop_picks(P, L, odd_rank);
  }
  if (corner_angle <= 0) return picks;
  double fine = 0.0;
  for (size_t k = 0; k < n; ++k)
    fine += cross2(P[static_cast<size_t>(L[k])], P[static_cast<size_t>(L[(k + 1) % n])]);
  // Holes (clockwise) leave reflex tips sharper than paving's corner template
  // angle to the template (measured: a stepped hole's 270 deg corners as
  // coarse vertices spoilt a cooper sweep through that face, 0.70 -> 0.22).
  const double reflex_limit = fine < 0 ? kHoleReflexLimit : 2 * M_PI;
  const std::vector<size_t> switched = corner_picks(P, L, corner_angle, reflex_limit);
  // Switching costs odd edges, each a path of irregular nodes whose quads
  // measure ~0.71-0.75 themselves: only worth it for a clearly bad skipped
  // node (a gain of 0.2: below ~100 or above ~260 deg). Measured on 3000
  // random faces: a gain of 0.02 lowered their mean median 0.965 -> 0.955,
  // 0.2 keeps 0.963.
  if (switched.size() < 3 ||
      skipped_quality_of_picks(P, L, switched) < skipped_quality_of_picks(P, L, picks) + 0.2) {
    return picks;
  }
  const double coarse = picked_area(P, L, switched);
  return fine * coarse > 0 && std::abs(coarse) > 0.05 * std::abs(fine) ? switched : picks;
}

CoarseBoundary coarse_boundary(const std::vector<Eigen::Vector2d>& P,
                               const std::vector<std::vector<int>>& loops, bool seed_rows,
                               int odd_rank, double corner_angle, bool odd_full_size) {
  CoarseBoundary out;
  for (const auto& L : loops) {
    const size_t n = L.size();
    auto at = [&](size_t k) { return P[static_cast<size_t>(L[k % n])]; };
    const std::vector<size_t> picks = loop_picks(P, L, odd_rank, corner_angle);
    const int first = static_cast<int>(out.points.size());
    std::vector<int> coarse;
    for (size_t k : picks) {
      const Eigen::Vector2d a = at(k + n - 1), b = at(k), c = at(k + 1);
      const double interior = M_PI - std::atan2(cross2(b - a, c - b), (b - a).dot(c - b));
      // FASTQ's node classes by angle (ALGORITHMS.md sec. 4): END < 135 deg
      // (1 cell), SIDE < 225 (2), CORNER < 315 (3), REVERSAL (4).
      const double deg = interior * 180.0 / M_PI;
      out.min_cells.push_back(deg < 135.0 ? 1 : deg < 225.0 ? 2 : deg < 315.0 ? 3 : 4);
      coarse.push_back(static_cast<int>(out.points.size()));
      out.points.push_back(P[static_cast<size_t>(L[k])]);
      out.fine_of_coarse.push_back(L[k]);
    }
    const size_t m = coarse.size();
    std::vector<char> odd_after(m, 0);  // coarse edge j -> j + 1 spans one fine edge
    for (size_t j = 0; j < m; ++j) {
      const int a = coarse[j], b = coarse[(j + 1) % m];
      if ((picks[(j + 1) % m] + n - picks[j]) % n == 2) {
        out.midpoint[undirected_key(a, b)] = L[(picks[j] + 1) % n];
      } else {
        out.odd_edges.push_back(undirected_key(a, b));
        odd_after[j] = 1;
      }
    }
    for (size_t j = 0; j < m; ++j) {
      const Eigen::Vector2d& x = out.points[static_cast<size_t>(first) + j];
      const Eigen::Vector2d& xp = out.points[static_cast<size_t>(first) + (j + m - 1) % m];
      const Eigen::Vector2d& xn = out.points[static_cast<size_t>(first) + (j + 1) % m];
      const double lp = (x - xp).norm(), ln = (x - xn).norm();
      // An odd edge is half a coarse edge: it counts twice in the size (else
      // the frontal size field of a long odd-sided loop is too fine inside).
      const double odd_weight = odd_full_size && m >= kOddFullSizeFrom ? 2.0 : 1.0;
      const double size = 0.5 * (lp * (odd_after[(j + m - 1) % m] ? odd_weight : 1.0) +
                                 ln * (odd_after[j] ? odd_weight : 1.0));
      out.sizes.push_back(size);
      const double interior = M_PI - std::atan2(cross2(x - xp, xn - x), (x - xp).dot(xn - x));
      if (seed_rows && m >= 3 && interior > 150.0 * M_PI / 180.0 &&
          interior < 210.0 * M_PI / 180.0) {
        const Eigen::Vector2d tin = (x - xp) / lp, tout = (xn - x) / ln;
        const Eigen::Vector2d nrm =
            Eigen::Vector2d(-tin.y() - tout.y(), tin.x() + tout.x()).normalized();
        out.seeds.push_back(x + 0.72 * size * nrm);
        out.seed_from.push_back(coarse[j]);
        out.seed_sizes.push_back(size);
      }
    }
    out.loops.push_back(std::move(coarse));
  }
  return out;
}

std::vector<int> ring_around_small_hole(const std::vector<int>& loop, double width,
                                        std::vector<Eigen::Vector2d>& P, std::vector<Quad>& quads) {
  // Counter-clockwise corners q0..q3 of the hole: (s, t) = (0,0), (1,0), (1,1), (0,1).
  const Eigen::Vector2d q[4] = {P[static_cast<size_t>(loop[0])], P[static_cast<size_t>(loop[3])],
                                P[static_cast<size_t>(loop[2])], P[static_cast<size_t>(loop[1])]};
  const double s_of[4] = {-width, 0.0, 1.0, 1.0 + width};
  int g[4][4];
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) {
      const double s = s_of[i], t = s_of[j];
      const Eigen::Vector2d x =
          (1 - s) * (1 - t) * q[0] + s * (1 - t) * q[1] + s * t * q[2] + (1 - s) * t * q[3];
      if ((i == 1 || i == 2) && (j == 1 || j == 2)) continue;
      g[i][j] = static_cast<int>(P.size());
      P.push_back(x);
    }
  }
  g[1][1] = loop[0];
  g[2][1] = loop[3];
  g[2][2] = loop[2];
  g[1][2] = loop[1];
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      if (i == 1 && j == 1) continue;
      quads.push_back({g[i][j], g[i + 1][j], g[i + 1][j + 1], g[i][j + 1]});
    }
  }
  const std::vector<int> ccw = {g[0][0], g[1][0], g[2][0], g[3][0], g[3][1], g[3][2],
                                g[3][3], g[2][3], g[1][3], g[0][3], g[0][2], g[0][1]};
  return std::vector<int>(ccw.rbegin(), ccw.rend());
}

}  // namespace cooperage::pave::detail
