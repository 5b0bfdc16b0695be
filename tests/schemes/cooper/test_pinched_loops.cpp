// Subcaps whose loops touch at a node (schemes/cooper/pinched_loops.h) on
// hand-made loops, and the journal where they arise (issue 15, the journal
// campaign's case 1810: two bosses meeting at a corner on a block's top).
#include "support/hex_mesh_check.h"

#include "framework/io/journal_reader.h"
#include "framework/pipeline/build_geometry.h"
#include "framework/pipeline/mesher.h"
#include "schemes/builtin_schemes.h"
#include "schemes/cooper/pinched_loops.h"
#include "selector/select_schemes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <map>

namespace cooperage::cooper {
namespace {

using detail::point_in_loop;

double area(const std::vector<Vec2>& l) {
  double a = 0;
  for (size_t k = 0; k < l.size(); ++k) a += detail::cross(l[k], l[(k + 1) % l.size()]);
  return 0.5 * a;
}

// A 4 x 4 square with a 2 x 2 notch at its top left, whose inner corner
// (2, 2) is also the corner of a 1 x 1 square hole below and right of it.
TEST(PinchedLoops, AnOuterLoopAndAHoleThroughOneNodeBecomeOneLoop) {
  std::map<int, Vec2> xy = {{1, {0, 0}}, {2, {4, 0}}, {3, {4, 4}}, {4, {2, 4}}, {5, {2, 2}},
                            {6, {0, 2}}, {7, {3, 2}}, {8, {3, 1}}, {9, {2, 1}}};
  const std::vector<std::vector<int>> loops = {{1, 2, 3, 4, 5, 6}, {5, 7, 8, 9}};  // hole clockwise
  const UnpinchedLoops u = unpinch_loops(loops, xy);
  EXPECT_EQ(u.pinches, 1);
  ASSERT_EQ(u.points.size(), 1u);
  ASSERT_EQ(u.nodes.size(), 10u);
  EXPECT_EQ(std::count(u.nodes.begin(), u.nodes.end(), 5), 2);
  // The area is the outer loop's minus the hole's (the nudges are small).
  EXPECT_NEAR(area(u.points[0]), 12.0 - 1.0, 0.05);
  // Each pass of node 5 moved into the domain: inside the notched square,
  // outside the hole, and apart from the other pass.
  std::vector<int> outer_ids = loops[0], hole_ids = loops[1];
  std::vector<Vec2> passes;
  for (size_t k = 0; k < u.nodes.size(); ++k) {
    if (u.nodes[k] != 5) continue;
    const Vec2& p = u.points[0][k];
    passes.push_back(p);
    EXPECT_TRUE(point_in_loop(p, outer_ids, xy)) << p.transpose();
    EXPECT_FALSE(point_in_loop(p, hole_ids, xy)) << p.transpose();
    EXPECT_GT((p - xy.at(5)).norm(), 0.0);
    EXPECT_LT((p - xy.at(5)).norm(), 0.05);
  }
  ASSERT_EQ(passes.size(), 2u);
  EXPECT_GT((passes[0] - passes[1]).norm(), 0.0);
}

TEST(PinchedLoops, LoopsThatDoNotTouchAreKept) {
  std::map<int, Vec2> xy = {{1, {0, 0}}, {2, {4, 0}}, {3, {4, 4}}, {4, {0, 4}},
                            {5, {1, 1}}, {6, {1, 2}}, {7, {2, 2}}, {8, {2, 1}}};
  const UnpinchedLoops u = unpinch_loops({{1, 2, 3, 4}, {5, 6, 7, 8}}, xy);
  EXPECT_EQ(u.pinches, 0);
  ASSERT_EQ(u.points.size(), 2u);
  EXPECT_EQ(u.nodes, (std::vector<int>{1, 2, 3, 4, 5, 6, 7, 8}));
  for (size_t k = 0; k < 4; ++k) EXPECT_EQ(u.points[0][k], xy.at(static_cast<int>(k) + 1));
}

// The journal: plan and mesh all four volumes, all-hex and conformal, the
// exact volume (planar faces only), no poor element.
TEST(PinchedLoops, CornerTouchingBossesJournalMeshes) {
  const io::Job job =
      io::read_journal(std::string(COOPERAGE_SOURCE_DIR) +
                       "/tests/schemes/cooper/data/cooper_corner_touching_bosses.xml");
  ASSERT_TRUE(job.mesh.has_value());
  const geom::Model model = pipeline::build_geometry(job);
  ASSERT_EQ(model.volumes().size(), 4u);
  scheme::Registry registry;
  register_builtin_schemes(registry);
  const auto r = pipeline::mesh_model(model, *job.mesh, registry, selector::mesh_options());
  EXPECT_EQ(r.plan.volumes.at(1).scheme, "cooper");
  const testing::HexMeshSummary s = testing::check_hex_mesh(model, r.mesh);
  EXPECT_NEAR(s.volume, 52.875, 52.875 * 1e-9);
  EXPECT_GE(s.min_sj, 0.3);
  std::printf(
      "[pinched loops] cooper_corner_touching_bosses.xml: %zu hexes, min scaled Jacobian %.4f\n",
      s.hexes, s.min_sj);
}

}  // namespace
}  // namespace cooperage::cooper
