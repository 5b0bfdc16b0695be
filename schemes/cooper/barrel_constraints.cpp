#include "schemes/cooper/barrel_constraints.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <set>

namespace cooperage::cooper {
namespace {

using Expr = std::map<int, int>;

Expr combine(const Expr& a, int sa, const Expr& b, int sb) {
  Expr out = a;
  for (auto& [k, v] : out) v *= sa;
  for (const auto& [k, v] : b) out[k] += sb * v;
  for (auto it = out.begin(); it != out.end();)
    it = it->second == 0 ? out.erase(it) : std::next(it);
  return out;
}

Expr chain_sum(const LinkChain& c) {
  Expr e;
  for (int curve : c.curves) e[curve] += 1;
  return e;
}

std::string ids(const std::vector<int>& v) {
  std::string s;
  for (size_t i = 0; i < v.size(); ++i) s += (i ? "+" : "") + std::to_string(v[i]);
  return s;
}

}  // namespace

std::vector<std::map<int, int>> layer_potentials(const SideLattice& lattice,
                                                 const SweepOrder& order,
                                                 std::vector<size_t>* extra) {
  const size_t n = static_cast<size_t>(lattice.classes);
  std::vector<std::vector<size_t>> at(n);
  for (size_t i = 0; i < lattice.chains.size(); ++i) {
    at[static_cast<size_t>(order.chain_upper[i])].push_back(i);
    at[static_cast<size_t>(order.chain_lower[i])].push_back(i);
  }
  std::vector<Expr> lambda(n);
  std::vector<char> known(n, 0);
  std::vector<char> used(lattice.chains.size(), 0);
  for (size_t root = 0; root < n; ++root) {
    if (known[root]) continue;
    known[root] = 1;
    std::deque<size_t> queue{root};
    while (!queue.empty()) {
      const size_t c = queue.front();
      queue.pop_front();
      for (size_t i : at[c]) {
        if (used[i]) continue;
        const size_t u = static_cast<size_t>(order.chain_upper[i]);
        const size_t l = static_cast<size_t>(order.chain_lower[i]);
        const size_t other = c == u ? l : u;
        if (known[other]) continue;
        used[i] = 1;
        // lambda(upper) - lambda(lower) = sum of the chain.
        lambda[other] = c == u ? combine(lambda[c], 1, chain_sum(lattice.chains[i]), -1)
                               : combine(lambda[c], 1, chain_sum(lattice.chains[i]), 1);
        known[other] = 1;
        queue.push_back(other);
      }
    }
  }
  if (extra) {
    extra->clear();
    for (size_t i = 0; i < used.size(); ++i) {
      if (!used[i]) extra->push_back(i);
    }
  }
  return lambda;
}

// cite: Blacker 1996, sec. 3-4 (a barrel is a single-axis sweep: every rib
// has its layers; at least one layer per barrel).
std::vector<IntervalRow> barrel_constraints(const VolumeFacts& facts, const SideLattice& lattice,
                                            const SweepOrder& order, const BarrelTree& tree,
                                            const std::set<int>& even_caps, const std::string& tag,
                                            double layer_size) {
  std::vector<IntervalRow> rows;
  std::vector<size_t> extra;
  const auto lambda = layer_potentials(lattice, order, &extra);
  std::set<Expr> seen;
  auto add = [&](Expr e, intervals::Sense sense, int rhs, const std::string& label) {
    if (e.empty()) return;
    if (sense == intervals::Sense::Equal) {
      // x and -x are the same equality.
      Expr neg = combine(e, -1, {}, 0);
      if (seen.count(e) || seen.count(neg)) return;
      seen.insert(e);
    }
    rows.push_back({std::move(e), sense, rhs, false, tag + ": " + label});
  };
  auto prefer = [&](const Expr& e, int rhs, const std::string& label) {
    if (!e.empty())
      rows.push_back({e, intervals::Sense::GreaterEqual, rhs, false, tag + ": " + label, true});
  };
  for (size_t i : extra) {
    const LinkChain& c = lattice.chains[i];
    const Expr diff = combine(lambda[static_cast<size_t>(order.chain_upper[i])], 1,
                              lambda[static_cast<size_t>(order.chain_lower[i])], -1);
    add(combine(diff, 1, chain_sum(c), -1), intervals::Sense::Equal, 0,
        "linking curves " + ids(c.curves) + " of side surface " + std::to_string(c.face) +
            " = the layers they span");
  }
  for (size_t b = 0; b < tree.barrels.size(); ++b) {
    const BarrelNode& node = tree.barrels[b];
    const std::string name = "barrel " + std::to_string(b + 1);
    for (const auto* classes : {&node.upper_classes, &node.lower_classes}) {
      for (size_t k = 1; k < classes->size(); ++k) {
        add(combine(lambda[static_cast<size_t>((*classes)[k])], 1,
                    lambda[static_cast<size_t>(classes->front())], -1),
            intervals::Sense::Equal, 0,
            name + ": its " + (classes == &node.upper_classes ? "upper" : "lower") +
                " cap on one layer");
      }
    }
    add(combine(lambda[static_cast<size_t>(node.upper_classes.front())], 1,
                lambda[static_cast<size_t>(node.lower_classes.front())], -1),
        intervals::Sense::GreaterEqual, 1,
        name + " (sides " + std::to_string(node.sides.front()) + ", ...) has a layer");
  }
  // A class no barrel ends on (the rim where a boss's cone meets its
  // cylinder) lies between the cap levels around it: its chains tie it to
  // their other ends only, and a cone of one interval put its top rim in
  // the middle of the barrel below the levels it passes (a blind hole's
  // floor and another's ceiling), so the barrels there found no side mesh.
  std::set<int> levels;
  for (const BarrelNode& node : tree.barrels) {
    levels.insert(node.upper_classes.begin(), node.upper_classes.end());
    levels.insert(node.lower_classes.begin(), node.lower_classes.end());
  }
  std::map<int, std::vector<int>> vertices_of;  // class -> its vertices
  for (const auto& [v, cls] : lattice.vertex_class) vertices_of[cls].push_back(v);
  for (size_t c = 0; c < lambda.size(); ++c) {
    if (levels.count(static_cast<int>(c))) continue;
    const double h = order.height[c];
    int above = -1, below = -1;
    for (int l : levels) {
      const double hl = order.height[static_cast<size_t>(l)];
      if (hl >= h && (above < 0 || hl < order.height[static_cast<size_t>(above)])) above = l;
      if (hl <= h && (below < 0 || hl > order.height[static_cast<size_t>(below)])) below = l;
    }
    const std::string name = "the ring of vertices " + ids(vertices_of[static_cast<int>(c)]);
    // A ring more than a quarter of an element from the level is a layer
    // away where the counts allow: on that level's layer, the rim of a
    // lug's cone 13 below a pocket's floor tilted the layer between them
    // across the narrow wall beside the lug, and the wall's quad there
    // folded with all four corners on its boundary (plan => mesh campaign
    // seed 10 case 169).
    const auto apart = [&](int level) {
      return layer_size > 0 && order.straight &&
             std::abs(order.height[static_cast<size_t>(level)] - h) > 0.25 * layer_size;
    };
    if (above >= 0) {
      const Expr gap = combine(lambda[static_cast<size_t>(above)], 1, lambda[c], -1);
      add(gap, intervals::Sense::GreaterEqual, 0, name + " lies below the cap level above it");
      if (apart(above)) prefer(gap, 1, name + " lies a layer below the cap level above it");
    }
    if (below >= 0) {
      const Expr gap = combine(lambda[c], 1, lambda[static_cast<size_t>(below)], -1);
      add(gap, intervals::Sense::GreaterEqual, 0, name + " lies above the cap level below it");
      if (apart(below)) prefer(gap, 1, name + " lies a layer above the cap level below it");
    }
  }
  for (int cap : even_caps) {
    {
      const auto& loops = facts.face(cap)->loops;
      for (size_t l = 0; l < loops.size(); ++l) {
        Expr e;
        for (const UseFact& u : loops[l]) e[u.curve] = 1;
        rows.push_back(
            {std::move(e), intervals::Sense::Equal, 0, true,
             tag + ": loop " + std::to_string(l) + " of cap " + std::to_string(cap) + " even"});
      }
    }
  }
  return rows;
}

void add_rows(const std::vector<IntervalRow>& rows, intervals::IntervalProblem& problem) {
  for (const IntervalRow& r : rows) {
    if (r.even) {
      std::vector<int> curves;
      for (const auto& [c, k] : r.terms) curves.push_back(c);
      problem.add_even(curves, r.label);
      continue;
    }
    std::vector<intervals::LinearTerm> terms;
    for (const auto& [c, k] : r.terms) terms.push_back({c, k});
    if (r.preferred)
      problem.add_preference(std::move(terms), r.sense, r.rhs, r.label);
    else
      problem.add_linear(std::move(terms), r.sense, r.rhs, r.label);
  }
}

}  // namespace cooperage::cooper
