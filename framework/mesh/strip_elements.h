// One row of elements across a strip: a face that runs between two sharp
// tips and is thinner than its elements (a thread's flank on a bottle's
// neck, a sliver left by a fillet). Paving fronts collide across such a
// face and triangles inside it are needles, but its two boundary chains
// face each other node for node: quads between them keep the scaled
// Jacobian of their corners (near right angles however thin the strip),
// a triangle closes each tip, and a triangle takes up any node one chain
// has more than the other. No node is added.
#pragma once

#include "framework/mesh/mesh_db.h"

#include <optional>
#include <vector>

namespace cooperage::mesh {

/// Elements indexed by position in the ring.
struct StripElements {
  std::vector<Quad> quads;
  std::vector<Tri> tris;
};

/// The row of elements of the loop `ring` (positions, in loop order)
/// between its tips at positions tip0 and tip1: chain a runs forward from
/// tip0 to tip1, chain b backward. Nodes pair by arc-length fraction along
/// their chains (a zipper: each step advances both chains with a quad, or
/// the one that lags with a triangle, whichever keeps the fractions
/// closest; ties take the quad). Elements run in loop order, so they turn
/// like the loop. Nullopt when a chain has fewer than two edges.
std::optional<StripElements> strip_elements(const std::vector<Vec3>& ring, size_t tip0,
                                            size_t tip1);

}  // namespace cooperage::mesh
