#include "schemes/cooper/side_parity.h"

#include "schemes/cooper/side_lattice.h"

#include <map>
#include <numeric>

namespace cooperage::cooper {
namespace {

// Union-find over curves with the parity of each to its root: the roles of
// two curves in one set are equal or opposite by the parities' sum. Node 0
// stands for "runs along".
class ParityForest {
 public:
  explicit ParityForest(int n) : parent_(static_cast<size_t>(n)), parity_(static_cast<size_t>(n)) {
    std::iota(parent_.begin(), parent_.end(), 0);
  }
  /// Ties a and b (roles equal when `differ` is 0); false on a contradiction.
  bool tie(int a, int b, int differ) {
    const auto [ra, pa] = find(a);
    const auto [rb, pb] = find(b);
    if (ra == rb) return (pa ^ pb) == differ;
    parent_[static_cast<size_t>(ra)] = rb;
    parity_[static_cast<size_t>(ra)] = pa ^ pb ^ differ;
    return true;
  }

 private:
  std::pair<int, int> find(int a) {
    int p = 0;
    int r = a;
    while (parent_[static_cast<size_t>(r)] != r) {
      p ^= parity_[static_cast<size_t>(r)];
      r = parent_[static_cast<size_t>(r)];
    }
    // Path compression: every node on the path points at the root.
    int q = p;
    while (parent_[static_cast<size_t>(a)] != a) {
      const int next = parent_[static_cast<size_t>(a)];
      const int own = parity_[static_cast<size_t>(a)];
      parent_[static_cast<size_t>(a)] = r;
      parity_[static_cast<size_t>(a)] = q;
      q ^= own;
      a = next;
    }
    return {r, p};
  }
  std::vector<int> parent_;
  std::vector<int> parity_;
};

}  // namespace

SideParity::SideParity(const VolumeFacts& facts) {
  std::map<int, int> index;  // curve id -> 1..n (0 is "along")
  for (const auto& [id, c] : facts.curves) index.emplace(id, static_cast<int>(index.size()) + 1);
  curves_ = static_cast<int>(index.size()) + 1;
  for (const FaceFact& f : facts.faces) {
    Face face;
    face.id = f.id;
    face.side = !cannot_be_side(f);
    face.rigid = face.side && !f.ambiguous_corners;
    for (size_t l = 0; l < f.loops.size(); ++l) {
      for (size_t k = 0; k < f.loops[l].size(); ++k) {
        const auto it = index.find(f.loops[l][k].curve);
        if (it == index.end()) continue;  // not a curve of the facts: side_lattice decides
        const int parity = face.rigid ? f.directions[k] % 2 : 0;
        face.uses.push_back({it->second, parity});
      }
    }
    faces_.push_back(std::move(face));
  }
}

bool SideParity::can_agree(const std::set<int>& caps) const {
  ParityForest forest(curves_);
  for (const Face& f : faces_) {
    if (caps.count(f.id)) {
      for (const auto& [curve, parity] : f.uses) {
        if (!forest.tie(curve, 0, 0)) return false;
      }
    } else if (!f.side) {
      return false;
    } else if (f.rigid && !f.uses.empty()) {
      const auto& [first, first_parity] = f.uses.front();
      for (const auto& [curve, parity] : f.uses) {
        if (!forest.tie(curve, first, parity ^ first_parity)) return false;
      }
    }
  }
  return true;
}

}  // namespace cooperage::cooper
