// Edge directions of a submap face (ALGORITHMS.md sec. 1; Whiteley et al.
// 1996): every curve use gets one of +i, +j, -i, -j by walking its loop with
// the face on the left, d_next = (d_prev + t_k) mod 4, and the per-loop,
// per-axis interval balance the lattice needs. Value types only.
#pragma once

#include <array>
#include <map>
#include <vector>

#include "schemes/submap/classify.h"

namespace cooperage::submap {

/// Lattice directions in counter-clockwise order about the natural normal:
/// turning left (END, t = +1) adds 1.
enum Direction : int { kPlusI = 0, kPlusJ = 1, kMinusI = 2, kMinusJ = 3 };

/// "+i", "+j", "-i", "-j".
const char* direction_name(int d);
/// Unit lattice step of a direction: +i -> (1, 0), +j -> (0, 1), ...
std::array<int, 2> direction_step(int d);

/// Direction of every use of a loop. Corner k sits before use k (as in
/// scheme::loop_corners). The walk starts at the first END corner, whose
/// outgoing use gets direction `start` (corner 0 when the loop has no END);
/// then d_k = (d_{k-1} + t_k) mod 4.
/// \param[in] types  per corner, loop order
/// \param[in] start  direction of the first use after the start corner
std::vector<int> use_directions(const std::vector<VertexType>& types, int start = kPlusI);

/// A curve use with its direction.
struct DirectedUse {
  int curve = 0;
  int direction = kPlusI;
};

/// The interval balance of a loop on one axis: coefficient per curve
/// (+1 per use along + of the axis, -1 per use along -); the loop closes
/// when sum coeff * x = 0. Curves whose uses cancel (a seam walked up and
/// down) are left out. Index 0: the i axis, 1: the j axis.
std::array<std::map<int, int>, 2> loop_balance(const std::vector<DirectedUse>& uses);

/// Sum of the uses' curve ids along direction d (for the hole-fit rows).
std::map<int, int> along(const std::vector<DirectedUse>& uses, int d);

}  // namespace cooperage::submap
