#include "schemes/cooper/column_order.h"

#include "schemes/cooper/wall_walk.h"

#include <algorithm>
#include <cmath>
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
    const std::vector<WallStep> walk = wall_walk(*f, lattice);
    if (walk.empty() || !upright_wall(facts, *f, lattice, d, tol)) continue;
    // Rims go +-i by their counts (here as coefficients), and as far along
    // the wall as they are long.
    std::vector<Corner> corners;
    std::map<int, int> column;
    double along = 0, perimeter = 0;
    bool was_along = false;
    for (size_t m = 0; m < walk.size(); ++m) {
      const UseFact& u = loop[walk[m].use];
      const CurveFact& c = facts.curves.at(u.curve);
      if (m == 0 || walk[m].along != was_along)
        corners.push_back({u.forward ? c.start : c.end, column, along});
      if (walk[m].along) {
        const int sign = walk[m].dir == 0 ? 1 : -1;
        if ((column[u.curve] += sign) == 0) column.erase(u.curve);
        const double l = flat_length(c, d);
        along += sign * l;
        perimeter += l;
      }
      was_along = walk[m].along;
    }
    // Back at the start: the rims seen along the sweep must close (a wall
    // whose rims differ in length is no wall parallel to the sweep).
    if (std::abs(along) > 0.02 * perimeter) continue;
    corners.push_back({corners.front().vertex, column, along});
    // Corners closer than the rims' closing error have no order to keep.
    const double apart = std::max({tol, 1e-3 * perimeter, 2 * std::abs(along)});
    std::vector<IntervalRow> rows;
    bool ok = true;
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
