// The parts issue 15 lists as "must mesh", built from journal primitives
// (occ::Workbench, the journal's geometry operations), shared by the
// must-mesh and the plan/mesh parity tests. Every part is one shape named
// "part" (or, webcut, its pieces).
#pragma once

#include "framework/geometry/occ/workbench.h"

#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace cooperage::cooper::parts {

using geom::Vec3;
using Build = std::function<void(occ::Workbench&)>;

inline constexpr double kPi = 3.14159265358979323846;

// A 10 x 4 x 2 plate with three round through holes, as "plate" (not on
// the must-mesh list: one-to-one, shared by the cooper and threads tests).
inline void plate_three_round_holes(occ::Workbench& wb) {
  wb.brick("b", {0, 0, 0}, {10, 4, 2});
  wb.cylinder("h1", {2.5, 2, 0}, {0, 0, 1}, 0.6, 2);
  wb.cylinder("h2", {5, 2, 0}, {0, 0, 1}, 0.6, 2);
  wb.cylinder("h3", {7.5, 2, 0}, {0, 0, 1}, 0.6, 2);
  wb.cut("plate", {"b", "h1", "h2", "h3"});
}

// A 4 x 4 x 2 block with a round blind hole from the top, 1.2 deep.
inline void blind_hole(occ::Workbench& wb) {
  wb.brick("b", {0, 0, 0}, {4, 4, 2});
  wb.cylinder("h", {2, 2, 0.8}, {0, 0, 1}, 0.75, 2);
  wb.cut("part", {"b", "h"});
}

// Blind holes from the top (1.2 deep) and the bottom (0.5 deep), beside
// each other.
inline void blind_holes_both_ends(occ::Workbench& wb) {
  wb.brick("b", {0, 0, 0}, {5, 4, 2});
  wb.cylinder("h", {1.5, 2, 0.8}, {0, 0, 1}, 0.6, 2);
  wb.cylinder("g", {3.5, 2, -1}, {0, 0, 1}, 0.5, 1.5);
  wb.cut("part", {"b", "h", "g"});
}

// The same on one axis, of different radii: the bottom hole's footprint
// lies inside the top hole's floor.
inline void blind_holes_coaxial(occ::Workbench& wb) {
  wb.brick("b", {0, 0, 0}, {4, 4, 2});
  wb.cylinder("h", {2, 2, 1.2}, {0, 0, 1}, 1.0, 2);
  wb.cylinder("g", {2, 2, -1}, {0, 0, 1}, 0.5, 1.6);
  wb.cut("part", {"b", "h", "g"});
}

// Blind holes from both ends of one radius whose axes a CAD model put
// 0.002 apart (0.03 % of the block; occt_bm2_ec_lever-A has such a pair,
// 0.055 mm apart): their floors' rims project onto each other within a
// hair, so they need equal interval counts to seam.
inline void blind_holes_offset_axes(occ::Workbench& wb) {
  wb.brick("b", {0, 0, 0}, {4, 4, 2});
  wb.cylinder("h", {2, 2, 1.4}, {0, 0, 1}, 0.75, 1);
  wb.cylinder("g", {2, 2.002, -0.4}, {0, 0, 1}, 0.75, 1);
  wb.cut("part", {"b", "h", "g"});
}

// Two overlapping blind holes from the bottom, 0.93 and 0.48 deep (plan =>
// mesh campaign seed 3 case 45, scaled by 0.1): the shallow hole's wall,
// outside the deep one, crosses its own seam 0.005 from where the walls
// meet. The cut left that sliver of wall as a face of its own, its rims
// graded the ring round the deep hole, and the sweep's ribs there twisted
// by 66 degrees into inverted hexes at every size.
inline void overlapping_blind_holes(occ::Workbench& wb) {
  wb.brick("b", {0, 0, 0}, {2.403, 5.445, 2.043});
  wb.cylinder("deep", {1.262, 1.212, -2.043}, {0, 0, 1}, 0.537, 2.972);
  wb.cylinder("shallow", {1.019, 1.744, -2.043}, {0, 0, 1}, 0.348, 2.524);
  wb.cut("part", {"b", "deep", "shallow"});
}

// Two prongs standing on a plate with a hole between them (the fork of
// occt_bm2_ec_lever-A): the prongs' walls at y = 0 and y = 2 are one face
// each with the plate's, so both prongs are one barrel, whose lower
// (virtual) cap is two separate regions.
inline void fork_over_plate(occ::Workbench& wb) {
  wb.brick("base", {0, 0, 0}, {4, 2, 1});
  wb.brick("left", {0, 0, 1}, {1.5, 2, 1});
  wb.brick("right", {2.5, 0, 1}, {1.5, 2, 1});
  wb.fuse("solid", {"base", "left", "right"});
  wb.cylinder("hole", {2, 1, -1}, {0, 0, 1}, 0.3, 3);
  wb.cut("part", {"solid", "hole"});
}

