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

// A wall whose notch from the top ends in a V (a lug's conical underside
// cut by the wall: campaign seed 21 case 33): the V's sides run at 34
// degrees to the lattice axis they are drawn along, so the picture is not
// rectilinear; its aligned curves still face each other. The notch's
// floor must stay a row above the wall's bottom: a notch as deep in the
// lattice as the wall is high put two boundary nodes on one lattice point
// at mesh time, after the plan had accepted the counts.
TEST(FacingEdges, ANotchEndingInAVKeepsItsFloorAboveTheBottom) {
  occ::Workbench wb;
  wb.prism("wall",
           {{0, 0, 0},
            {50, 0, 0},
            {50, 0, 16},
            {32, 0, 16},
            {32, 0, 7},
            {29, 0, 5},
            {23, 0, 5},
            {20, 0, 7},
            {20, 0, 16},
            {0, 0, 16}},
           {}, {0, 1, 0});
  const geom::Model model = wb.build_model();
  int surface = 0;
  for (const auto& s : model.surfaces()) {
    if (std::abs(s.box.max.y()) < 1e-9 && std::abs(s.box.min.y()) < 1e-9) surface = s.id;
  }
  ASSERT_GT(surface, 0);
  const SubmapPlan plan = plan_submap(model, surface, {});
  ASSERT_TRUE(plan.ok) << plan.why;
  // Hard counts on the wall's two outer edges (`wall`) and on the notch's
  // right side (`notch`); the goals at size 2 elsewhere.
  const auto counts = [&](int wall, int notch, bool facing) {
    intervals::IntervalProblem p;
    for (const auto& u : plan.loops.front().uses) {
      const geom::Curve& c = model.curve(u.curve);
      const geom::Vec3 a = model.vertex(c.start_vertex).point;
      const geom::Vec3 b = model.vertex(c.end_vertex).point;
      const bool vertical = std::abs(a.x() - b.x()) < 1e-9;
      const bool outer = vertical && (a.x() < 1e-9 || a.x() > 50 - 1e-9);
      const bool notch_side = vertical && std::abs(a.x() - 32) < 1e-9;
      if (outer) {
        p.add_curve(c.id, c.length / 2, intervals::Firmness::Hard, wall);
      } else if (notch_side) {
        p.add_curve(c.id, c.length / 2, intervals::Firmness::Hard, notch);
      } else {
        p.add_curve(c.id, c.length / 2);
      }
    }
    add_submap_constraints(surface, plan, p);
    if (facing) add_facing_edge_constraints(model, surface, plan.loops.front(), p);
    return p;
  };
  EXPECT_TRUE(feasible(counts(3, 3, false)));  // the balance alone lets the floor sink
  EXPECT_FALSE(feasible(counts(3, 3, true)));
  EXPECT_FALSE(feasible(counts(3, 4, true)));
  EXPECT_TRUE(feasible(counts(4, 3, true)));
  EXPECT_TRUE(feasible(counts(8, 4, true)));
}

// A face that is two strips meeting along a short piece of one level: the
// lower strip's right edge comes down from that level where the upper
// strip's left edge goes up from it, 0.5 (or 6 degrees) further left. The
// face runs on both sides of the piece between their ends, so those ends
// must not share a lattice point: the counts along the bottom and along the
// lower strip's top (equal lengths but for that piece) must differ.
struct Strips {
  geom::Model model;
  int surface = 0;
  int bottom = 0;  // the lower strip's bottom curve
  int step = 0;    // the lower strip's top curve, left of the upper strip
};

// The face's curves with goals at size 2, hard counts on two of them (0:
// the goal alone).
intervals::IntervalProblem strips_problem(const Strips& f, int bottom, int step, bool facing) {
  intervals::IntervalProblem p;
  const SubmapPlan plan = plan_submap(f.model, f.surface, {});
  EXPECT_TRUE(plan.ok) << plan.why;
  for (const auto& u : plan.loops.front().uses) {
    const geom::Curve& c = f.model.curve(u.curve);
    if (u.curve == f.bottom && bottom > 0) {
      p.add_curve(u.curve, c.length / 2, intervals::Firmness::Hard, bottom);
    } else if (u.curve == f.step && step > 0) {
      p.add_curve(u.curve, c.length / 2, intervals::Firmness::Hard, step);
    } else {
      p.add_curve(u.curve, c.length / 2);
    }
  }
  add_submap_constraints(f.surface, plan, p);
  if (facing) add_facing_edge_constraints(f.model, f.surface, plan.loops.front(), p);
  return p;
}

