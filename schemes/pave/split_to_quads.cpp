#include "schemes/pave/split_to_quads.h"

#include <algorithm>

namespace cooperage::pave::detail {

void split_to_quads(const std::vector<Cell>& cells,
                    const std::vector<Eigen::Vector2d>& coarse_points,
                    std::vector<int> fine_of_coarse,
                    const std::unordered_map<std::uint64_t, int>& edge_midpoint,
                    std::vector<Eigen::Vector2d>& fine_points, std::vector<Quad>& quads,
                    const std::unordered_set<std::uint64_t>& no_midpoint) {
  auto add = [&](const Eigen::Vector2d& x) {
    fine_points.push_back(x);
    return static_cast<int>(fine_points.size()) - 1;
  };
  auto node = [&](int c) {
    int& f = fine_of_coarse[static_cast<size_t>(c)];
    if (f < 0) f = add(coarse_points[static_cast<size_t>(c)]);
    return f;
  };
  // The cells' edges in compressed rows by their lower end, each with its
  // midpoint (-2: not decided yet). A hash map of all edges thrashes the
  // cache on large meshes; the rows hold a few edges each.
  const size_t n_coarse = coarse_points.size();
  std::vector<int> row(n_coarse + 1, 0);
  for (const Cell& c : cells) {
    const int n = c[3] < 0 ? 3 : 4;
    for (int k = 0; k < n; ++k) {
      ++row[static_cast<size_t>(
                std::min(c[static_cast<size_t>(k)], c[static_cast<size_t>((k + 1) % n)])) +
            1];
    }
  }
  for (size_t i = 0; i < n_coarse; ++i) row[i + 1] += row[i];
  std::vector<int> other(static_cast<size_t>(row[n_coarse]), -1);
  std::vector<int> value(other.size(), -2);
  {
    std::vector<int> fill(row.begin(), row.end() - 1);
    for (const Cell& c : cells) {
      const int n = c[3] < 0 ? 3 : 4;
      for (int k = 0; k < n; ++k) {
        const int a = c[static_cast<size_t>(k)], b = c[static_cast<size_t>((k + 1) % n)];
        const size_t lo = static_cast<size_t>(std::min(a, b));
        const int hi = std::max(a, b);
        bool seen = false;
        for (int j = row[lo]; j < fill[lo]; ++j) seen = seen || other[static_cast<size_t>(j)] == hi;
        if (!seen) other[static_cast<size_t>(fill[lo]++)] = hi;
      }
    }
  }
  auto mid = [&](int a, int b) {
    const size_t lo = static_cast<size_t>(std::min(a, b));
    const int hi = std::max(a, b);
    int slot = row[lo];
    while (other[static_cast<size_t>(slot)] != hi) ++slot;
    int& m = value[static_cast<size_t>(slot)];
    if (m != -2) return m;
    const std::uint64_t k = undirected_key(a, b);
    if (!no_midpoint.empty() && no_midpoint.count(k)) return m = -1;
    auto it = edge_midpoint.find(k);
    if (it != edge_midpoint.end()) return m = it->second;
    return m = add(0.5 *
                   (coarse_points[static_cast<size_t>(a)] + coarse_points[static_cast<size_t>(b)]));
  };
  quads.reserve(quads.size() + cells.size() * 4);
  for (const Cell& c : cells) {
    const int n = c[3] < 0 ? 3 : 4;
    // The cell's ring of fine nodes: corners and the midpoints that exist.
    int ring[8];
    int r = 0, first_mid = -1;
    Eigen::Vector2d g = Eigen::Vector2d::Zero();
    for (int k = 0; k < n; ++k) {
      ring[r++] = node(c[static_cast<size_t>(k)]);
      g += coarse_points[static_cast<size_t>(c[static_cast<size_t>(k)])];
      const int m = mid(c[static_cast<size_t>(k)], c[static_cast<size_t>((k + 1) % n)]);
      if (m >= 0) {
        if (first_mid < 0) first_mid = r;
        ring[r++] = m;
      }
    }
    if (r == 4) {  // a cell crossed by parity paths on every side pair
      quads.push_back({ring[0], ring[1], ring[2], ring[3]});
      continue;
    }
    if (r == 6 && n == 4) {
      // Two midpoints: opposite ones split the quad in two.
      int mids[2], count = 0;
      for (int k = 0; k < 6; ++k) {
        bool is_corner = false;
        for (int j = 0; j < n; ++j)
          is_corner = is_corner || ring[k] == node(c[static_cast<size_t>(j)]);
        if (!is_corner && count < 2) mids[count++] = k;
      }
      if (count == 2 && mids[1] - mids[0] == 3) {
        const int i = mids[0];
        quads.push_back({ring[i], ring[i + 1], ring[i + 2], ring[i + 3]});
        quads.push_back({ring[(i + 3) % 6], ring[(i + 4) % 6], ring[(i + 5) % 6], ring[i]});
        continue;
      }
    }
    // Otherwise a centre node joined to every other ring node, starting at
    // a midpoint: (centre, ring[s], ring[s + 1], ring[s + 2]).
    const int center = add(g / n);
    for (int s = first_mid; s < first_mid + r; s += 2) {
      quads.push_back({center, ring[s % r], ring[(s + 1) % r], ring[(s + 2) % r]});
    }
  }
}

}  // namespace cooperage::pave::detail
