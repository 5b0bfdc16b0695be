// Untangling a projected subcap (Blacker 1996, sec. 6.1 projects each cap
// stack's mesh onto its other subcaps). Where a subcap's boundary differs
// in shape from its source's -- an imprinted line 0.04 from a hole's wall
// at one end and 0.1 at the other -- the projected interior folds, and
// smoothing that never lets a worst corner drop cannot undo the fold: every
// single move makes some corner worse first. Knupp's untangling objective
// (P. Knupp, "Hexahedral and tetrahedral mesh untangling", Eng. Comput. 17,
// 2001) can: per node it is the sum over the corners the node is part of of
// max(0, floor - corner area)^2, and as every corner area is linear in the
// node's position it is convex in that node alone. Value types only.
#pragma once

#include "framework/mesh/mesh_db.h"

#include <functional>
#include <vector>

namespace cooperage::cooper {

/// Moves the `movable` nodes of a quad (and triangle) mesh so that every
/// corner's area about `normal` reaches a floor: `fraction` of the same
/// corner's area in `source` (a fold-free mesh of the same faces), scaled
/// by the ratio of the two meshes' total signed areas. Node by node in index
/// order, each minimising its own convex objective (deterministic) by damped
/// Newton steps that count a corner within 1e-9 of its floor as on it, so
/// that a rigidly moved cap is untangled the same way (rounding alone once
/// moved nodes by a fifth of an element); every move followed by `project`
/// (onto the cap's surface; identity in a plane).
/// The fractions 1/4, 1/20 and 1/100 are tried in turn until no corner is
/// folded; then the movable nodes of faces with a corner sine below 0.3
/// move to raise the worst element around them (mesh::raise_worst_elements,
/// three passes). Bounded work: at most 200 minimisations per node, and the
/// search's own bounds. Kept only when the worst corner (its sine)
/// improves; returns whether it did.
/// \param[in,out] points  node positions, indexed by the faces
/// \param[in] source      the same faces' fold-free positions (the mesh projected)
/// \param[in] normal      the direction the faces are counter-clockwise about
bool untangle_cap(std::vector<mesh::Vec3>& points, const std::vector<mesh::Vec3>& source,
                  const std::vector<mesh::Quad>& quads, const std::vector<mesh::Tri>& tris,
                  const std::vector<char>& movable, const mesh::Vec3& normal,
                  const std::function<mesh::Vec3(const mesh::Vec3&)>& project);

}  // namespace cooperage::cooper
