// The volume between two consecutive cap levels (a slab) is cut into
// regions, each bounded by one outer cycle of side faces and the cycles of
// its holes: the topological equivalent of a complete layer of ribs
// (Blacker 1996, sec. 4: "all of the exterior ribs of the barrel progress a
// complete layer at a time"). Cycles are the side faces active in the slab
// joined by the curves they share there (stacked faces, Fig. 4, are one
// cycle). A cap joins the cycles it bounds on its material side (a cap's
// loops belong to one region); a cycle passing a level unchanged keeps its
// region. Plain data: testable without CAD.
#pragma once

#include "schemes/cooper/sweep_order.h"

#include <string>
#include <vector>

namespace cooperage::cooper {

struct Cycle {
  std::vector<int> faces;  ///< ascending
  bool outer = true;       ///< the volume lies inside it (else it bounds a hole)
};

struct Slab {
  double top = 0, bottom = 0;  ///< heights of the cap levels around it
  std::vector<Cycle> cycles;   ///< ascending by first face
  /// Regions: cycle indices, the outer cycle first, then holes ascending.
  std::vector<std::vector<int>> regions;
};

struct SlabRegions {
  bool ok = false;
  std::string why;
  std::vector<double> levels;  ///< distinct cap heights, descending
  std::vector<Slab> slabs;     ///< slab k lies between levels[k] and levels[k + 1]
  double tolerance = 0;        ///< heights closer than this are one level
  /// Per side face: lowest and highest level height of its runs along.
  std::map<int, std::pair<double, double>> span;
  /// Per side face: the volume lies inside its cycles (outer walls), from
  /// its first deciding cap contact. A slab's cycle takes its role from the
  /// caps bounding that slab (Cycle::outer), which may differ from this for
  /// a face that walls the volume in at one level and a hole at another.
  std::map<int, bool> outer_face;
};

SlabRegions slab_regions(const VolumeFacts& facts, const SideLattice& lattice,
                         const SweepOrder& order);

/// Index of the slab's region holding cycle `c`, or -1.
int region_of_cycle(const Slab& slab, int c);

}  // namespace cooperage::cooper
