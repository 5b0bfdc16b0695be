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

}  // namespace

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

}  // namespace cooperage::cooper
