#include "schemes/cooper/form_barrels.h"

#include <algorithm>
#include <utility>

namespace cooperage::cooper {
namespace {

// Compressed sorted adjacency of the quad edges over nodes 0..n-1.
struct Graph {
  std::vector<int> start;  // n + 1 offsets
  std::vector<int> next;   // neighbours, ascending per node
  int begin(int v) const { return start[static_cast<size_t>(v)]; }
  int end(int v) const { return start[static_cast<size_t>(v) + 1]; }
};

Graph build_graph(const std::vector<mesh::Quad>& quads, int n) {
  std::vector<std::pair<int, int>> edges;
  edges.reserve(quads.size() * 8);
  for (const auto& q : quads) {
    for (int k = 0; k < 4; ++k) {
      const int a = q[static_cast<size_t>(k)];
      const int b = q[static_cast<size_t>((k + 1) % 4)];
      edges.emplace_back(a, b);
      edges.emplace_back(b, a);
    }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  Graph g;
  g.start.assign(static_cast<size_t>(n) + 1, 0);
  for (const auto& e : edges) ++g.start[static_cast<size_t>(e.first) + 1];
  for (size_t i = 1; i < g.start.size(); ++i) g.start[i] += g.start[i - 1];
  g.next.reserve(edges.size());
  for (const auto& e : edges) g.next.push_back(e.second);
  return g;
}

}  // namespace

// cite: Blacker 1996, sec. 4 (rib progression, Figure 7).
Barrel form_barrels(const BarrelInput& input) {
  Barrel barrel;
  int n = 0;
  for (const auto& q : input.side_quads) {
    for (int v : q) n = std::max(n, v + 1);
  }
  for (const auto& loop : input.upper_loops) {
    for (int v : loop) n = std::max(n, v + 1);
  }
  for (int v : input.stop_nodes) n = std::max(n, v + 1);
  for (int v : input.blocked_nodes) n = std::max(n, v + 1);
  const Graph g = build_graph(input.side_quads, n);

  std::vector<char> in_rib(static_cast<size_t>(n), 0);
  std::vector<char> stop(static_cast<size_t>(n), 0);
  for (int v : input.stop_nodes) stop[static_cast<size_t>(v)] = 1;
  for (int v : input.blocked_nodes) in_rib[static_cast<size_t>(v)] = 1;
  std::vector<int> front;
  for (const auto& loop : input.upper_loops) {
    for (int v : loop) {
      if (in_rib[static_cast<size_t>(v)]) {
        barrel.why = "upper cap node " + std::to_string(v) + " appears twice in its loops";
        return barrel;
      }
      in_rib[static_cast<size_t>(v)] = 1;
      front.push_back(v);
    }
  }
  if (front.empty()) {
    barrel.why = "the upper cap has no boundary nodes";
    return barrel;
  }
  barrel.ribs.resize(front.size());
  for (size_t r = 0; r < front.size(); ++r) barrel.ribs[r].push_back(front[r]);

  std::vector<int> advanced(front.size());
  const int max_layers = input.layers > 0 ? input.layers : n;
  for (int layer = 1; layer <= max_layers; ++layer) {
    // A complete layer at a time: every front node is already in a rib, so
    // the only unused neighbour of a rib end is the next node down its side.
    for (size_t r = 0; r < front.size(); ++r) {
      const int v = front[r];
      int found = -1;
      int count = 0;
      for (int e = g.begin(v); e < g.end(v); ++e) {
        const int w = g.next[static_cast<size_t>(e)];
        if (in_rib[static_cast<size_t>(w)]) continue;
        found = w;
        ++count;
      }
      if (count != 1) {
        barrel.why = "rib " + std::to_string(r) + " at node " + std::to_string(v) + " (layer " +
                     std::to_string(layer - 1) + ") has " + std::to_string(count) +
                     " unused side neighbours; a rib needs exactly one";
        return barrel;
      }
      advanced[r] = found;
    }
    bool any_stop = false;
    for (size_t r = 0; r < front.size(); ++r) {
      const int w = advanced[r];
      if (in_rib[static_cast<size_t>(w)]) {
        barrel.why = "ribs " + std::to_string(r) + " and another one meet at node " +
                     std::to_string(w) + " in layer " + std::to_string(layer);
        return barrel;
      }
      in_rib[static_cast<size_t>(w)] = 1;
      barrel.ribs[r].push_back(w);
      any_stop = any_stop || stop[static_cast<size_t>(w)];
    }
    front.swap(advanced);
    if (input.layers > 0) {
      if (layer < input.layers && any_stop) {
        barrel.why = "a rib reaches another cap after " + std::to_string(layer) + " of " +
                     std::to_string(input.layers) + " layers";
        return barrel;
      }
      if (layer < input.layers) continue;
      barrel.layers = layer;
      barrel.all_ribs_on_stop_nodes = std::all_of(
          front.begin(), front.end(), [&](int w) { return stop[static_cast<size_t>(w)] != 0; });
      barrel.ok = true;
      return barrel;
    }
    if (any_stop) {
      // Rib formation ceases as soon as any rib reaches another cap.
      barrel.layers = layer;
      barrel.all_ribs_on_stop_nodes = std::all_of(
          front.begin(), front.end(), [&](int w) { return stop[static_cast<size_t>(w)] != 0; });
      barrel.ok = true;
      return barrel;
    }
  }
  barrel.why = "the ribs never reach another cap";
  return barrel;
}

}  // namespace cooperage::cooper
