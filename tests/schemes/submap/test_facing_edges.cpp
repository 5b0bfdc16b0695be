// Facing curves keep a row of cells between them (schemes/submap/
// facing_edges.h): the C-shaped side of occt_bm2_ec_lever-A (issue 15),
// rebuilt from primitives: a 95 x 80 profile with an 80 x 60 notch from its
// left side, extruded. With the notch's curves at 14 intervals and the
// outer ones at 11 (the counts cooper's layers gave the lever), the loop
// balance holds but the lattice folds (the notch is longer than the face is
// wide): the new rows make that infeasible, and leave valid counts alone.
#include "framework/core/error.h"
#include "framework/geometry/occ/workbench.h"
#include "framework/intervals/solve.h"
#include "schemes/submap/facing_edges.h"
#include "schemes/submap/submap_plan.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace cooperage::submap {
namespace {

struct CFace {
  geom::Model model;
  int surface = 0;
};

CFace c_face() {
  occ::Workbench wb;
  wb.brick("b", {0, 0, 0}, {95, 10, 80});
  wb.brick("notch", {-1, -1, 10}, {81, 12, 60});
  wb.cut("part", {"b", "notch"});
  CFace out{wb.build_model(), 0};
  for (const auto& s : out.model.surfaces()) {
    if (std::abs(s.box.max.y()) < 1e-9 && std::abs(s.box.min.y()) < 1e-9) out.surface = s.id;
  }
  return out;
}

// The face's curves with goals at size 8.84 (the lever's D/40 scaled),
// hard counts for the curves along x: `notch` on the notch's two, `outer`
// on the outer two; the submap rows, and the facing rows when asked.
intervals::IntervalProblem problem(const CFace& f, int notch, int outer, bool facing) {
  intervals::IntervalProblem p;
  const SubmapPlan plan = plan_submap(f.model, f.surface, {});
  EXPECT_TRUE(plan.ok) << plan.why;
  for (const auto& u : plan.loops.front().uses) {
    const geom::Curve& c = f.model.curve(u.curve);
    const geom::Vec3 d = f.model.vertex(c.end_vertex).point - f.model.vertex(c.start_vertex).point;
    const bool along_x = std::abs(d.x()) > 1;
    const bool long_x = along_x && std::abs(d.x()) > 90;
    if (along_x) {
      p.add_curve(u.curve, c.length / 8.84, intervals::Firmness::Hard, long_x ? outer : notch);
    } else {
      p.add_curve(u.curve, c.length / 8.84);
    }
  }
  add_submap_constraints(f.surface, plan, p);
  if (facing) add_facing_edge_constraints(f.model, f.surface, plan.loops.front(), p);
  return p;
}

bool feasible(const intervals::IntervalProblem& p) {
  try {
    intervals::solve(p);
    return true;
  } catch (const MeshingError&) {
    return false;
  }
}

TEST(FacingEdges, ANotchLongerThanTheFaceIsWideIsInfeasible) {
  const CFace f = c_face();
  ASSERT_GT(f.surface, 0);
  EXPECT_TRUE(feasible(problem(f, 14, 11, false)));  // the balance alone accepts the fold
  EXPECT_FALSE(feasible(problem(f, 14, 11, true)));
  EXPECT_FALSE(feasible(problem(f, 11, 11, true)));  // no row of cells behind the notch
  EXPECT_TRUE(feasible(problem(f, 9, 11, true)));
  EXPECT_TRUE(feasible(problem(f, 10, 11, true)));
}

TEST(FacingEdges, ValidCountsAreUnchanged) {
  const CFace f = c_face();
  ASSERT_GT(f.surface, 0);
  const auto a = intervals::solve(problem(f, 9, 11, false));
  const auto b = intervals::solve(problem(f, 9, 11, true));
  EXPECT_EQ(a.intervals, b.intervals);
}

}  // namespace
}  // namespace cooperage::submap
