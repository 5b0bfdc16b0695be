// Untangling a lattice fill that folded at one corner: a blend across a
// steep boundary (a lug's conical underside on the wall it stands on: the
// cone's edges are one row of the wall's lattice, 50 degrees off level)
// can put an interior node on the wrong side of the boundary row next to
// it. Guarded smoothing cannot undo that: every move it tries is judged
// against a 0.2 floor that the neighbours of a fold do not reach. Here only
// the free nodes of inverted quads and their neighbours move, each to the
// candidate position that raises the smallest scaled Jacobian of its quads
// the most; everything else stays where the fill put it (a sweep's rows on
// its caps' levels).
#pragma once

#include "schemes/submap/smooth.h"

namespace cooperage::submap {

struct UntangleOptions {
  int sweeps = 30;      ///< passes over the nodes near poor quads
  double target = 0.2;  ///< quads below this scaled Jacobian are worked on
};

/// Moves free nodes near poor quads (scaled Jacobian below options.target
/// against the surface normal, inverted ones first among them) in place;
/// a node moves only to raise the smallest scaled Jacobian of its quads.
/// Deterministic. Returns the smallest scaled Jacobian over all quads
/// afterwards (> 0: nothing inverted).
/// \param[in,out] x        node positions
/// \param[in,out] normals  unit surface normal per node (updated for moved nodes)
/// \param[in] fixed        per node: true for nodes that must not move (boundary)
/// \param[in] quads        elements over x, counter-clockwise about the normal
/// \param[in] project      projection onto the surface
double untangle_quads(std::vector<Vec3>& x, std::vector<Vec3>& normals,
                      const std::vector<bool>& fixed, const std::vector<mesh::Quad>& quads,
                      const Projector& project, const UntangleOptions& options = {});

}  // namespace cooperage::submap
