// After split_poor_quads, the quad a sharp corner made poor is two triangles,
// and the one away from the corner can be thin: its interior node was placed
// for a quad. Moving the free nodes of the triangles (and only them) so the
// worst element around each gets better lifts those triangles without
// touching the rest of the mesh or its topology.
#pragma once

#include "framework/mesh/mesh_db.h"
#include "framework/mesh/split_poor_quads.h"

#include <functional>
#include <vector>

namespace cooperage::mesh {

/// Moves every node of `tris` for which `movable` is true to raise the
/// smallest quality of the quads and triangles around it, never lowering it
/// and never taking a quad below `quad_floor` (the quality the split kept
/// quads at) or below its own quality if that was lower.
/// Quality: min_corner_sine about each element's normal at the start
/// (triangles scaled by 2/sqrt 3, so an equilateral triangle and a square
/// both score 1). A compass search along the directions to the node's
/// neighbours (so a rigidly moved mesh moves the same way), each trial
/// position passed through `project` (onto the surface; identity in a plane).
/// Nodes in ascending order, `passes` times; deterministic.
void improve_split_nodes(std::vector<Vec3>& points, const std::vector<Quad>& quads,
                         const std::vector<Tri>& tris, const std::vector<bool>& movable,
                         const std::function<Vec3(const Vec3&)>& project, double quad_floor,
                         int passes = 3);

/// The search of improve_split_nodes for any `targets` (distinct node
/// indices, ascending): each moves, `passes` times, to raise the smallest
/// quality of the elements around it, no quad going below `quad_floor` (or
/// its own quality if lower). Deterministic.
void raise_worst_elements(std::vector<Vec3>& points, const std::vector<Quad>& quads,
                          const std::vector<Tri>& tris, const std::vector<int>& targets,
                          const std::function<Vec3(const Vec3&)>& project, double quad_floor,
                          int passes);

/// A quad mesh made quad-dominant: split_poor_quads(points, quads,
/// min_quality), then improve_split_nodes with the same floor. `points` are
/// moved in place; the elements are returned.
QuadDominant make_quad_dominant(std::vector<Vec3>& points, const std::vector<Quad>& quads,
                                const std::vector<bool>& movable,
                                const std::function<Vec3(const Vec3&)>& project,
                                double min_quality);

}  // namespace cooperage::mesh
