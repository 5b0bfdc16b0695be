#include "schemes/pave/parity_paths.h"

#include "schemes/pave/split_to_quads.h"

#include <algorithm>
#include <unordered_set>
#include <stdexcept>

namespace cooperage::pave::detail {

namespace {

/// The edges of the cells in flat arrays (the search may sweep much of a
/// large mesh, and hash maps there cost more than the recombination):
/// edges numbered in order of first use, each with its one or two cells.
struct CellEdges {
  std::vector<std::array<int, 2>> cells_of;  ///< edge -> its cells (second -1 on a loop edge)
  std::vector<std::uint64_t> key;            ///< edge -> undirected_key
  std::vector<std::array<int, 4>> edges_of;  ///< cell -> its edges (-1 past a triangle's third)
  std::vector<int> first;  ///< CSR by smaller vertex: rows of (larger vertex, edge)
  std::vector<std::pair<int, int>> row;
  std::vector<int> fill;

  int find(int a, int b) const {
    if (a > b) std::swap(a, b);
    if (a < 0 || static_cast<size_t>(a) + 1 >= first.size()) return -1;
    for (int k = first[static_cast<size_t>(a)]; k < fill[static_cast<size_t>(a)]; ++k) {
      if (row[static_cast<size_t>(k)].first == b) return row[static_cast<size_t>(k)].second;
    }
    return -1;
  }
};

CellEdges cell_edges(const std::vector<Cell>& cells) {
  CellEdges g;
  int nv = 0;
  for (const Cell& c : cells) {
    for (int v : c) nv = std::max(nv, v + 1);
  }
  g.first.assign(static_cast<size_t>(nv) + 1, 0);
  for (const Cell& c : cells) {
    const int n = c[3] < 0 ? 3 : 4;
    for (int k = 0; k < n; ++k)
      ++g.first[static_cast<size_t>(
                    std::min(c[static_cast<size_t>(k)], c[static_cast<size_t>((k + 1) % n)])) +
                1];
  }
  for (size_t i = 0; i + 1 < g.first.size(); ++i) g.first[i + 1] += g.first[i];
  g.row.resize(static_cast<size_t>(g.first.back()));
  g.fill.assign(g.first.begin(), g.first.end() - 1);
  g.edges_of.resize(cells.size());
  for (int c = 0; c < static_cast<int>(cells.size()); ++c) {
    const Cell& cell = cells[static_cast<size_t>(c)];
    const int n = cell[3] < 0 ? 3 : 4;
    auto& mine = g.edges_of[static_cast<size_t>(c)];
    mine = {-1, -1, -1, -1};
    for (int k = 0; k < n; ++k) {
      const int a = cell[static_cast<size_t>(k)], b = cell[static_cast<size_t>((k + 1) % n)];
      int e = g.find(a, b);
      if (e < 0) {
        e = static_cast<int>(g.key.size());
        g.key.push_back(undirected_key(a, b));
        g.cells_of.push_back({c, -1});
        const size_t lo = static_cast<size_t>(std::min(a, b));
        g.row[static_cast<size_t>(g.fill[lo]++)] = {std::max(a, b), e};
      } else {
        g.cells_of[static_cast<size_t>(e)][1] = c;
      }
      mine[static_cast<size_t>(k)] = e;
    }
  }
  return g;
}

}  // namespace

int split_loop_triangles(std::vector<Cell>& cells, std::vector<Eigen::Vector2d>& points,
                         const std::vector<std::vector<int>>& loops,
                         const std::vector<std::uint64_t>& odd_edges, LoopTriangles which) {
  if (odd_edges.empty()) return 0;
  std::unordered_set<std::uint64_t> loop_edges;
  for (const auto& loop : loops) {
    for (size_t k = 0; k < loop.size(); ++k)
      loop_edges.insert(undirected_key(loop[k], loop[(k + 1) % loop.size()]));
  }
  const std::unordered_set<std::uint64_t> odd(odd_edges.begin(), odd_edges.end());
  int split = 0;
  const size_t n = cells.size();
  for (size_t c = 0; c < n; ++c) {
    const Cell t = cells[c];
    if (t[3] >= 0) continue;
    int odd_count = 0, plain_loop = 0;
    for (int k = 0; k < 3; ++k) {
      const std::uint64_t key =
          undirected_key(t[static_cast<size_t>(k)], t[static_cast<size_t>((k + 1) % 3)]);
      if (odd.count(key)) {
        ++odd_count;
      } else if (loop_edges.count(key)) {
        ++plain_loop;
      }
    }
    if (plain_loop == 0) continue;
    if (which == LoopTriangles::OddEars && odd_count != 1) continue;
    const int g = static_cast<int>(points.size());
    points.push_back((points[static_cast<size_t>(t[0])] + points[static_cast<size_t>(t[1])] +
                      points[static_cast<size_t>(t[2])]) /
                     3.0);
    cells[c] = {t[0], t[1], g, -1};
    cells.push_back({t[1], t[2], g, -1});
    cells.push_back({t[2], t[0], g, -1});
    ++split;
  }
  return split;
}

std::unordered_set<std::uint64_t> parity_paths(const std::vector<Cell>& cells,
                                               const std::vector<std::uint64_t>& odd_edges) {
  std::unordered_set<std::uint64_t> odd(odd_edges.begin(), odd_edges.end());
  if (odd_edges.empty()) return odd;
  if (odd_edges.size() % 2 != 0) throw std::runtime_error("an odd number of odd loop edges");
  const CellEdges g = cell_edges(cells);
  auto is_loop_edge = [&](int e) { return g.cells_of[static_cast<size_t>(e)][1] < 0; };
  // Crossing cell c from edge e_in to edge e_out is allowed unless c is a
  // triangle whose third edge is a loop edge: its single quad would then have
  // a straight angle at the fixed boundary node in the middle of that edge.
  auto may_cross = [&](int c, int e_in, int e_out) {
    if (cells[static_cast<size_t>(c)][3] >= 0) return true;
    for (int e : g.edges_of[static_cast<size_t>(c)]) {
      if (e >= 0 && e != e_in && e != e_out) return !is_loop_edge(e);
    }
    return true;
  };
  std::vector<int> odd_ids;
  for (std::uint64_t key : odd_edges) {
    const int e = g.find(static_cast<int>(key >> 32), static_cast<int>(key & 0xffffffffu));
    if (e < 0) throw std::runtime_error("an odd loop edge has no cell");
    odd_ids.push_back(e);
  }
  std::vector<char> unpaired(g.key.size(), 0);
  for (int e : odd_ids) unpaired[static_cast<size_t>(e)] = 1;
  std::vector<int> seen_in(g.key.size(), -1);  // the search that reached each edge
  for (size_t p = 0; p < odd_ids.size(); ++p) {
    const int start_edge = odd_ids[p];
    if (!unpaired[static_cast<size_t>(start_edge)]) continue;
    unpaired[static_cast<size_t>(start_edge)] = 0;
    // Breadth-first search over (edge, the cell entered through it) until a
    // cell holding another unpaired odd edge.
    struct State {
      int edge;
      int cell;
      int parent;
    };
    std::vector<State> states{{start_edge, g.cells_of[static_cast<size_t>(start_edge)][0], -1}};
    seen_in[static_cast<size_t>(start_edge)] = static_cast<int>(p);
    int found = -1, found_edge = -1;
    for (size_t head = 0; head < states.size() && found < 0; ++head) {
      const State st = states[head];
      for (int e : g.edges_of[static_cast<size_t>(st.cell)]) {
        if (e < 0 || e == st.edge) continue;
        if (unpaired[static_cast<size_t>(e)] && may_cross(st.cell, st.edge, e)) {
          found = static_cast<int>(head);
          found_edge = e;
          break;
        }
      }
      if (found >= 0) break;
      for (int e : g.edges_of[static_cast<size_t>(st.cell)]) {
        if (e < 0 || e == st.edge || is_loop_edge(e) ||
            seen_in[static_cast<size_t>(e)] == static_cast<int>(p) ||
            !may_cross(st.cell, st.edge, e)) {
          continue;
        }
        seen_in[static_cast<size_t>(e)] = static_cast<int>(p);
        const auto& two = g.cells_of[static_cast<size_t>(e)];
        states.push_back({e, two[0] == st.cell ? two[1] : two[0], static_cast<int>(head)});
      }
    }
    if (found < 0) throw std::runtime_error("no path joins two odd loop edges");
    unpaired[static_cast<size_t>(found_edge)] = 0;
    for (int k = found; states[static_cast<size_t>(k)].parent >= 0;
         k = states[static_cast<size_t>(k)].parent) {
      const std::uint64_t key = g.key[static_cast<size_t>(states[static_cast<size_t>(k)].edge)];
      if (!odd.erase(key)) odd.insert(key);
    }
  }
  return odd;
}

}  // namespace cooperage::pave::detail
