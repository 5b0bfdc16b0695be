// Curves that map and submap starve (issue 16, item 1). Curve sizing asks a
// curve beside a thin face or a small feature for small intervals; a mapped
// or submapped surface ties it to curves that ask few, and the interval
// program settles between them. Held at half its goal or less, the curve's
// intervals are twice as long as the feature allows, and the thin face gets
// slivers (real-cad gmsh_Kurbelwelle: a crescent 0.05 wide whose inner arc
// asks 19 intervals, held at 7 by a mapped cylinder tied to a submapped
// plane; its best triangles reach 0.14, paved free 0.22).
#pragma once

#include "framework/geometry/model.h"
#include "framework/intervals/solve.h"
#include "framework/io/job.h"
#include "framework/scheme/registry.h"
#include "selector/selection.h"

namespace cooperage::selector {

/// After a feasible solve (selection.intervals set): for each graded curve
/// (one with a size function) held at half its goal or less, and goal >= 4,
/// that is not on a narrow mapped face (whose rows resolve its width at any
/// count), the automatic map/submap choices on it that pave can take, except
/// narrow faces, are paved; the change is kept if the curve gets more
/// intervals and the graded curves' shares of their goals improve (leximin),
/// and then each paved choice gets its scheme back where the curve and the
/// shares do as well without. Kept changes are listed in
/// selection.relaxations and in the choices' reasons; selection.intervals
/// is the solution with them. At most 12 extra solves; deterministic.
void pave_where_curves_starve(const geom::Model& model, const scheme::Registry& registry,
                              const io::MeshSettings& settings, Selection& selection,
                              intervals::SolveMemo& memo);

}  // namespace cooperage::selector