// A 4 x 3 x 2 block with a 2 x 1 x 1 rectangular pocket.
inline void pocket(occ::Workbench& wb) {
  wb.brick("b", {0, 0, 0}, {4, 3, 2});
  wb.brick("p", {1, 1, 1}, {2, 1, 2});
  wb.cut("part", {"b", "p"});
}

// Three diameters along z, an axial bore through all.
inline void stepped_shaft(occ::Workbench& wb) {
  wb.cylinder("a", {0, 0, 0}, {0, 0, 1}, 2, 1);
  wb.cylinder("b", {0, 0, 1}, {0, 0, 1}, 1.5, 1.5);
  wb.cylinder("c", {0, 0, 2.5}, {0, 0, 1}, 1, 1);
  wb.cylinder("bore", {0, 0, -1}, {0, 0, 1}, 0.5, 6);
  wb.fuse("f", {"a", "b", "c"});
  wb.cut("part", {"f", "bore"});
}

// A flange, a hub on it, a bore through both.
inline void flanged_hub(occ::Workbench& wb) {
  wb.cylinder("flange", {0, 0, 0}, {0, 0, 1}, 3, 0.75);
  wb.cylinder("hub", {0, 0, 0.75}, {0, 0, 1}, 1.25, 1.5);
  wb.cylinder("bore", {0, 0, -1}, {0, 0, 1}, 0.6, 4);
  wb.fuse("f", {"flange", "hub"});
  wb.cut("part", {"f", "bore"});
}

inline void flanged_hub_webcut(occ::Workbench& wb) {
  flanged_hub(wb);
  wb.webcut("part", {0, 0, 0.75}, {0, 0, 1});
}

// The paper's Fig. 1 style part: an 8 x 5 x 2 block, bosses of two heights
// on top, a foot below, a through hole, a blind hole from each end.
inline void fig1_part(occ::Workbench& wb) {
  wb.brick("b", {0, 0, 0}, {8, 5, 2});
  wb.brick("tall", {0.75, 0.75, 2}, {1.5, 1.5, 1.5});
  wb.cylinder("short", {6.5, 1.5, 2}, {0, 0, 1}, 0.75, 0.75);
  wb.brick("foot", {3.5, 2.75, -1}, {2, 1.5, 1});
  wb.fuse("f", {"b", "tall", "short", "foot"});
  wb.cylinder("through", {4, 1.25, -1}, {0, 0, 1}, 0.5, 4);
  wb.cylinder("top", {1.5, 3.75, 1}, {0, 0, 1}, 0.6, 2);
  wb.cylinder("bottom", {6.5, 3.75, -1}, {0, 0, 1}, 0.5, 1.75);
  wb.cut("part", {"f", "through", "top", "bottom"});
}

// A boss whose footprint lies inside a larger foot on the other end.
inline void boss_over_larger_foot(occ::Workbench& wb) {
  wb.brick("b", {0, 0, 0}, {6, 4, 2});
  wb.cylinder("boss", {3, 2, 2}, {0, 0, 1}, 0.75, 1);
  wb.brick("foot", {1.5, 0.75, -1}, {3, 2.5, 1});
  wb.fuse("part", {"b", "boss", "foot"});
}

// A round boss partly over a square foot, scaled by `k` (k = 1: radius 1,
// square 2 x 2 shifted by 0.3 from the boss's centre).
inline Build round_over_square(double k) {
  return [k](occ::Workbench& wb) {
    wb.brick("b", {0, 0, 0}, {6, 4, 2});
    wb.cylinder("boss", {2.5, 2, 2}, {0, 0, 1}, k, 1);
    wb.brick("foot", {2.5 + 0.3 * k, 2 - k, -1}, {2 * k, 2 * k, 1});
    wb.fuse("part", {"b", "boss", "foot"});
  };
}

// The mirror: a square boss partly over a round foot.
inline Build square_over_round(double k) {
  return [k](occ::Workbench& wb) {
    wb.brick("b", {0, 0, 0}, {6, 4, 2});
    wb.brick("boss", {2.5 + 0.3 * k, 2 - k, 2}, {2 * k, 2 * k, 1});
    wb.cylinder("foot", {2.5, 2, -1}, {0, 0, 1}, k, 1);
    wb.fuse("part", {"b", "boss", "foot"});
  };
}

