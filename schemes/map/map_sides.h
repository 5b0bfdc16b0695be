// The logical rectangle of a mappable surface: four END corners, every other
// junction a SIDE, the loop's curve uses grouped into four logical sides
// (ALGORITHMS.md sec. 1; White et al. 1995). Decided from angles alone.
#pragma once

#include "framework/geometry/model.h"
#include "framework/intervals/interval_problem.h"

#include <array>
#include <string>
#include <vector>

namespace cooperage::map {

/// The result of analyse_map_surface().
struct MapSides {
  bool ok = false;
  std::string why;     ///< the reason, for a person, when !ok
  double score = 0.0;  ///< in (0, 1] when ok: 1 for a perfect rectangle
  /// Curve uses of logical side s, in loop order; side s runs from END
  /// corner s to END corner s+1 (mod 4), face on the left.
  std::array<std::vector<geom::CurveUse>, 4> sides;
  std::array<int, 4> corner_vertices{};  ///< model vertex at the start of side s
};

/// Can `surface_id` be mapped? Exactly one loop, exactly 4 END junctions and
/// every other junction a SIDE. The score is 1 minus a penalty from how far
/// END angles deviate from 90 degrees and SIDE angles from 180.
MapSides analyse_map_surface(const geom::Model& model, int surface_id);

/// Adds the map constraints of an analysed surface: side 0 = side 2 and
/// side 1 = side 3 (sums of curve intervals), labelled
/// "surface 7 (map): curves 1+2 = 5".
void add_map_constraints(int surface_id, const MapSides& sides,
                         intervals::IntervalProblem& problem);

/// "1+2" for a list of ids.
std::string join_ids(const std::vector<int>& ids, const char* separator = "+");

/// The curve ids of a logical side, in loop order.
std::vector<int> side_curves(const std::vector<geom::CurveUse>& side);

}  // namespace cooperage::map
