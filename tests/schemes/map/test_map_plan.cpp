// Map's applicable() returns its plan (the logical sides it found), and
// constrain() and mesh() use the plan they are handed instead of analysing
// the face again (issue 19 item 3: one path for plans).
#include "analytic_model.h"
#include "mesh_helpers.h"

#include "framework/core/error.h"
#include "schemes/map/map_plan.h"
#include "schemes/map/surface_map.h"
#include "schemes/map/volume_map.h"

#include <gtest/gtest.h>

namespace cooperage {
namespace {

TEST(SurfaceMapPlan, ApplicableReturnsTheSides) {
  const geom::Model model = testing::rectangle_model(4, 6);
  const auto a = map::make_surface_map()->applicable({model, 1, nullptr});
  ASSERT_TRUE(a.ok) << a.why;
  const auto* plan = dynamic_cast<const map::SurfaceMapPlan*>(a.plan.get());
  ASSERT_NE(plan, nullptr);
  EXPECT_EQ(plan->surface_id, 1);
  EXPECT_TRUE(plan->sides.ok);
  // The same sides analyse_map_surface() finds: four sides of one curve each.
  const map::MapSides direct = map::analyse_map_surface(model, 1);
  for (int s = 0; s < 4; ++s) {
    EXPECT_EQ(map::side_curves(plan->sides.sides[s]), map::side_curves(direct.sides[s]));
  }
}

TEST(SurfaceMapPlan, MeshAndConstrainUseTheCarriedPlan) {
  const geom::Model model = testing::rectangle_model(4, 6);
  const auto scheme = map::make_surface_map();
  const auto a = scheme->applicable({model, 1, nullptr});
  ASSERT_TRUE(a.ok);
  // A carried plan that says "no" must be believed: proof it is not recomputed.
  map::SurfaceMapPlan refused = *dynamic_cast<const map::SurfaceMapPlan*>(a.plan.get());
  refused.sides.ok = false;
  refused.sides.why = "carried plan marker";
  intervals::IntervalProblem problem;
  scheme->constrain({model, 1, nullptr, nullptr, &refused}, problem);
  EXPECT_TRUE(problem.constraints().empty());
  mesh::MeshDB db;
  testing::mesh_curves(model, db, 1.0);
  try {
    scheme->mesh({model, 1, &db, nullptr, &refused}, {});
    FAIL() << "the carried plan was ignored";
  } catch (const MeshingError& e) {
    EXPECT_NE(std::string(e.what()).find("carried plan marker"), std::string::npos) << e.what();
  }
  // A plan for another surface is not taken.
  map::SurfaceMapPlan other = refused;
  other.surface_id = 2;
  scheme->constrain({model, 1, nullptr, nullptr, &other}, problem);
  EXPECT_EQ(problem.constraints().size(), 2u);
}

TEST(VolumeMapPlan, ConstrainUsesTheCarriedFaces) {
  const geom::Model brick = testing::brick_model(2, 3, 4);
  const auto scheme = map::make_volume_map();
  const auto a = scheme->applicable({brick, 1, nullptr});
  ASSERT_TRUE(a.ok) << a.why;
  const auto* plan = dynamic_cast<const map::VolumeMapPlan*>(a.plan.get());
  ASSERT_NE(plan, nullptr);
  EXPECT_EQ(plan->faces.size(), 6u);
  intervals::IntervalProblem all;
  scheme->constrain({brick, 1, nullptr, nullptr, plan}, all);
  EXPECT_EQ(all.constraints().size(), 12u);  // 2 per face
  // Drop one face from the carried plan: its two constraints go with it.
  map::VolumeMapPlan five = *plan;
  five.faces.erase(five.faces.begin());
  intervals::IntervalProblem fewer;
  scheme->constrain({brick, 1, nullptr, nullptr, &five}, fewer);
  EXPECT_EQ(fewer.constraints().size(), 10u);
}

}  // namespace
}  // namespace cooperage