// A through hole with a countersink: a cone over a cylinder.
inline void countersunk_hole(occ::Workbench& wb) {
  wb.brick("b", {0, 0, 0}, {4, 4, 2});
  wb.cylinder("h", {2, 2, -1}, {0, 0, 1}, 0.5, 4);
  wb.cone("k", {2, 2, 1.5}, {0, 0, 1}, 0.5, 1.0, 0.5);
  wb.cut("part", {"b", "h", "k"});
}

// A 6 x 4 block whose top is inclined by 20 degrees, a boss standing on it
// (along the top's normal) and a foot below.
inline void inclined_top(occ::Workbench& wb) {
  wb.brick("b", {0, 0, 0}, {6, 4, 5});
  wb.brick("cutter", {-1, -1, 2.5}, {8, 6, 6});
  wb.rotate("cutter", {0, 0, 2.5}, {0, 1, 0}, -20);
  wb.cut("body", {"b", "cutter"});
  const double a = 20 * kPi / 180;
  const Vec3 n(-std::sin(a), 0, std::cos(a));  // the top's normal
  const Vec3 on_top = Vec3(2, 2, 2.5 + 2 * std::tan(a));
  wb.cylinder("boss", on_top - 0.2 * n, n, 0.75, 1.2);
  wb.brick("foot", {3.5, 1, -1}, {1.5, 2, 1});
  wb.fuse("part", {"body", "boss", "foot"});
}

// A 90-degree elbow (a 2 x 2 section revolved about z) with a round boss on
// its end face at angle 90.
inline void elbow_with_boss(occ::Workbench& wb) {
  wb.revolve("elbow", {{3, 0, 0}, {5, 0, 0}, {5, 0, 2}, {3, 0, 2}}, {0, 0, 0}, {0, 0, 1}, 90);
  wb.cylinder("boss", {0.2, 4, 1}, {-1, 0, 0}, 0.6, 1.2);
  wb.fuse("part", {"elbow", "boss"});
}

// From the plan => mesh campaign (seed 9 case 129): a block with a through
// hole (radius 12.18) that cuts the edge of a wide low boss on the top,
// and two smaller bosses beside it. Not in all(): swept along -z, as
// planned, the first hex of the wide boss's barrel inverts at size 5.965
// and at half and a quarter of it; along +z it meshes at 5.965 (worst hex
// 0.49). (Seed 4 case 157 was this part until a ring's layer preference,
// barrel_constraints.h, meshed it the way it was planned.)
inline void bosses_over_a_through_hole(occ::Workbench& wb) {
  wb.brick("block", {0, 0, 0}, {53.81, 58.47, 18.18});
  wb.cylinder("small", {20.31, 13.64, 18.18}, {0, 0, 1}, 5.58, 11.67);
  wb.cylinder("hole", {43.72, 17.36, -18.18}, {0, 0, 1}, 12.18, 54.54);
  wb.cylinder("wide", {24.5, 21.61, 18.18}, {0, 0, 1}, 12.51, 3.8);
  wb.cylinder("other", {45.32, 38.42, 18.18}, {0, 0, 1}, 5.38, 6.24);
  wb.fuse("body", {"block", "small", "wide", "other"});
  wb.cut("part", {"body", "hole"});
}

/// Every part with a name, for loops over them.
inline std::vector<std::pair<std::string, Build>> all() {
  return {{"blind_hole", blind_hole},
          {"blind_holes_both_ends", blind_holes_both_ends},
          {"blind_holes_coaxial", blind_holes_coaxial},
          {"blind_holes_offset_axes", blind_holes_offset_axes},
          {"overlapping_blind_holes", overlapping_blind_holes},
          {"fork_over_plate", fork_over_plate},
          {"pocket", pocket},
          {"stepped_shaft", stepped_shaft},
          {"flanged_hub", flanged_hub},
          {"flanged_hub_webcut", flanged_hub_webcut},
          {"fig1_part", fig1_part},
          {"boss_over_larger_foot", boss_over_larger_foot},
          {"round_over_square_0.8", round_over_square(0.8)},
          {"round_over_square_1.0", round_over_square(1.0)},
          {"round_over_square_1.2", round_over_square(1.2)},
          {"square_over_round_0.8", square_over_round(0.8)},
          {"square_over_round_1.0", square_over_round(1.0)},
          {"square_over_round_1.2", square_over_round(1.2)},
          {"countersunk_hole", countersunk_hole},
          {"inclined_top", inclined_top},
          {"elbow_with_boss", elbow_with_boss}};
}

}  // namespace cooperage::cooper::parts
