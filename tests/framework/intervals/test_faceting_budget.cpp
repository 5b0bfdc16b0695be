// The faceting budget (issue 16, item 4) on models whose loss is known in
// closed form: a cylinder's loss is its polygon's segment area times its
// length; a rod at a coarse size gets the intervals that keep its polygon
// within the budget; a small hole in a large plate is not refined.
#include "framework/intervals/faceting_budget.h"

#include "framework/geometry/occ/workbench.h"
#include "framework/intervals/curve_sizing.h"
#include "framework/intervals/solve.h"
#include "framework/pipeline/interval_setup.h"
#include "schemes/builtin_schemes.h"
#include "selector/select_schemes.h"

#include <gtest/gtest.h>

#include <cmath>

namespace cooperage::intervals {
namespace {

/// Fraction of a circle's area a regular n-gon inscribed in it leaves out.
double polygon_shortfall(int n) { return 1.0 - n * std::sin(2.0 * M_PI / n) / (2.0 * M_PI); }

/// A rod of radius 5 and length 50.
geom::Model rod() {
  occ::Workbench bench;
  bench.cylinder("rod", {0, 0, 0}, {0, 0, 1}, 5.0, 50.0);
  return bench.build_model();
}

/// A radius-1 hole through a 100 x 100 x 10 plate.
geom::Model plate_with_hole() {
  occ::Workbench bench;
  bench.brick("plate", {0, 0, 0}, {100, 100, 10});
  bench.cylinder("hole", {50, 50, -1}, {0, 0, 1}, 1.0, 12.0);
  bench.cut("part", {"plate", "hole"});
  return bench.build_model();
}

std::map<int, TurningCurve> circles_at(const geom::Model& model, int n) {
  std::map<int, TurningCurve> out;
  for (const auto& c : model.curves()) {
    if (c.geometry->type() == geom::CurveType::Circle) out[c.id] = {2.0 * M_PI, n};
  }
  return out;
}

TEST(FacetingBudget, ACylindersLossIsItsPolygonsShortfallTimesItsLength) {
  const geom::Model model = rod();
  for (int n : {6, 12, 40}) {
    const FacetingLoss loss = faceting_loss(model, 1, circles_at(model, n));
    const double disc = M_PI * 25.0;
    EXPECT_NEAR(loss.volume, 50.0 * disc * polygon_shortfall(n), 1e-9 * disc * 50.0) << n;
    // n flat panels of width 2 r sin(pi / n) around a circumference 2 pi r.
    const double side = 2.0 * M_PI * 5.0 * 50.0;
    const double panels = n * 2.0 * 5.0 * std::sin(M_PI / n) * 50.0;
    EXPECT_NEAR(loss.area, side - panels, 1e-9 * side) << n;
  }
}

IntervalSolution solved(const geom::Model& model, double size, int dim) {
  scheme::Registry registry;
  register_builtin_schemes(registry);
  io::MeshSettings settings;
  settings.size = size;
  const auto plan = selector::planner()(model, registry, settings, dim);
  return solve(pipeline::build_interval_problem(model, registry, plan, settings));
}

TEST(FacetingBudget, ARodAtACoarseSizeKeepsItsVolume) {
  // Diameter 10 at size 20: the turning rule alone gives a hexagon, 17 %
  // of the volume short. The budget is half the default tolerance of 1 %.
  const geom::Model model = rod();
  ASSERT_GT(polygon_shortfall(6), 0.17);
  int least = 3;
  while (polygon_shortfall(least) > 0.005) ++least;  // 37
  for (int dim : {2, 3}) {
    const IntervalSolution sol = solved(model, 20.0, dim);
    int circles = 0;
    for (const auto& c : model.curves()) {
      if (c.geometry->type() != geom::CurveType::Circle) continue;
      ++circles;
      const int n = sol.intervals.at(c.id);
      EXPECT_LE(polygon_shortfall(n), 0.005) << "curve " << c.id << ", " << n << " intervals";
      EXPECT_LE(n, 1.3 * least) << "curve " << c.id << ": refined past the budget's need";
    }
    EXPECT_EQ(circles, 2);
  }
}

TEST(FacetingBudget, ALooserToleranceRefinesLess) {
  const geom::Model model = rod();
  std::map<int, TurningCurve> curves = circles_at(model, 6);
  FacetingOptions tight, loose;
  tight.fraction = 0.005;
  loose.fraction = 0.05;
  const auto a = faceting_minima(model, curves, tight);
  const auto b = faceting_minima(model, curves, loose);
  ASSERT_EQ(a.size(), 2u);
  ASSERT_EQ(b.size(), 2u);
  for (const auto& [id, n] : a) {
    EXPECT_GT(n, b.at(id));
    EXPECT_LE(polygon_shortfall(b.at(id)), 0.05);
  }
  FacetingOptions off;
  off.fraction = 0;
  EXPECT_TRUE(faceting_minima(model, curves, off).empty());
}

TEST(FacetingBudget, AHolesFacetsAddVolumeAndATubesCancel) {
  // A radius-1 hole through a 10-thick plate: n chords leave the hole's
  // polygon short, so the mesh holds 10 pi shortfall(n) more than the CAD.
  const geom::Model plate = plate_with_hole();
  const FacetingLoss hole = faceting_loss(plate, 1, circles_at(plate, 8));
  EXPECT_NEAR(hole.volume, -10.0 * M_PI * polygon_shortfall(8), 1e-9);
  EXPECT_GT(hole.area, 0.0);  // flat panels are shorter than arcs either way
  // A tube of radii 2 and 1 with 16 and 8 intervals: the outside loses
  // 4 pi shortfall(16), the bore gives back pi shortfall(8), per unit length.
  occ::Workbench tube_bench;
  tube_bench.cylinder("out", {0, 0, 0}, {0, 0, 1}, 2.0, 3.0);
  tube_bench.cylinder("in", {0, 0, -1}, {0, 0, 1}, 1.0, 5.0);
  tube_bench.cut("tube", {"out", "in"});
  const geom::Model tube = tube_bench.build_model();
  std::map<int, TurningCurve> curves;
  for (const auto& c : tube.curves()) {
    if (c.geometry->type() != geom::CurveType::Circle) continue;
    const bool outer = std::abs(c.length - 4.0 * M_PI) < 1e-6;
    curves[c.id] = {2.0 * M_PI, outer ? 16 : 8};
  }
  ASSERT_EQ(curves.size(), 4u);
  EXPECT_NEAR(faceting_loss(tube, 1, curves).volume,
              3.0 * M_PI * (4.0 * polygon_shortfall(16) - polygon_shortfall(8)), 1e-9);
}

TEST(FacetingBudget, ASmallHoleInALargePlateIsNotRefined) {
  // A radius-1 hole through a 100 x 100 x 10 plate at size 5: its hexagon
  // adds 10 * 1.09 to a volume of 1e5, far inside the budget.
  const geom::Model model = plate_with_hole();
  const auto sizing = curve_sizing(model, [](int) { return 5.0; });
  int circles = 0;
  for (const auto& c : model.curves()) {
    if (c.geometry->type() != geom::CurveType::Circle) continue;
    ++circles;
    EXPECT_EQ(sizing.at(c.id).min, 6) << "curve " << c.id;
  }
  EXPECT_EQ(circles, 2);
}

TEST(FacetingBudget, EveryRoundFaceAtItsFinestStopsTheSearch) {
  // A radius-5 rod with a cap of 60 degrees an interval cannot meet 0.5 %:
  // the search ends with every circle at the cap.
  const geom::Model model = rod();
  FacetingOptions coarse;
  coarse.min_turn_deg = 30.0;  // at most 12 intervals a circle
  const auto raised = faceting_minima(model, circles_at(model, 6), coarse);
  ASSERT_EQ(raised.size(), 2u);
  for (const auto& [id, n] : raised) EXPECT_EQ(n, 12);
}

}  // namespace
}  // namespace cooperage::intervals
