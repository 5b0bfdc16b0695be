#include "schemes/cooper/sweep_order.h"

#include <algorithm>
#include <deque>
#include <set>

namespace cooperage::cooper {
namespace {

// x_a XOR x_b = parity, over nodes "f<id>" (sides) and "c<id>" (caps).
struct ParityGraph {
  struct Edge {
    int to;
    int parity;
    std::string why;
  };
  std::map<int, std::vector<Edge>> adj;  // node key: +id side, -id cap
  void add(int a, int b, int parity, const std::string& why) {
    adj[a].push_back({b, parity, why});
    adj[b].push_back({a, parity, why});
  }
};

int side_key(int face) { return face; }
int cap_key(int face) { return -face; }

std::string node_name(int key) {
  return key > 0 ? "side surface " + std::to_string(key) : "cap " + std::to_string(-key);
}

}  // namespace

// cite: Blacker 1996, sec. 4 (ribs progress from the upper cap down the
// sides; upper/lower designations are arbitrary but consistent per barrel).
SweepOrder sweep_order(const VolumeFacts& facts, const SideLattice& lattice,
                       const OrderAnchor& anchor) {
  SweepOrder out;
  ParityGraph g;
  for (int s : lattice.sides) g.adj[side_key(s)];
  for (int c : lattice.caps) g.adj[cap_key(c)];
  // A contact: the side lies above the cap iff the chain leaving the run
  // goes up; it lies above an upper cap iff the contact is re-entrant.
  for (const CapContact& k : lattice.contacts) {
    const int sb = k.leaving_sign > 0 ? 1 : 0;
    g.add(side_key(k.face), cap_key(k.cap), 1 ^ sb ^ (k.convex ? 1 : 0),
          "side surface " + std::to_string(k.face) + " meets cap " + std::to_string(k.cap) + " " +
              (k.convex ? "convexly" : "re-entrantly") + " along curve " + std::to_string(k.curve));
  }
  // A linking curve shared by two sides runs the same way in both.
  std::map<int, std::vector<std::pair<int, int>>> uses;  // curve -> (face, fwd ^ sign bit)
  for (const LinkChain& c : lattice.chains) {
    for (size_t i = 0; i < c.curves.size(); ++i) {
      uses[c.curves[i]].push_back({c.face, (c.forward[i] ? 1 : 0) ^ (c.lattice_sign > 0 ? 1 : 0)});
    }
  }
  for (const auto& [curve, list] : uses) {
    for (size_t i = 1; i < list.size(); ++i) {
      if (list[i].first == list[0].first) continue;  // a seam walked up and down in one face
      g.add(side_key(list[0].first), side_key(list[i].first), list[0].second ^ list[i].second,
            "curve " + std::to_string(curve) + " links the sides " + std::to_string(list[0].first) +
                " and " + std::to_string(list[i].first));
    }
  }
  // A curve running along between two stacked sides: one above, one below.
  std::map<int, std::vector<const StackedCurve*>> stacked;
  for (const StackedCurve& s : lattice.stacked) stacked[s.curve].push_back(&s);
  for (const auto& [curve, list] : stacked) {
    for (size_t i = 1; i < list.size(); ++i) {
      if (list[i]->face == list[0]->face) continue;
      const int a = list[0]->leaving_sign > 0 ? 1 : 0, b = list[i]->leaving_sign > 0 ? 1 : 0;
      g.add(side_key(list[0]->face), side_key(list[i]->face), 1 ^ a ^ b,
            "curve " + std::to_string(curve) + " joins the stacked sides " +
                std::to_string(list[0]->face) + " and " + std::to_string(list[i]->face));
    }
  }
  // Anchors, then propagation (deterministic: ascending keys).
  std::map<int, int> value;
  std::deque<int> queue;
  auto fix = [&](int key, int v, const std::string& why) {
    const auto [it, added] = value.emplace(key, v);
    if (!added && it->second != v) {
      out.why = node_name(key) + " is both an upper and a lower end (" + why + ")";
      return false;
    }
    if (added) queue.push_back(key);
    return true;
  };
  if (anchor.down) {
    const geom::Vec3 d = anchor.down->normalized();
    for (int c : lattice.caps) {
      if (!fix(cap_key(c), facts.face(c)->normal.dot(d) < 0 ? 1 : 0,
               "its normal against the sweep axis"))
        return out;
    }
  } else if (anchor.upper_cap) {
    if (!fix(cap_key(anchor.upper_cap), anchor.flip ? 0 : 1, "the cap the sweep starts from"))
      return out;
  }
  if (queue.empty()) {
    out.why = "no anchor for the sweep direction";
    return out;
  }
  while (!queue.empty()) {
    const int key = queue.front();
    queue.pop_front();
    for (const auto& e : g.adj[key]) {
      const int want = value.at(key) ^ e.parity;
      const auto [it, added] = value.emplace(e.to, want);
      if (added) {
        queue.push_back(e.to);
      } else if (it->second != want) {
        out.why = "the sweep cannot run one way through " + node_name(key) + " and " +
                  node_name(e.to) + " (" + e.why +
                  "; Blacker 1996, sec. 3: one projection direction along every shared face)";
        return out;
      }
    }
  }
  for (const auto& [key, adj] : g.adj) {
    if (!value.count(key)) {
      out.why = node_name(key) + " is not connected to the rest of the sweep";
      return out;
    }
  }
  for (int c : lattice.caps) out.upper[c] = value.at(cap_key(c)) == 1;
  for (int s : lattice.sides) out.face_up[s] = value.at(side_key(s)) == 1 ? 1 : -1;
  for (const LinkChain& c : lattice.chains) {
    const bool up = (c.lattice_sign > 0) == (out.face_up.at(c.face) > 0);
    out.chain_upper.push_back(up ? c.to_class : c.from_class);
    out.chain_lower.push_back(up ? c.from_class : c.to_class);
  }
  out.height.assign(static_cast<size_t>(lattice.classes), 0.0);
  if (anchor.down) {
    out.straight = true;
    const geom::Vec3 d = anchor.down->normalized();
    std::vector<int> count(out.height.size(), 0);
    for (const auto& [v, cls] : lattice.vertex_class) {
      out.height[static_cast<size_t>(cls)] -= facts.vertices.at(v).dot(d);
      ++count[static_cast<size_t>(cls)];
    }
    for (size_t i = 0; i < out.height.size(); ++i) {
      if (count[i]) out.height[i] /= count[i];
    }
    const double tol = 1e-6 * facts.size();
    for (size_t i = 0; i < lattice.chains.size(); ++i) {
      if (out.height[static_cast<size_t>(out.chain_upper[i])] <=
          out.height[static_cast<size_t>(out.chain_lower[i])] + tol) {
        out.why = "side surface " + std::to_string(lattice.chains[i].face) +
                  " links its levels against the sweep axis";
        return out;
      }
    }
  } else {
    // Longest paths down the chains (lengths), from the classes nothing is above.
    const size_t n = out.height.size();
    std::vector<std::vector<std::pair<int, double>>> below(n);
    std::vector<int> indegree(n, 0);
    std::set<std::pair<int, int>> seen;
    for (size_t i = 0; i < lattice.chains.size(); ++i) {
      below[static_cast<size_t>(out.chain_upper[i])].push_back(
          {out.chain_lower[i], lattice.chains[i].length});
      ++indegree[static_cast<size_t>(out.chain_lower[i])];
    }
    std::vector<double> depth(n, 0.0);
    std::deque<int> ready;
    for (size_t i = 0; i < n; ++i) {
      if (indegree[i] == 0) ready.push_back(static_cast<int>(i));
    }
    size_t done = 0;
    while (!ready.empty()) {
      const int u = ready.front();
      ready.pop_front();
      ++done;
      for (const auto& [w, len] : below[static_cast<size_t>(u)]) {
        depth[static_cast<size_t>(w)] =
            std::max(depth[static_cast<size_t>(w)], depth[static_cast<size_t>(u)] + len);
        if (--indegree[static_cast<size_t>(w)] == 0) ready.push_back(w);
      }
    }
    if (done != n) {
      out.why = "the chains of the sides run in a circle (no first level)";
      return out;
    }
    for (size_t i = 0; i < n; ++i) out.height[i] = -depth[i];
  }
  out.ok = true;
  return out;
}

}  // namespace cooperage::cooper
