#include "schemes/map/block_lattice.h"

#include <algorithm>
#include <cstdint>
#include <map>
#include <unordered_map>

namespace cooperage::map {
namespace {

std::uint64_t edge_key(int a, int b) {
  const auto lo = static_cast<std::uint32_t>(std::min(a, b));
  const auto hi = static_cast<std::uint32_t>(std::max(a, b));
  return (static_cast<std::uint64_t>(lo) << 32) | hi;
}

// True when a-b is an edge of quad q.
bool quad_has_edge(const mesh::Quad& q, int a, int b) {
  for (size_t k = 0; k < 4; ++k) {
    const int x = q[k], y = q[(k + 1) % 4];
    if ((x == a && y == b) || (x == b && y == a)) return true;
  }
  return false;
}

struct Failure {
  std::string why;
};

class Recovery {
 public:
  explicit Recovery(const std::vector<mesh::Quad>& quads) : quads_(quads) {
    for (size_t q = 0; q < quads.size(); ++q) {
      for (size_t k = 0; k < 4; ++k) {
        const int a = quads[q][k], b = quads[q][(k + 1) % 4];
        edges_[edge_key(a, b)].push_back(q);
        neighbours_[a].push_back(b);
        neighbours_[b].push_back(a);
        ++valence_[a];
      }
    }
    for (auto& [node, list] : neighbours_) {
      std::sort(list.begin(), list.end());
      list.erase(std::unique(list.begin(), list.end()), list.end());
    }
    for (const auto& [key, list] : edges_) {
      if (list.size() != 2) {
        throw Failure{"the boundary mesh is not closed: edge " +
                      std::to_string(static_cast<int>(key >> 32)) + "-" +
                      std::to_string(static_cast<int>(key & 0xffffffffu)) + " is in " +
                      std::to_string(list.size()) + " quads"};
      }
    }
  }

  BlockLattice run() {
    std::vector<int> corners;
    for (const auto& [node, count] : valence_) {
      if (count == 3)
        corners.push_back(node);
      else if (count != 4) {
        throw Failure{"node " + std::to_string(node) + " is in " + std::to_string(count) +
                      " boundary quads; a mapped block has 3 at its 8 corners and 4 elsewhere"};
      }
    }
    if (corners.size() != 8) {
      throw Failure{std::to_string(corners.size()) +
                    " boundary nodes are in 3 quads; a mapped block has 8 corners"};
    }
    std::sort(corners.begin(), corners.end());
    const int c0 = corners.front();
    const std::vector<int>& first = neighbours_.at(c0);
    if (first.size() != 3) throw Failure{"corner node " + std::to_string(c0) + " has no 3 edges"};
    const std::vector<int> li = walk(c0, first[0]);
    const std::vector<int> lj = walk(c0, first[1]);
    const std::vector<int> lk = walk(c0, first[2]);
    out_.ni = static_cast<int>(li.size()) - 1;
    out_.nj = static_cast<int>(lj.size()) - 1;
    out_.nk = static_cast<int>(lk.size()) - 1;
    const int ni = out_.ni, nj = out_.nj, nk = out_.nk;
    const size_t expected = 2 * static_cast<size_t>(ni * nj + nj * nk + ni * nk);
    if (expected != quads_.size()) {
      throw Failure{"block lines of " + std::to_string(ni) + ", " + std::to_string(nj) + ", " +
                    std::to_string(nk) + " intervals need " + std::to_string(expected) +
                    " boundary quads, the surfaces have " + std::to_string(quads_.size())};
    }
    out_.node.assign(static_cast<size_t>((ni + 1) * (nj + 1) * (nk + 1)), -1);
    used_.assign(quads_.size(), false);

    auto line = [&](int count, auto node_at) {
      std::vector<int> l;
      for (int a = 0; a <= count; ++a) l.push_back(node_at(a));
      return l;
    };
    fill(li, lj, [&](int a, int b) { return index(a, b, 0); });
    fill(li, lk, [&](int a, int b) { return index(a, 0, b); });
    fill(lj, lk, [&](int a, int b) { return index(0, a, b); });
    fill(line(nj, [&](int j) { return get(ni, j, 0); }),
         line(nk, [&](int k) { return get(ni, 0, k); }),
         [&](int a, int b) { return index(ni, a, b); });
    fill(line(ni, [&](int i) { return get(i, nj, 0); }),
         line(nk, [&](int k) { return get(0, nj, k); }),
         [&](int a, int b) { return index(a, nj, b); });
    fill(line(ni, [&](int i) { return get(i, 0, nk); }),
         line(nj, [&](int j) { return get(0, j, nk); }),
         [&](int a, int b) { return index(a, b, nk); });
    out_.ok = true;
    return out_;
  }

