// A quick necessary test of a sorting of faces into caps and sides, before
// side_lattice() runs it in full. Every side whose corners type it alone
// (a rigid side) ties its curves' roles: curve k runs along the caps when
// its lattice direction d_k has the parity the face takes, so two of its
// curves share a role when their directions have the same parity and swap
// it otherwise. Every cap curve runs along. When these ties contradict
// each other no lattice exists, and side_lattice() would refuse the
// sorting too (it assigns every rigid side's curves by the same rule).
// A curved sweep's search plans thousands of sortings per volume, and a
// search of decompositions plans it for every piece of every cut
// (issue 16: 50,000 sortings in one refusal, nearly all refused by the
// lattice).
#pragma once

#include "schemes/cooper/volume_facts.h"

#include <set>
#include <utility>
#include <vector>

namespace cooperage::cooper {

class SideParity {
 public:
  explicit SideParity(const VolumeFacts& facts);

  /// False when a face not in `caps` cannot be a side (cannot_be_side()),
  /// or when the rigid sides and the cap curves running along contradict
  /// each other; then side_lattice(facts, caps) is not ok. True says
  /// nothing more.
  bool can_agree(const std::set<int>& caps) const;

 private:
  struct Face {
    int id = 0;
    bool side = true;    ///< it may be a side (not cannot_be_side())
    bool rigid = false;  ///< a side whose own corners give its directions
    /// (curve index, parity of its lattice direction) per use.
    std::vector<std::pair<int, int>> uses;
  };
  std::vector<Face> faces_;
  int curves_ = 0;
};

}  // namespace cooperage::cooper
