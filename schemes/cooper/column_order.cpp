#include "schemes/cooper/column_order.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <set>

namespace cooperage::cooper {
namespace {

// Where the walk round a wall's loop passes from its rims to the curves
// between them, or back: the vertex, its lattice column as curve
// coefficients (how many intervals of which rims lie before it), and how
// far along the rims it lies, seen along the sweep, in the same sense.
struct Corner {
  int vertex = 0;
  std::map<int, int> column;
  double along = 0;
};

// Length of a curve seen along the sweep (its axis component removed).
// Its samples' chords fall short of an arc by their sagittas, and two rims
// sampled alike do not fall short alike (a half circle against the whole
// circle it faces): scaled by the curve's length over its chords', a rim
// along a level measures its own length.
double flat_length(const CurveFact& c, const geom::Vec3& d) {
  double flat = 0, chords = 0;
  for (size_t k = 1; k < c.samples.size(); ++k) {
    const geom::Vec3 e = c.samples[k] - c.samples[k - 1];
    flat += (e - e.dot(d) * d).norm();
    chords += e.norm();
  }
  return chords > 0 ? flat * c.length / chords : flat;
}

// b's column minus a's.
std::map<int, int> difference(const std::map<int, int>& b, const std::map<int, int>& a) {
  std::map<int, int> out = b;
  for (const auto& [c, k] : a) {
    if ((out[c] -= k) == 0) out.erase(c);
  }
  return out;
}

std::string corner_text(int vertex) { return "vertex " + std::to_string(vertex); }

}  // namespace

// cite: Blacker 1996, sec. 4 (ribs progress straight down a barrel's side).
std::vector<IntervalRow> column_order_rows(const VolumeFacts& facts, const SideLattice& lattice,
                                           const geom::Vec3& down, const std::string& tag) {
  std::vector<IntervalRow> out;
  std::set<std::map<int, int>> seen;
  const geom::Vec3 d = down.normalized();
  const double tol = 2e-4 * facts.size();
  for (int face : lattice.sides) {
    const FaceFact* f = facts.face(face);
    if (!f || f->loops.size() != 1) continue;
    const auto& loop = f->loops.front();
    if (f->angles.size() != loop.size()) continue;
    size_t first = loop.size();
    for (size_t k = 0; k < loop.size() && first == loop.size(); ++k) {
      if (lattice.along.count(loop[k].curve)) first = k;
    }
    if (first == loop.size()) continue;
    // A corner seen along the sweep is its column's foot only on a wall
    // parallel to the sweep: the curves between its rims run along it.
    bool upright = true;
    for (const UseFact& u : loop) {
      if (lattice.along.count(u.curve)) continue;
      const CurveFact& c = facts.curves.at(u.curve);
      const geom::Vec3 foot = facts.vertices.at(c.start);
      for (const geom::Vec3& y : c.samples) {
        const geom::Vec3 e = y - foot;
        upright = upright && (e - e.dot(d) * d).norm() <= tol;
      }
    }
    if (!upright) continue;
    // The walk of column_spacing.cpp: the direction turns by a quarter at
    // every corner, rims go +-i by their counts (here as coefficients).
    std::vector<Corner> corners;
    std::map<int, int> column;
    double along = 0, perimeter = 0;
    int dir = 0;  // 0: +i, 1: +j, 2: -i, 3: -j
    bool ok = true, was_along = false;
    for (size_t m = 0; m < loop.size() && ok; ++m) {
      const size_t k = (first + m) % loop.size();
      if (m > 0) {
        const long turn = std::lround((180.0 - f->angles[k]) / 90.0);
        dir = static_cast<int>(((dir + turn) % 4 + 4) % 4);
      }
      const UseFact& u = loop[k];
      const CurveFact& c = facts.curves.at(u.curve);
      const bool is_along = lattice.along.count(u.curve) > 0;
      ok = is_along == (dir % 2 == 0);
      if (!ok) break;
      if (m == 0 || is_along != was_along)
        corners.push_back({u.forward ? c.start : c.end, column, along});
      if (is_along) {
        const int sign = dir == 0 ? 1 : -1;
        if ((column[u.curve] += sign) == 0) column.erase(u.curve);
        const double l = flat_length(c, d);
        along += sign * l;
        perimeter += l;
      }
      was_along = is_along;
    }
    // Back at the start: the rims seen along the sweep must close (a wall
    // whose rims differ in length is no wall parallel to the sweep).
    if (!ok || std::abs(along) > 0.02 * perimeter) continue;
    corners.push_back({corners.front().vertex, column, along});
    // Corners closer than the rims' closing error have no order to keep.
    const double apart = std::max({tol, 1e-3 * perimeter, 2 * std::abs(along)});
    std::vector<IntervalRow> rows;
    for (size_t a = 0; a < corners.size() && ok; ++a) {
      for (size_t b = a + 1; b < corners.size() && ok; ++b) {
        const double gap = corners[b].along - corners[a].along;
        if (std::abs(gap) <= apart) continue;
        const Corner& before = gap > 0 ? corners[a] : corners[b];
        const Corner& after = gap > 0 ? corners[b] : corners[a];
        std::map<int, int> terms = difference(after.column, before.column);
        bool negative = false, positive = false;
        for (const auto& [c, k] : terms) (k < 0 ? negative : positive) = true;
        if (!negative) continue;  // every count is at least 1
        // The walk contradicts the wall's geometry: no row from it.
        if (!positive) ok = false;
        if (!ok) continue;
        IntervalRow r;
        r.terms = std::move(terms);
        r.sense = intervals::Sense::GreaterEqual;
        r.rhs = 0;
        r.preferred = true;
        r.label = tag + ": side surface " + std::to_string(face) + ": the column of " +
                  corner_text(after.vertex) + " is not before that of " +
                  corner_text(before.vertex) + " (their order along the wall)";
        rows.push_back(std::move(r));
      }
    }
    if (!ok) continue;
    for (IntervalRow& r : rows) {
      if (seen.insert(r.terms).second) out.push_back(std::move(r));
    }
  }
  return out;
}

}  // namespace cooperage::cooper
