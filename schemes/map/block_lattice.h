// Recovery of the structured boundary lattice of a mapped hexahedral block
// from its closed quad boundary mesh: the 8 block corners are the nodes with
// 3 incident quads, grid lines run straight through the valence-4 nodes, and
// each of the 6 faces is filled quad by quad from two of its grid lines.
#pragma once

#include "framework/mesh/mesh_db.h"

#include <string>
#include <vector>

namespace cooperage::map {

/// The boundary nodes of an (ni+1) x (nj+1) x (nk+1) block, as MeshDB node
/// indices at Grid3 positions (i fastest, then j, then k); -1 in the interior.
struct BlockLattice {
  bool ok = false;
  std::string why;  ///< why the lattice could not be recovered, when !ok
  int ni = 0, nj = 0, nk = 0;
  std::vector<int> node;
};

/// Recovers the block lattice of a closed all-quad boundary mesh (any
/// consistent or mixed orientation). Deterministic: (0,0,0) is the corner with
/// the smallest node index and i, j, k follow its neighbours in ascending node
/// index; the handedness is not fixed (the caller checks the Jacobian).
BlockLattice recover_block_lattice(const std::vector<mesh::Quad>& quads);

}  // namespace cooperage::map
