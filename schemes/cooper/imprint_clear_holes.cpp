// A projected path or loop that passes a loop of the subcap it is imprinted
// into by less than a chord's sagitta (a boss's rim 0.07 of an element
// outside a foot's, whose chords cut each other; sec. 5.2). The subcap's
// nodes are nodes of its cap and stay; the new nodes, placed by this
// projection only, move off to a tenth of their edges (when nearer than
// 2 % of one, or across), so that the other loop lies wholly on one side
// and the pieces do not cross. Seaming onto the loop instead (sec. 5.4)
// put a path through a foot at two nodes and cut the piece there.
#include "schemes/cooper/imprinter.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cooperage::cooper::detail {
namespace {

// Nodes nearer an edge than this fraction of it, or across it, are moved
// to a tenth of it. A loop 3.5 % of an edge from another is left alone:
// moved, it leaned a rib into an inverted hex (campaign seed 5 case 33).
constexpr double kTouching = 0.02;

}  // namespace

bool Imprinter::crosses_any(const Loop& chain, bool closed, const std::vector<Loop>& loops) const {
  const size_t edges = closed ? chain.size() : chain.size() - 1;
  for (size_t i = 0; i < edges; ++i) {
    const int p0 = chain[i], p1 = chain[(i + 1) % chain.size()];
    for (const Loop& l : loops) {
      for (size_t k = 0; k < l.size(); ++k) {
        const int q0 = l[k], q1 = l[(k + 1) % l.size()];
        if (p0 == q0 || p0 == q1 || p1 == q0 || p1 == q1) continue;
        if (segment_hit(xy().at(p0), xy().at(p1), xy().at(q0), xy().at(q1))) return true;
      }
    }
  }
  return false;
}

bool Imprinter::keep_clear(const Loop& chain, bool closed, const std::vector<Loop>& obstacles,
                           int first_new) {
  if (chain.size() < 2) return true;
  auto movable = [&](int w) { return w >= first_new; };
  std::map<int, Vec2> start;
  for (int w : chain) {
    if (movable(w)) start[w] = xy().at(w);
  }
  const size_t n = chain.size();
  const size_t edges = closed ? n : n - 1;
  for (int round = 0; round < 4; ++round) {
    bool moved = false;
    // An obstacle node nearer a chain edge than kTouching of it, or across
    // it, pushes the edge's movable ends away along its normal, to a tenth
    // of the edge.
    for (size_t i = 0; i < edges; ++i) {
      const int p0 = chain[i], p1 = chain[(i + 1) % n];
      if (!movable(p0) && !movable(p1)) continue;
      const Vec2 a = xy().at(p0), c = xy().at(p1);
      const double len = (c - a).norm();
      if (len <= 0) continue;
      const double margin = 0.1 * len;
      const Vec2 left(-(c - a).y() / len, (c - a).x() / len);
      for (const Loop& l : obstacles) {
        // The side the edge moves to: the left of a closed counter-
        // clockwise image (its inside, where no other loop belongs); for a
        // path, away from where most of the loop lies.
        Vec2 away = left;
        if (!closed) {
          double side = 0;
          for (int q : l) side += (xy().at(q) - a).dot(left);
          if (side > 0) away = -left;
        }
        double push = 0;
        for (int q : l) {
          if (q == p0 || q == p1) continue;
          const Vec2& hq = xy().at(q);
          const auto foot = foot_inside_segment(hq, a, c);
          if (!foot) continue;                           // beyond the edge
          const double beyond = (hq - *foot).dot(away);  // towards where the edge moves
          if (beyond > -kTouching * len) push = std::max(push, beyond + margin);
        }
        if (push <= 0 || push > 0.3 * len) continue;  // nothing near, or no sliver
        if (movable(p0)) r_.ends.xy[p0] += push * away;
        if (movable(p1)) r_.ends.xy[p1] += push * away;
        moved = true;
      }
    }
    // A movable chain node within a tenth of its edges of an obstacle edge,
    // or across it: onto the obstacle's material side (the left of a
    // subcap's loops, outer counter-clockwise and holes clockwise).
    for (size_t i = 0; i < n; ++i) {
      const int w = chain[i];
      if (!movable(w)) continue;
      double edge = std::numeric_limits<double>::infinity();
      if (closed || i + 1 < n)
        edge = std::min(edge, (xy().at(chain[(i + 1) % n]) - xy().at(w)).norm());
      if (closed || i > 0)
        edge = std::min(edge, (xy().at(chain[(i + n - 1) % n]) - xy().at(w)).norm());
      if (!std::isfinite(edge) || edge <= 0) continue;
      const double margin = 0.1 * edge;
      for (const Loop& l : obstacles) {
        for (size_t k = 0; k < l.size(); ++k) {
          const int q0 = l[k], q1 = l[(k + 1) % l.size()];
          if (q0 == w || q1 == w) continue;
          const Vec2 a = xy().at(q0), c = xy().at(q1);
          const double len = (c - a).norm();
          if (len <= 0) continue;
          const Vec2& p = xy().at(w);
          const auto foot = foot_inside_segment(p, a, c);
          if (!foot) continue;
          const Vec2 left(-(c - a).y() / len, (c - a).x() / len);
          const double inside = (p - *foot).dot(left);
          if (inside >= kTouching * edge || inside < -0.3 * edge) continue;
          r_.ends.xy[w] += (margin - inside) * left;
          moved = true;
        }
      }
    }
    if (!moved) break;
  }
  if (!crosses_any(chain, closed, obstacles)) return true;
  for (const auto& [w, p] : start) r_.ends.xy[w] = p;
  return false;
}

}  // namespace cooperage::cooper::detail
