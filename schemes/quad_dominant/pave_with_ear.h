// Pave for a quad-dominant mesh (cooper's mixed elements): where the
// boundary has an odd number of nodes, no all-quad mesh exists, so one
// corner is cut off as a triangle (mesh2d::parity_ear) and the rest, one
// node fewer, is paved. Imprinted subcaps can be odd whatever the interval
// counts (Blacker 1996 sec. 5.3; bench/RESULTS.md, session 37), and a
// column of wedges there is better than no mesh.
#pragma once

#include "schemes/pave/pave_2d.h"

#include <array>
#include <optional>
#include <vector>

namespace cooperage::quad_dominant {

struct PavedWithEar {
  pave::QuadMesh2D mesh;                  ///< boundary nodes first, in the input order, as pave_2d
  std::optional<std::array<int, 3>> ear;  ///< the triangle cut off, counter-clockwise
};

/// pave::pave_2d(loops) when the boundary is even; else the ear and pave's
/// quads of the rest. Throws as pave_2d does when no corner makes an ear.
PavedWithEar pave_with_ear(const std::vector<std::vector<Eigen::Vector2d>>& loops);

}  // namespace cooperage::quad_dominant
