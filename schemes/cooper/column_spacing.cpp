#include "schemes/cooper/column_spacing.h"

#include "schemes/cooper/level_spacing.h"
#include "schemes/cooper/wall_walk.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <set>

namespace cooperage::cooper {

namespace {

// A notched wall's rim follows knots far from even spacing only where the
// even columns would lean more than kMinShear of their height (11 degrees:
// a hole's wall notched into a foot leaned 0.24 and its fill folded; two
// L-shaped walls of pyocc_face_recognition lean 0.09 and 0.11 and fill
// soundly as they are; following their knots took the part's minimum
// scaled Jacobian from 0.38 to 0.12), and only if no interval falls below
// kMinSqueeze of even spacing (column_spacing).
constexpr double kMinShear = 0.2;
constexpr double kMinSqueeze = 0.3;
// A closed rim (round a hole) squeezed below kMinSqueeze still follows down
// to kMinSqueezeClosed: a hole's wall notched by a slot had its notch's arcs
// graded by the slot's thin feature and its bottom circle, left even, leaned
// its columns 65 degrees (campaign seed 3 case 121; squeezed to 0.26 it
// meshes). On the campaign's seeds 3-7 two parts that failed at every size
// mesh and seven mesh at their own size rather than half of it; at 0.05 a
// squeeze of 0.08 made a column of slivers (scaled Jacobian 0.0002).
constexpr double kMinSqueezeClosed = 0.2;
// A notched wall's corners may be this far from a multiple of 90 degrees
// (halfway to the next would make the walk's reading of them ambiguous).
constexpr double kSquareTolerance = 30.0;

// A curve's samples seen along the sweep (the axis component removed), and
// their arc-length fractions.
struct Profile {
  std::vector<geom::Vec3> x;
  std::vector<double> s;
  double sagitta = 0;  ///< how far the chords may lie inside the curve
};

Profile profile_of(const CurveFact& c, const geom::Vec3& d) {
  Profile p;
  for (const geom::Vec3& y : c.samples) p.x.push_back(y - y.dot(d) * d);
  p.s.assign(p.x.size(), 0.0);
  for (size_t k = 1; k < p.x.size(); ++k) p.s[k] = p.s[k - 1] + (p.x[k] - p.x[k - 1]).norm();
  // A chord lies inside its arc by about its length times its turn over 8.
  for (size_t k = 1; k + 1 < p.x.size(); ++k) {
    const geom::Vec3 a = p.x[k] - p.x[k - 1], b = p.x[k + 1] - p.x[k];
    const double la = a.norm(), lb = b.norm();
    if (la <= 0 || lb <= 0) continue;
    const double turn = std::acos(std::clamp(a.dot(b) / (la * lb), -1.0, 1.0));
    p.sagitta = std::max(p.sagitta, std::max(la, lb) * turn / 8);
  }
  if (p.s.back() > 0) {
    for (double& v : p.s) v /= p.s.back();
  }
  return p;
}

// The arc-length fraction of the point of the profile nearest to y, and its
// distance.
std::pair<double, double> nearest_on(const Profile& p, const geom::Vec3& y) {
  double best = std::numeric_limits<double>::infinity(), at = 0.0;
  for (size_t k = 1; k < p.x.size(); ++k) {
    const geom::Vec3 e = p.x[k] - p.x[k - 1];
    const double l2 = e.squaredNorm();
    const double w = l2 > 0 ? std::clamp((y - p.x[k - 1]).dot(e) / l2, 0.0, 1.0) : 0.0;
    const double dist = (p.x[k - 1] + w * e - y).norm();
    if (dist < best) {
      best = dist;
      at = p.s[k - 1] + w * (p.s[k] - p.s[k - 1]);
    }
  }
  return {at, best};
}

// The profile's point at arc-length fraction t.
geom::Vec3 point_at(const Profile& p, double t) {
  for (size_t k = 1; k < p.x.size(); ++k) {
    if (t > p.s[k] && k + 1 < p.x.size()) continue;
    const double w = p.s[k] > p.s[k - 1] ? (t - p.s[k - 1]) / (p.s[k] - p.s[k - 1]) : 0.0;
    return p.x[k - 1] + std::clamp(w, 0.0, 1.0) * (p.x[k] - p.x[k - 1]);
  }
  return p.x.front();
}

}  // namespace

// cite: Blacker 1996, sec. 4 (ribs progress straight down a barrel's side).
std::map<int, mesh::SizeFunction> column_spacing(const VolumeFacts& facts,
                                                 const SideLattice& lattice, const geom::Vec3& down,
                                                 const std::map<int, int>& counts,
                                                 const std::map<int, mesh::SizeFunction>* sizes) {
  std::map<int, mesh::SizeFunction> out;
  std::set<int> conflicting;
  const geom::Vec3 d = down.normalized();
  const double tol = 2e-4 * facts.size();
  auto flat = [&](const geom::Vec3& y) -> geom::Vec3 { return y - y.dot(d) * d; };
  for (int face : lattice.sides) {
    const FaceFact* f = facts.face(face);
    if (!f || f->loops.size() != 1) continue;
    // Lattice columns of the loop's vertices (wall_walk.h): curves running
    // along go +-i by their counts.
    const auto& loop = f->loops.front();
    const std::vector<WallStep> walk = wall_walk(*f, lattice);
    if (walk.empty()) continue;
    // A side closed round the sweep (a boss's cylinder, its seam a curve
    // across the rims) has periodic columns: a rim that is one closed curve
    // of n intervals meets its own vertex again n columns on.
    long period = 0;
    for (const UseFact& u : loop) {
      const CurveFact& c = facts.curves.at(u.curve);
      if (c.start != c.end || !lattice.along.count(u.curve) || !counts.count(u.curve)) continue;
      const long n = counts.at(u.curve);
      period = period == 0 || period == n ? n : -1;
    }
    if (period < 0) continue;
    // A side closed by a seam (a hole's wall whose rims are cut into arcs
    // by other features) passes the seam twice: its period is how far the
    // walk has gone round when it meets the seam's vertex again.
    std::map<int, int> uses;
    for (const UseFact& u : loop) ++uses[u.curve];
    const bool seamed = std::any_of(uses.begin(), uses.end(), [&](const auto& cu) {
      return cu.second == 2 && !lattice.along.count(cu.first);
    });
    const auto same_column = [&period](long a, long b) {
      return period > 0 ? (a - b) % period == 0 : a == b;
    };
    std::map<int, long> column;                      // vertex -> i
    std::map<int, std::pair<long, long>> start_col;  // along curve -> (i at its start, step)
    bool ok = true;
    long i = 0;
    for (const WallStep& step : walk) {
      const UseFact& u = loop[step.use];
      const CurveFact& c = facts.curves.at(u.curve);
      const int from = u.forward ? c.start : c.end;
      const bool is_along = step.along;
      const int dir = step.dir;
      ok = ok && counts.count(u.curve);
      if (!ok) break;
      const auto [it, added] = column.emplace(from, i);
      if (!added && period == 0 && seamed && it->second != i) period = std::abs(it->second - i);
      ok = ok && (added || same_column(it->second, i));
      if (is_along) {
        const long sign = dir == 0 ? 1 : -1, n = counts.at(u.curve);
        start_col[u.curve] =
            u.forward ? std::make_pair(i, sign) : std::make_pair(i + sign * n, -sign);
        i += sign * n;
      }
    }
    if (!ok || i != 0) continue;
    // Columns run along the sweep only where the curves between the rings
    // do (a wall parallel to the axis); on a slanted or twisted side a
    // vertex seen along the sweep is no column's foot.
    if (!upright_wall(facts, *f, lattice, d, tol)) continue;
    // A rectangle whose sides are split only at straight (180-degree)
    // vertices is one lattice rectangle: its columns are where the walk puts
    // them, however far from even spacing (a boss overhanging a wall by a
    // fraction of an element refines one rim; the other rim must follow).
    const bool rectangle =
        std::count_if(f->angles.begin(), f->angles.end(),
                      [](double a) { return std::abs(a - 90.0) <= 10.0; }) == 4 &&
        std::all_of(f->angles.begin(), f->angles.end(), [](double a) {
          return std::abs(a - 90.0) <= 10.0 || std::abs(a - 180.0) <= 10.0;
        });
    // A wall notched by a bay or a step (square corners, 270 degrees
    // included) has its columns where the walk puts them too: a pocket 0.35
    // from the wall refined its top rim, and the bottom rim, evenly spaced,
    // sheared the columns past the notch until the fill inverted. Its other
    // rim follows where the even columns would lean steeply (kMinShear),
    // unless that squeezes an interval below kMinSqueeze of even spacing:
    // such slivers on a cap's rim were swept through the barrels into
    // inverted hexes (two bays 0.3 apart); an L-shaped wall whose even
    // columns lean by 0.16 of their height (pyocc_face_recognition) fills
    // soundly as it is, and with the knots its barrel's hexes inverted.
    // "Square" allows kSquareTolerance: a lug's conical underside meets the
    // wall at 201 and 249 degrees, which the walk and the submap both read
    // as straight on and a turn, so its columns are where the walk puts them.
    const bool square = std::all_of(f->angles.begin(), f->angles.end(), [](double a) {
      return std::abs(a - 90.0) <= kSquareTolerance || std::abs(a - 180.0) <= kSquareTolerance ||
             std::abs(a - 270.0) <= kSquareTolerance;
    });
    // Open curves first: a closed rim follows the nodes they get.
    std::vector<size_t> order(loop.size());
    std::iota(order.begin(), order.end(), size_t{0});
    std::stable_partition(order.begin(), order.end(), [&](size_t k) {
      const CurveFact& c = facts.curves.at(loop[k].curve);
      return c.start != c.end;
    });
    for (size_t k : order) {
      const int id = loop[k].curve;
      if (!lattice.along.count(id)) continue;
      const CurveFact& c = facts.curves.at(id);
      const int n = counts.at(id);
      if (n < 2 || (c.start == c.end && period == 0)) continue;
      const Profile prof = profile_of(c, d);
      // Columns of the curve's own ends (every vertex of the loop has one).
      const auto [ia, step] = start_col.at(id);
      std::map<int, double> knots{{0, 0.0}, {n, 1.0}};
      bool consistent = true;
      bool far = false;    // a knot more than 1.5 intervals from even spacing
      double shear = 0.0;  // the steepest column such a knot straightens
      for (const auto& [v, iv] : column) {
        long k_v = (iv - ia) * step;
        if (period > 0) k_v = (k_v % period + period) % period;
        if (v == c.start || v == c.end || k_v <= 0 || k_v >= n) continue;
        const auto [at, dist] = nearest_on(prof, flat(facts.vertices.at(v)));
        if (dist > tol + 1.5 * prof.sagitta) continue;  // a slanted column: no knot
        // A knot far from even spacing (more than 1.5 intervals) means the
        // submap's columns are not where this walk puts them (a wall of
        // pyocc_face_recognition: 3 intervals off, and a hex inverted).
        if (!rectangle && std::abs(at * n - static_cast<double>(k_v)) > 1.5) {
          // How far the column through the vertex leans at even spacing,
          // per unit of its height above (or below) the curve.
          const double lean = std::abs(at - static_cast<double>(k_v) / n) * c.length;
          const double height = std::abs((facts.vertices.at(v) - c.samples.front()).dot(d));
          shear = std::max(shear, height > tol ? lean / height : kMinShear);
          far = true;
          consistent = consistent && square;
          if (!square) continue;
        }
        const auto [it, added] = knots.emplace(static_cast<int>(k_v), at);
        consistent = consistent && (added || std::abs(it->second - at) <= 1e-3);
      }
      // A closed rim follows every node of the other rim, not only its
      // vertices: that rim may be graded (a foot overhanging a wall: its
      // overhang arc refined towards a nearby edge), and ribs leaning between
      // the knots distort the chart the overhang's chord is imprinted in.
      if (c.start == c.end && sizes) {
        for (const UseFact& o : loop) {
          const CurveFact& oc = facts.curves.at(o.curve);
          if (o.curve == id || oc.start == oc.end || !lattice.along.count(o.curve)) continue;
          const int no = counts.at(o.curve);
          const auto [io, ostep] = start_col.at(o.curve);
          mesh::CurveSpacing spacing;
          const auto mine = out.find(o.curve);
          const auto given = sizes->find(o.curve);
          if (mine != out.end()) {
            spacing.kind = mesh::CurveSpacing::Kind::Sized;
            spacing.sizes = mine->second;
          } else if (given != sizes->end() && !given->second.empty()) {
            spacing.kind = mesh::CurveSpacing::Kind::Sized;
            spacing.sizes = given->second;
          }
          const std::vector<double> fo = mesh::spacing_fractions(no, oc.length, spacing);
          const Profile oprof = profile_of(oc, d);
          for (int j = 1; j < no; ++j) {
            long k_v = (io + ostep * j - ia) * step;
            k_v = (k_v % period + period) % period;
            if (k_v <= 0 || k_v >= n || knots.count(static_cast<int>(k_v))) continue;
            const auto [at, dist] = nearest_on(prof, point_at(oprof, fo[static_cast<size_t>(j)]));
            if (dist > tol + 1.5 * std::max(prof.sagitta, oprof.sagitta)) continue;
            knots.emplace(static_cast<int>(k_v), at);
          }
        }
      }
      if (!consistent || knots.size() == 2) continue;
      // Between the knots, even arc lengths.
      std::vector<double> t;
      for (auto it = knots.begin(); std::next(it) != knots.end(); ++it) {
        const auto next = std::next(it);
        for (int m = it->first; m < next->first; ++m)
          t.push_back(it->second + (next->second - it->second) * (m - it->first) /
                                       static_cast<double>(next->first - it->first));
      }
      t.push_back(1.0);
      bool increasing = true;
      for (size_t m = 1; m < t.size(); ++m) increasing = increasing && t[m] > t[m - 1] + 1e-6;
      if (!increasing) continue;
      double squeeze = 1.0;
      for (size_t m = 1; m < t.size(); ++m) squeeze = std::min(squeeze, (t[m] - t[m - 1]) * n);
      // A closed rim follows at any lean: round a hole every even column
      // leans the same way, and the ribs spiral (a wall leaning 0.07 round
      // a hole across a boss's edge inverted a hex beside the hole).
      const bool closed = c.start == c.end;
      if (far && !rectangle &&
          (squeeze < (closed ? kMinSqueezeClosed : kMinSqueeze) || (shear < kMinShear && !closed)))
        continue;
      // 3D arc length along a curve that runs along a level is its profile's.
      mesh::SizeFunction sf = steps_through(t, c.length);
      if (out.count(id)) conflicting.insert(id);
      out[id] = std::move(sf);
    }
  }
  for (int id : conflicting) out.erase(id);
  return out;
}

}  // namespace cooperage::cooper