 private:
  size_t index(int i, int j, int k) const {
    return (static_cast<size_t>(k) * static_cast<size_t>(out_.nj + 1) + static_cast<size_t>(j)) *
               static_cast<size_t>(out_.ni + 1) +
           static_cast<size_t>(i);
  }
  int get(int i, int j, int k) const { return out_.node[index(i, j, k)]; }

  void set(size_t at, int node) {
    int& slot = out_.node[at];
    if (slot >= 0 && slot != node) {
      throw Failure{"the faces disagree at a block edge (nodes " + std::to_string(slot) + " and " +
                    std::to_string(node) + ")"};
    }
    slot = node;
  }

  // The grid line from corner c through its neighbour q, straight through
  // valence-4 nodes, up to the next corner.
  std::vector<int> walk(int c, int q) const {
    std::vector<int> l{c, q};
    int p = c;
    while (valence_.at(q) == 4) {
      if (l.size() > valence_.size() + 1) throw Failure{"a grid line does not end at a corner"};
      const auto& around = edges_.at(edge_key(p, q));
      int next = -1;
      for (int r : neighbours_.at(q)) {
        if (r == p) continue;
        if (quad_has_edge(quads_[around[0]], q, r) || quad_has_edge(quads_[around[1]], q, r))
          continue;
        if (next >= 0)
          throw Failure{"node " + std::to_string(q) + " has no unique straight continuation"};
        next = r;
      }
      if (next < 0) throw Failure{"node " + std::to_string(q) + " has no straight continuation"};
      p = q;
      q = next;
      l.push_back(q);
    }
    return l;
  }

  // Fills the face spanned by grid lines la (a = 0..na) and lb (b = 0..nb)
  // from their common corner, quad by quad.
  template <class Index>
  void fill(const std::vector<int>& la, const std::vector<int>& lb, Index at) {
    const int na = static_cast<int>(la.size()) - 1, nb = static_cast<int>(lb.size()) - 1;
    std::vector<int> g(static_cast<size_t>((na + 1) * (nb + 1)), -1);
    auto cell = [&](int a, int b) -> int& { return g[static_cast<size_t>(a * (nb + 1) + b)]; };
    for (int a = 0; a <= na; ++a) cell(a, 0) = la[static_cast<size_t>(a)];
    for (int b = 0; b <= nb; ++b) cell(0, b) = lb[static_cast<size_t>(b)];
    for (int b = 0; b < nb; ++b) {
      for (int a = 0; a < na; ++a) {
        const int p = cell(a, b), q = cell(a + 1, b), r = cell(a, b + 1);
        auto it = edges_.find(edge_key(p, q));
        int found = -1;
        if (it != edges_.end()) {
          for (size_t qi : it->second) {
            if (quad_has_edge(quads_[qi], p, r)) found = static_cast<int>(qi);
          }
        }
        if (found < 0 || used_[static_cast<size_t>(found)]) {
          throw Failure{"no unused boundary quad at nodes " + std::to_string(p) + ", " +
                        std::to_string(q) + ", " + std::to_string(r)};
        }
        used_[static_cast<size_t>(found)] = true;
        const mesh::Quad& quad = quads_[static_cast<size_t>(found)];
        int fourth = -1;
        for (int x : quad) {
          if (x != p && x != q && x != r) fourth = x;
        }
        if (!quad_has_edge(quad, q, fourth)) throw Failure{"a boundary quad is twisted"};
        cell(a + 1, b + 1) = fourth;
      }
    }
    // The far row and column are reached from other faces too: set() checks them.
    for (int a = 0; a <= na; ++a) {
      for (int b = 0; b <= nb; ++b) set(at(a, b), cell(a, b));
    }
  }

  const std::vector<mesh::Quad>& quads_;
  std::unordered_map<std::uint64_t, std::vector<size_t>> edges_;
  std::unordered_map<int, std::vector<int>> neighbours_;
  std::map<int, int> valence_;
  std::vector<bool> used_;
  BlockLattice out_;
};

}  // namespace

BlockLattice recover_block_lattice(const std::vector<mesh::Quad>& quads) {
  try {
    return Recovery(quads).run();
  } catch (const Failure& f) {
    BlockLattice out;
    out.why = f.why;
    return out;
  }
}

}  // namespace cooperage::map