// The curve of f's surface whose two ends satisfy `at`.
template <class At>
int curve_with_ends(const geom::Model& model, int surface, At at) {
  for (const auto& loop : model.surface(surface).loops) {
    for (const auto& use : loop.uses) {
      const geom::Curve& c = model.curve(use.curve);
      if (at(model.vertex(c.start_vertex).point, model.vertex(c.end_vertex).point)) return c.id;
    }
  }
  return 0;
}

TEST(FacingEdges, StripsMeetingAtOneLevelKeepTheirEndsApartOnAPlane) {
  occ::Workbench wb;
  wb.prism("z",
           {{0, 0, 0},
            {5, 0, 0},
            {5, 0, 5},
            {10, 0, 5},
            {10, 0, 10},
            {4.5, 0, 10},
            {4.5, 0, 5},
            {0, 0, 5}},
           {}, {0, 1, 0});
  Strips f{wb.build_model()};
  for (const auto& s : f.model.surfaces()) {
    if (std::abs(s.box.max.y()) < 1e-9 && std::abs(s.box.min.y()) < 1e-9) f.surface = s.id;
  }
  ASSERT_GT(f.surface, 0);
  const auto level = [](double z) {
    return [z](const geom::Vec3& a, const geom::Vec3& b) {
      return std::abs(a.z() - z) < 1e-9 && std::abs(b.z() - z) < 1e-9 &&
             std::min(a.x(), b.x()) < 1e-9;
    };
  };
  f.bottom = curve_with_ends(f.model, f.surface, level(0));
  f.step = curve_with_ends(f.model, f.surface, level(5));
  ASSERT_GT(f.bottom, 0);
  ASSERT_GT(f.step, 0);
  EXPECT_TRUE(feasible(strips_problem(f, 2, 2, false)));  // the balance alone lets them meet
  EXPECT_FALSE(feasible(strips_problem(f, 2, 2, true)));
  EXPECT_TRUE(feasible(strips_problem(f, 3, 2, true)));
  EXPECT_FALSE(feasible(strips_problem(f, 2, 3, true)));  // the ends crossed over
}

// The same on a cylinder (radius 5): the strips are a tube's quarter from 0
// to 90 degrees under z = 5 and from 84 to 180 degrees above it; its outer
// face's parameters, unwrapped, are the picture.
TEST(FacingEdges, StripsMeetingAtOneLevelKeepTheirEndsApartOnACylinder) {
  occ::Workbench wb;
  const std::vector<geom::Vec3> lower = {{3, 0, 0}, {5, 0, 0}, {5, 0, 5}, {3, 0, 5}};
  const std::vector<geom::Vec3> upper = {{3, 0, 5}, {5, 0, 5}, {5, 0, 10}, {3, 0, 10}};
  wb.revolve("lower", lower, {0, 0, 0}, {0, 0, 1}, 90);
  wb.revolve("upper", upper, {0, 0, 0}, {0, 0, 1}, 96);
  wb.rotate("upper", {0, 0, 0}, {0, 0, 1}, 84);
  wb.fuse("tube", {"lower", "upper"});
  Strips f{wb.build_model()};
  for (const auto& s : f.model.surfaces()) {
    if (s.geometry && s.geometry->type() == geom::SurfaceType::Cylinder && s.box.max.y() > 4.9)
      f.surface = s.id;
  }
  ASSERT_GT(f.surface, 0);
  const auto level = [](double z) {
    return [z](const geom::Vec3& a, const geom::Vec3& b) {
      const auto at_start = [](const geom::Vec3& p) { return std::abs(p.y()) < 1e-9 && p.x() > 0; };
      return std::abs(a.z() - z) < 1e-9 && std::abs(b.z() - z) < 1e-9 &&
             (at_start(a) || at_start(b));
    };
  };
  f.bottom = curve_with_ends(f.model, f.surface, level(0));
  f.step = curve_with_ends(f.model, f.surface, level(5));
  ASSERT_GT(f.bottom, 0);
  ASSERT_GT(f.step, 0);
  // Lengths 7.85 and 7.33 at size 2: by their goals alone both get 4
  // intervals, which puts the ends together. Off a plane the rows are
  // preferences: kept where the counts allow, and dropped (the face then
  // fails at mesh time, as without them) where they do not.
  const auto apart = [&](bool facing) {
    const intervals::IntervalSolution s = intervals::solve(strips_problem(f, 0, 0, facing));
    return s.intervals.at(f.bottom) - s.intervals.at(f.step);
  };
  EXPECT_EQ(apart(false), 0);
  EXPECT_GE(apart(true), 1);
  EXPECT_TRUE(feasible(strips_problem(f, 4, 4, true)));
}

}  // namespace
}  // namespace cooperage::submap
