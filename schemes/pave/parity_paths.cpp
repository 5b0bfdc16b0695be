#include "schemes/pave/parity_paths.h"

#include "schemes/pave/split_to_quads.h"

#include <algorithm>
#include <stdexcept>
#include <unordered_map>

namespace cooperage::pave::detail {

std::unordered_set<std::uint64_t> parity_paths(const std::vector<Cell>& cells,
                                               const std::vector<std::uint64_t>& odd_edges) {
  std::unordered_set<std::uint64_t> odd(odd_edges.begin(), odd_edges.end());
  if (odd_edges.empty()) return odd;
  if (odd_edges.size() % 2 != 0) throw std::runtime_error("an odd number of odd loops");
  // Edge -> the (one or two) cells using it; cell -> its edges.
  std::unordered_map<std::uint64_t, std::array<int, 2>> cells_of;
  std::vector<std::array<std::uint64_t, 4>> edges_of(cells.size());
  for (int c = 0; c < static_cast<int>(cells.size()); ++c) {
    const Cell& cell = cells[static_cast<size_t>(c)];
    const int n = cell[3] < 0 ? 3 : 4;
    for (int k = 0; k < 4; ++k) edges_of[static_cast<size_t>(c)][static_cast<size_t>(k)] = 0;
    for (int k = 0; k < n; ++k) {
      const std::uint64_t e = undirected_key(cell[static_cast<size_t>(k)], cell[static_cast<size_t>((k + 1) % n)]);
      edges_of[static_cast<size_t>(c)][static_cast<size_t>(k)] = e;
      auto it = cells_of.find(e);
      if (it == cells_of.end()) {
        cells_of.emplace(e, std::array<int, 2>{c, -1});
      } else {
        it->second[1] = c;
      }
    }
  }
  auto is_loop_edge = [&](std::uint64_t e) { return cells_of[e][1] < 0; };
  // Crossing cell c from edge e_in to edge e_out is allowed unless c is a
  // triangle whose third edge is a loop edge: its single quad would then have
  // a straight angle at the fixed boundary node in the middle of that edge.
  auto may_cross = [&](int c, std::uint64_t e_in, std::uint64_t e_out) {
    if (cells[static_cast<size_t>(c)][3] >= 0) return true;
    for (std::uint64_t e : edges_of[static_cast<size_t>(c)]) {
      if (e != 0 && e != e_in && e != e_out) return !is_loop_edge(e);
    }
    return true;
  };
  std::unordered_map<std::uint64_t, bool> unpaired;
  for (std::uint64_t e : odd_edges) unpaired[e] = true;
  for (std::uint64_t start_edge : odd_edges) {
    if (!unpaired[start_edge]) continue;
    unpaired[start_edge] = false;
    if (!cells_of.count(start_edge)) throw std::runtime_error("an odd loop edge has no cell");
    // Breadth-first search over (edge, the cell entered through it) until a
    // cell holding another unpaired odd edge.
    struct State {
      std::uint64_t edge;
      int cell;
      int parent;
    };
    std::vector<State> states{{start_edge, cells_of[start_edge][0], -1}};
    std::unordered_set<std::uint64_t> seen{start_edge};
    int found = -1;
    std::uint64_t found_edge = 0;
    for (size_t head = 0; head < states.size() && found < 0; ++head) {
      const State st = states[head];
      for (std::uint64_t e : edges_of[static_cast<size_t>(st.cell)]) {
        if (e == 0 || e == st.edge) continue;
        auto u = unpaired.find(e);
        if (u != unpaired.end() && u->second && may_cross(st.cell, st.edge, e)) {
          found = static_cast<int>(head);
          found_edge = e;
          break;
        }
      }
      if (found >= 0) break;
      for (std::uint64_t e : edges_of[static_cast<size_t>(st.cell)]) {
        if (e == 0 || e == st.edge || is_loop_edge(e) || seen.count(e) || !may_cross(st.cell, st.edge, e)) continue;
        seen.insert(e);
        const auto& two = cells_of[e];
        states.push_back({e, two[0] == st.cell ? two[1] : two[0], static_cast<int>(head)});
      }
    }
    if (found < 0) throw std::runtime_error("no path joins two odd loops");
    unpaired[found_edge] = false;
    for (int k = found; states[static_cast<size_t>(k)].parent >= 0; k = states[static_cast<size_t>(k)].parent) {
      const std::uint64_t e = states[static_cast<size_t>(k)].edge;
      if (!odd.erase(e)) odd.insert(e);
    }
  }
  return odd;
}

}  // namespace cooperage::pave::detail
