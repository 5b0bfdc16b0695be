// Parts from the cooper paper (Blacker 1996) built from Workbench
// primitives, shared by the tests that need them.
#pragma once

#include "framework/geometry/occ/workbench.h"

#include <string>

namespace cooperage::testing {

/// Fig. 3a: a 4 x 4 x 2 block with a unit boss on top (a sweep along z) and
/// one on the +x face (along x), fused as shape `name`; volume 34. No
/// single sweep covers it.
inline void build_fig3a(occ::Workbench& bench, const std::string& name = "part") {
  bench.brick("block", {0, 0, 0}, {4, 4, 2});
  bench.brick("up", {1, 0.5, 2}, {1, 1, 1});
  bench.brick("out", {4, 2.5, 0.5}, {1, 1, 1});
  bench.fuse(name, {"block", "up", "out"});
}

}  // namespace cooperage::testing
