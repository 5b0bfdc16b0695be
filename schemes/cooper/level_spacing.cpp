#include "schemes/cooper/level_spacing.h"

#include "schemes/cooper/barrel_constraints.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <limits>
#include <set>

namespace cooperage::cooper {
namespace {

int find_root(std::vector<int>& parent, int x) {
  while (parent[static_cast<size_t>(x)] != x) x = parent[static_cast<size_t>(x)];
  return x;
}

// Heights of a chain's potentials: its ends and the levels between them.
using Knots = std::map<long, double>;

double height_at(const Knots& k, long p) {
  const auto hi = k.lower_bound(p);
  if (hi == k.end()) return k.rbegin()->second;
  if (hi->first == p || hi == k.begin()) return hi->second;
  const auto lo = std::prev(hi);
  const double w = static_cast<double>(p - lo->first) / static_cast<double>(hi->first - lo->first);
  return lo->second + w * (hi->second - lo->second);
}

// Arc-length fractions of a curve's nodes whose heights are `target`
// (walked from its top vertex), or empty when its height does not fall
// monotonically or a target lies outside its drop.
std::vector<double> fractions_at_heights(const CurveFact& c, bool top_is_start,
                                         const std::vector<double>& target, const geom::Vec3& down,
                                         double tol) {
  std::vector<geom::Vec3> x = c.samples;
  if (!top_is_start) std::reverse(x.begin(), x.end());
  if (x.size() < 2) return {};
  std::vector<double> s(x.size(), 0.0), h(x.size());
  for (size_t k = 0; k < x.size(); ++k) {
    h[k] = -x[k].dot(down);
    if (k) s[k] = s[k - 1] + (x[k] - x[k - 1]).norm();
  }
  if (!(s.back() > 0)) return {};
  for (double& v : s) v /= s.back();
  for (size_t k = 1; k < h.size(); ++k) {
    if (h[k] > h[k - 1] + tol) return {};  // rises again
  }
  if (!(h.front() - h.back() > tol)) return {};
  std::vector<double> out;
  size_t k = 1;
  for (double t : target) {
    if (t > h.front() + tol || t < h.back() - tol) return {};
    while (k + 1 < h.size() && h[k] > t) ++k;
    const double d = h[k - 1] - h[k];
    const double w = d > 0 ? std::clamp((h[k - 1] - t) / d, 0.0, 1.0) : 1.0;
    out.push_back(s[k - 1] + w * (s[k] - s[k - 1]));
  }
  return out;
}

// Piecewise-constant sizes (steps kept piecewise linear by short ramps)
// under which n intervals equidistribute onto the given node fractions.
mesh::SizeFunction steps_through(const std::vector<double>& t, double length) {
  mesh::SizeFunction f;
  double gap = 1.0;
  for (size_t k = 1; k < t.size(); ++k) gap = std::min(gap, t[k] - t[k - 1]);
  const double ramp = 1e-4 * gap;
  for (size_t k = 0; k + 1 < t.size(); ++k) {
    const double size = (t[k + 1] - t[k]) * length;
    f.at.push_back(k == 0 ? 0.0 : t[k] + ramp);
    f.size.push_back(size);
    f.at.push_back(k + 2 == t.size() ? 1.0 : t[k + 1] - ramp);
    f.size.push_back(size);
  }
  return f;
}

}  // namespace

// cite: Blacker 1996, sec. 4 (a barrel ends where any rib reaches a cap: its
// rings of ribs lie on the caps' levels).
std::map<int, mesh::SizeFunction> level_spacing(const VolumeFacts& facts,
                                                const SideLattice& lattice, const SweepOrder& order,
                                                const geom::Vec3& down,
                                                const std::map<int, int>& counts) {
  std::map<int, mesh::SizeFunction> out;
  if (!order.straight || lattice.classes <= 0) return out;
  const geom::Vec3 d = down.normalized();
  const double tol = 1e-4 * facts.size();
  const size_t n = static_cast<size_t>(lattice.classes);
  // Potentials with the solver's counts (0 at the root of each component).
  std::vector<long> lambda(n, 0);
  {
    const auto expr = layer_potentials(lattice, order);
    for (size_t c = 0; c < n; ++c) {
      for (const auto& [curve, k] : expr[c]) {
        const auto it = counts.find(curve);
        if (it == counts.end()) return out;
        lambda[c] += static_cast<long>(k) * it->second;
      }
    }
  }
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  for (size_t i = 0; i < lattice.chains.size(); ++i) {
    const int a = find_root(parent, order.chain_upper[i]);
    const int b = find_root(parent, order.chain_lower[i]);
    if (a != b) parent[static_cast<size_t>(std::max(a, b))] = std::min(a, b);
  }
  // Per component, the height of every potential whose vertices all lie on
  // one level (a flat cap; an inclined one is no level); a potential held by
  // caps of different heights (two bosses of one layer each) is none either.
  auto height_of = [&](int v) { return -facts.vertices.at(v).dot(d); };
  std::map<int, std::map<long, std::pair<double, double>>> range;  // min, max height
  for (const auto& [v, cls] : lattice.vertex_class) {
    const double h = height_of(v);
    auto [it, added] = range[find_root(parent, cls)].emplace(lambda[static_cast<size_t>(cls)],
                                                             std::make_pair(h, h));
    if (!added) {
      it->second.first = std::min(it->second.first, h);
      it->second.second = std::max(it->second.second, h);
    }
  }
  std::map<int, std::map<long, double>> level;
  for (const auto& [comp, by] : range) {
    for (const auto& [p, h] : by) {
      if (h.second - h.first <= tol) level[comp][p] = 0.5 * (h.first + h.second);
    }
  }
  std::set<int> graded;
  for (const TangentDeparture& t : lattice.graded) graded.insert(t.along);
  for (size_t i = 0; i < lattice.chains.size(); ++i) {
    const LinkChain& c = lattice.chains[i];
    const int upper = order.chain_upper[i], lower = order.chain_lower[i];
    const auto lv = level.find(find_root(parent, upper));
    if (lv == level.end()) continue;
    const long pu = lambda[static_cast<size_t>(upper)], pl = lambda[static_cast<size_t>(lower)];
    // Walk the chain from its upper end.
    const bool forward = upper == c.from_class;
    std::vector<size_t> walk(c.curves.size());
    std::iota(walk.begin(), walk.end(), 0);
    if (!forward) std::reverse(walk.begin(), walk.end());
    int top = forward ? c.from_vertex : c.to_vertex;
    const int bottom = forward ? c.to_vertex : c.from_vertex;
    const double top_h = height_of(top), bottom_h = height_of(bottom);
    if (pu <= pl || !(top_h - bottom_h > tol)) continue;
    // Heights by potential: the chain's ends, the levels in between.
    Knots knots{{pl, bottom_h}, {pu, top_h}};
    for (const auto& [p, h] : lv->second) {
      if (p > pl && p < pu && h > bottom_h + tol && h < top_h - tol) knots[p] = h;
    }
    bool rising = true;
    for (auto it = knots.begin(); std::next(it) != knots.end(); ++it)
      rising = rising && std::next(it)->second > it->second;
    if (!rising) continue;
    long p = pu;
    for (size_t k : walk) {
      const int id = c.curves[k];
      const CurveFact& cf = facts.curves.at(id);
      const int count = counts.at(id);
      const bool top_is_start = cf.start == top;
      if (cf.start == cf.end || (!top_is_start && cf.end != top)) break;
      top = top_is_start ? cf.end : cf.start;
      const long first = p;
      p -= count;
      if (count < 2 || graded.count(id)) continue;
      std::vector<double> target;
      for (int j = 1; j < count; ++j) target.push_back(height_at(knots, first - j));
      std::vector<double> t = fractions_at_heights(cf, top_is_start, target, d, tol);
      t.insert(t.begin(), 0.0);
      t.push_back(1.0);
      if (!top_is_start) {
        std::reverse(t.begin(), t.end());
        for (double& v : t) v = 1.0 - v;
      }
      bool increasing = true;
      for (size_t m = 1; m < t.size(); ++m) increasing = increasing && t[m] > t[m - 1] + 1e-6;
      if (increasing) out[id] = steps_through(t, cf.length);
    }
  }
  return out;
}

namespace {

// A notched wall's rim follows knots far from even spacing only where the
// even columns would lean more than kMinShear of their height (22 degrees:
// the fill folds; below it the even fill is sound and the knots only
// squeeze the rim), and only if no interval falls below kMinSqueeze of
// even spacing (column_spacing).
constexpr double kMinShear = 0.4;
constexpr double kMinSqueeze = 0.3;

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
    // Lattice columns of the loop's vertices: walking the loop, the direction
    // turns by a quarter at every corner (90 degrees: one way, 270: the
    // other, 180: straight on); curves running along go +-i by their counts.
    const auto& loop = f->loops.front();
    if (f->angles.size() != loop.size()) continue;
    size_t first = loop.size();
    for (size_t k = 0; k < loop.size() && first == loop.size(); ++k) {
      if (lattice.along.count(loop[k].curve)) first = k;
    }
    if (first == loop.size()) continue;
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
    const auto same_column = [period](long a, long b) {
      return period > 0 ? (a - b) % period == 0 : a == b;
    };
    std::map<int, long> column;                      // vertex -> i
    std::map<int, std::pair<long, long>> start_col;  // along curve -> (i at its start, step)
    bool ok = true;
    long i = 0;
    int dir = 0;  // 0: +i, 1: +j, 2: -i, 3: -j
    for (size_t m = 0; m < loop.size() && ok; ++m) {
      const size_t k = (first + m) % loop.size();
      if (m > 0) {
        const long turn = std::lround((180.0 - f->angles[k]) / 90.0);
        dir = static_cast<int>(((dir + turn) % 4 + 4) % 4);
      }
      const UseFact& u = loop[k];
      const CurveFact& c = facts.curves.at(u.curve);
      const int from = u.forward ? c.start : c.end;
      const bool is_along = lattice.along.count(u.curve) > 0;
      ok = ok && counts.count(u.curve) && is_along == (dir % 2 == 0);
      if (!ok) break;
      const auto [it, added] = column.emplace(from, i);
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
    bool upright = true;
    for (const UseFact& u : loop) {
      if (lattice.along.count(u.curve)) continue;
      const CurveFact& c = facts.curves.at(u.curve);
      const geom::Vec3 foot = flat(facts.vertices.at(c.start));
      for (const geom::Vec3& y : c.samples) upright = upright && (flat(y) - foot).norm() <= tol;
    }
    if (!upright) continue;
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
    const bool square = std::all_of(f->angles.begin(), f->angles.end(), [](double a) {
      return std::abs(a - 90.0) <= 10.0 || std::abs(a - 180.0) <= 10.0 ||
             std::abs(a - 270.0) <= 10.0;
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
      if (far && !rectangle && (squeeze < kMinSqueeze || shear < kMinShear)) continue;
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
