// The plan's steps on hand-made facts, without CAD (issue 15, deliverable
// 8): side lattice, sweep order, slabs and regions, the barrel tree, cut
// caps and the interval rows of a cube, a block with a boss, a block with
// a blind pocket, the classic stepped L (Fig. 8) and appendages whose
// footprints overlap.
#include "polyhedron_facts.h"

#include "schemes/cooper/barrel_constraints.h"
#include "schemes/cooper/barrel_tree.h"
#include "schemes/cooper/cap_candidates.h"
#include "schemes/cooper/cap_roles.h"
#include "schemes/cooper/coincident_curves.h"
#include "schemes/cooper/plan_volume.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

namespace cooperage::cooper {
namespace {

using facts_test::cube;
using facts_test::oriented;
using facts_test::pocket;
using facts_test::PolyFace;
using facts_test::rect_xy;
using facts_test::walls;
using geom::Vec3;

const Vec3 kUp(0, 0, 1), kDown(0, 0, -1);

// A 4 x 4 x 2 block with a 1 x 1 x 1 boss on top.
std::vector<PolyFace> boss_on_block() {
  std::vector<PolyFace> f = walls(0, 0, 4, 4, 0, 2);
  f.push_back({oriented(rect_xy(0, 0, 4, 4, 0), kDown)});
  f.push_back({oriented(rect_xy(0, 0, 4, 4, 2), kUp),
               oriented(rect_xy(1.5, 1.5, 2.5, 2.5, 2), kUp, false)});
  for (const PolyFace& w : walls(1.5, 1.5, 2.5, 2.5, 2, 3)) f.push_back(w);
  f.push_back({oriented(rect_xy(1.5, 1.5, 2.5, 2.5, 3), kUp)});
  return f;
}

// The classic stepped L: a 4 x 4 x 1 block, a 4 x 2 x 1 step on its front
// half; the side walls touch the step top, the shoulder and the bottom.
std::vector<PolyFace> stepped_l() {
  std::vector<PolyFace> f;
  f.push_back({oriented(rect_xy(0, 0, 4, 4, 0), kDown)});
  f.push_back({oriented({{0, 0, 0}, {4, 0, 0}, {4, 0, 2}, {0, 0, 2}}, Vec3(0, -1, 0))});  // front
  f.push_back({oriented({{0, 4, 0}, {4, 4, 0}, {4, 4, 1}, {0, 4, 1}}, Vec3(0, 1, 0))});   // back
  for (double x : {0.0, 4.0}) {
    f.push_back({oriented({{x, 0, 0}, {x, 4, 0}, {x, 4, 1}, {x, 2, 1}, {x, 2, 2}, {x, 0, 2}},
                          Vec3(x > 0 ? 1 : -1, 0, 0))});
  }
  f.push_back({oriented(rect_xy(0, 2, 4, 4, 1), kUp)});  // shoulder
  f.push_back(
      {oriented({{0, 2, 1}, {4, 2, 1}, {4, 2, 2}, {0, 2, 2}}, Vec3(0, 1, 0))});  // step back
  f.push_back({oriented(rect_xy(0, 0, 4, 2, 2), kUp)});                          // step top
  return f;
}

// The ids of the faces facing z.
std::set<int> z_caps(const VolumeFacts& facts) { return caps_facing(facts, kUp); }

struct Steps {
  SideLattice lattice;
  SweepOrder order;
  SlabRegions slabs;
  BarrelTree tree;
};

Steps run_steps(const VolumeFacts& facts, const std::set<int>& caps, const OrderAnchor& anchor) {
  Steps s;
  s.lattice = side_lattice(facts, caps);
  EXPECT_TRUE(s.lattice.ok) << s.lattice.why;
  if (!s.lattice.ok) return s;
  s.order = sweep_order(facts, s.lattice, anchor);
  EXPECT_TRUE(s.order.ok) << s.order.why;
  if (!s.order.ok) return s;
  s.slabs = slab_regions(facts, s.lattice, s.order);
  EXPECT_TRUE(s.slabs.ok) << s.slabs.why;
  if (!s.slabs.ok) return s;
  s.tree = form_barrel_tree(facts, s.lattice, s.order, s.slabs);
  EXPECT_TRUE(s.tree.ok) << s.tree.why;
  return s;
}

OrderAnchor down() {
  OrderAnchor a;
  a.down = kDown;
  return a;
}

TEST(PlanSteps, CubeIsOneBarrelOfTwoLevels) {
  const VolumeFacts facts = facts_test::polyhedron_facts(cube());
  ASSERT_EQ(facts.faces.size(), 6u);
  ASSERT_EQ(facts.curves.size(), 12u);
  const Steps s = run_steps(facts, z_caps(facts), down());
  // The cap curves run along, the vertical edges between: two levels.
  EXPECT_EQ(s.lattice.sides.size(), 4u);
  EXPECT_EQ(s.lattice.along.size(), 8u);
  std::set<int> classes;
  for (const auto& [v, c] : s.lattice.vertex_class) classes.insert(c);
  EXPECT_EQ(classes.size(), 2u);
  EXPECT_EQ(s.lattice.chains.size(), 8u);  // each wall: its two vertical edges
  for (const CapContact& k : s.lattice.contacts) EXPECT_TRUE(k.convex);
  // Down from the top: the top is the upper cap, every chain runs down.
  for (const auto& [cap, upper] : s.order.upper)
    EXPECT_EQ(upper, facts.face(cap)->normal.z() > 0) << cap;
  EXPECT_EQ(s.slabs.slabs.size(), 1u);
  ASSERT_EQ(s.tree.barrels.size(), 1u);
  EXPECT_EQ(s.tree.barrels[0].sides.size(), 4u);
  EXPECT_TRUE(s.tree.interfaces.empty());
  // Either sign of the axis gives the mirrored order.
  OrderAnchor up;
  up.down = kUp;
  const SweepOrder o = sweep_order(facts, s.lattice, up);
  ASSERT_TRUE(o.ok) << o.why;
  for (const auto& [cap, upper] : o.upper) EXPECT_EQ(upper, facts.face(cap)->normal.z() < 0) << cap;
}

TEST(PlanSteps, ABossEndsItsBarrelOnTheShoulder) {
  const VolumeFacts facts = facts_test::polyhedron_facts(boss_on_block());
  const Steps s = run_steps(facts, z_caps(facts), down());
  ASSERT_EQ(s.tree.barrels.size(), 2u);
  // The boss walls meet the shoulder re-entrantly.
  int reentrant = 0;
  for (const CapContact& k : s.lattice.contacts) reentrant += k.convex ? 0 : 1;
  EXPECT_EQ(reentrant, 4);
  // Barrel 1: the boss, down to a virtual cap; barrel 2: shoulder + that
  // virtual cap, down to the bottom.
  const BarrelNode& boss = s.tree.barrels[0];
  const BarrelNode& block = s.tree.barrels[1];
  EXPECT_EQ(boss.sides.size(), 4u);
  ASSERT_EQ(boss.lower.size(), 1u);
  EXPECT_EQ(boss.lower[0].cap, 0);
  ASSERT_EQ(block.upper.size(), 2u);
  EXPECT_NE(block.upper[0].cap, 0);  // the shoulder
  EXPECT_GE(block.upper[1].interface, 0);
  ASSERT_EQ(s.tree.interfaces.size(), 1u);
  EXPECT_EQ(s.tree.interfaces[0].above, 0);
  EXPECT_EQ(s.tree.interfaces[0].below, 1);
  // Constraints: the block's and the boss's layers each at least one; the
  // four boss chains equal, the four block chains equal.
  const auto rows = barrel_constraints(facts, s.lattice, s.order, s.tree, {}, "t");
  int at_least = 0, equal = 0;
  for (const IntervalRow& r : rows) {
    if (r.sense == intervals::Sense::GreaterEqual) {
      ++at_least;
      EXPECT_EQ(r.rhs, 1);
    }
    if (r.sense == intervals::Sense::Equal && !r.even) ++equal;
  }
  EXPECT_EQ(at_least, 2);
  EXPECT_GE(equal, 6);  // 3 + 3 parallel chains tied to the first of each barrel
  // Nothing projects into the boss top or the shoulder.
  // One container: two calls would give iterators into two temporaries.
  const auto z = z_caps(facts);
  std::vector<int> caps(z.begin(), z.end());
  const auto cut = cut_caps(facts, caps, kDown, 5e-3);
  EXPECT_EQ(cut.size(), 1u);  // the bottom: the boss's footprint lies inside it
}

// A boss overhanging its 4 x 4 block far (issue 15, campaign cases 8110 and
// 8556): the block's edge y = 4 crosses the boss top's footprint, so
// imprinting cuts the top. Only the caps matter to the footprint test. The
// cut is 0.5 deep (0.15 for the narrow boss) in a part 200 long: a
// tolerance relative to the part's size missed it; and the narrow boss lies
// between two samples of the block's edge, so only the crossing shows.
TEST(PlanSteps, ALongBossOverhangingItsBlockHasItsTopCut) {
  for (const auto& [x0, x1] : {std::pair{1.5, 2.5}, std::pair{1.1, 1.4}}) {
    SCOPED_TRACE(x0);
    const VolumeFacts facts =
        facts_test::polyhedron_facts({{oriented(rect_xy(0, 0, 4, 4, 0), kDown)},
                                      {oriented(rect_xy(x0, 1.5, x1, 201.5, 3), kUp)}});
    const auto cut = cut_caps(facts, {1, 2}, kDown, 5e-3);
    // The bottom holds part of the top's footprint, the top part of the bottom's.
    EXPECT_EQ(cut, (std::vector<int>{1, 2}));
  }
  // The same boss standing inside the block: nothing cuts its top.
  const VolumeFacts inside = facts_test::polyhedron_facts(
      {{oriented(rect_xy(0, 0, 4, 4, 0), kDown)}, {oriented(rect_xy(1.5, 1.5, 2.5, 3.5, 3), kUp)}});
  EXPECT_EQ(cut_caps(inside, {1, 2}, kDown, 5e-3), (std::vector<int>{1}));
}

// Cap curves that project onto each other (issue 15: a round boss above a
// round foot of the same radius needs equal counts on both rims): the
// boss top's four edges over the shoulder's hole, the top's outer edges
// over the bottom's; nothing else. Two long parallel edges 1 apart (the
// campaign's 7,500-long boss) are not coincident.
TEST(PlanSteps, CapCurvesThatProjectOntoEachOtherArePaired) {
  const VolumeFacts facts = facts_test::polyhedron_facts(boss_on_block());
  const auto z = z_caps(facts);
  const auto pairs = coincident_cap_curves(facts, std::vector<int>(z.begin(), z.end()), kDown);
  EXPECT_EQ(pairs.size(), 8u);
  for (const auto& [a, b] : pairs) {
    const CurveFact& ca = facts.curves.at(a);
    const CurveFact& cb = facts.curves.at(b);
    std::set<std::pair<long, long>> ea, eb;
    for (int v : {ca.start, ca.end}) {
      const Vec3& p = facts.vertices.at(v);
      ea.insert({std::lround(p.x() * 1e6), std::lround(p.y() * 1e6)});
    }
    for (int v : {cb.start, cb.end}) {
      const Vec3& p = facts.vertices.at(v);
      eb.insert({std::lround(p.x() * 1e6), std::lround(p.y() * 1e6)});
    }
    EXPECT_EQ(ea, eb) << "curves " << a << " and " << b;
  }
  const auto rows = coincident_curve_rows(pairs, "t");
  ASSERT_EQ(rows.size(), 8u);
  EXPECT_EQ(rows[0].sense, intervals::Sense::Equal);
  const VolumeFacts apart =
      facts_test::polyhedron_facts({{oriented(rect_xy(4, 0.25, 5, 7500.25, 2.5), kUp)},
                                    {oriented(rect_xy(5, 0.25, 6, 7500.25, 2), kUp)}});
  // Only the shared line x = 5 coincides.
  EXPECT_EQ(coincident_cap_curves(apart, {1, 2}, kDown).size(), 1u);
}

// Footprints sharing part of an edge (issue 15, case 8110): a boss base
// x 4..5, y 0.25..2.25 over a foot top x 3.5..5, y 1.5..3 share y 1.5..2.25
// of the line x = 5. Edges on one line that do not overlap, or coincide
// whole, are not such a stretch.
TEST(PlanSteps, CapCurvesSharingPartOfALineAreFound) {
  const VolumeFacts facts =
      facts_test::polyhedron_facts({{oriented(rect_xy(4, 0.25, 5, 2.25, 2), kUp)},
                                    {oriented(rect_xy(3.5, 1.5, 5, 3, 0), kDown)}});
  const auto pairs = overlapping_cap_curves(facts, {1, 2}, kDown);
  ASSERT_EQ(pairs.size(), 1u);
  for (int c : {pairs[0].first, pairs[0].second}) {
    const CurveFact& f = facts.curves.at(c);
    EXPECT_NEAR(facts.vertices.at(f.start).x(), 5.0, 1e-12);
    EXPECT_NEAR(facts.vertices.at(f.end).x(), 5.0, 1e-12);
  }
  // Beside each other on the line y = 1.5 (x 0..1 and 2..3), or the same square.
  const VolumeFacts apart =
      facts_test::polyhedron_facts({{oriented(rect_xy(0, 1.5, 1, 2.5, 2), kUp)},
                                    {oriented(rect_xy(2, 1.5, 3, 2.5, 0), kDown)},
                                    {oriented(rect_xy(0, 1.5, 1, 2.5, -1), kDown)}});
  EXPECT_TRUE(overlapping_cap_curves(apart, {1, 2, 3}, kDown).empty());
}

TEST(PlanSteps, ABlindPocketsFloorJoinsTheBarrelBelowIt) {
  const VolumeFacts facts = facts_test::polyhedron_facts(pocket());
  const Steps s = run_steps(facts, z_caps(facts), down());
  ASSERT_EQ(s.tree.barrels.size(), 2u);
  const int floor = facts.faces.back().id;
  // Barrel 1: the top, down the outer and the pocket walls to the floor's
  // level; barrel 2 starts from the floor and barrel 1's virtual cap.
  EXPECT_EQ(s.tree.barrels[0].sides.size(), 8u);
  EXPECT_EQ(s.tree.barrels[1].sides.size(), 4u);
  const auto& upper = s.tree.barrels[1].upper;
  EXPECT_TRUE(
      std::any_of(upper.begin(), upper.end(), [&](const EndPiece& e) { return e.cap == floor; }));
  EXPECT_TRUE(
      std::any_of(upper.begin(), upper.end(), [&](const EndPiece& e) { return e.interface >= 0; }));
  EXPECT_EQ(imprint_operation(s.tree.barrels[1]), "subtract");
  // The outer walls pass the floor's level without a vertex: barrel 2 has a
  // layer only if the walls' chains exceed the pocket walls' chains.
  const auto rows = barrel_constraints(facts, s.lattice, s.order, s.tree, {}, "t");
  bool difference = false;
  for (const IntervalRow& r : rows) {
    if (r.sense != intervals::Sense::GreaterEqual) continue;
    int pos = 0, neg = 0;
    for (const auto& [c, k] : r.terms) (k > 0 ? pos : neg)++;
    difference = difference || (pos > 0 && neg > 0);
  }
  EXPECT_TRUE(difference);
  // The floor faces up: an upper cap, the pocket walls meet it re-entrantly.
  EXPECT_TRUE(s.order.upper.at(floor));
}

// A 4 x 4 x 2 block with a blind hole from the bottom (1 x 1, floor at
// 1.5) and a lug on its right wall (x 4 to 6, y 1 to 3, floor at 0.5) whose
// outer bottom edge is chamfered up to 1.2: the chamfer is a side that
// joins the ring between the levels 0.5 and 1.5 (a lug's conical underside
// in the campaign), so the rings above and below the hole's floor differ
// by it.
std::vector<PolyFace> chamfered_lug_and_blind_hole() {
  std::vector<PolyFace> f;
  f.push_back(
      {oriented(rect_xy(0, 0, 4, 4, 0), kDown), oriented(rect_xy(1, 1, 2, 2, 0), kDown, false)});
  f.push_back({oriented(
      {{0, 0, 2}, {4, 0, 2}, {4, 1, 2}, {6, 1, 2}, {6, 3, 2}, {4, 3, 2}, {4, 4, 2}, {0, 4, 2}},
      kUp)});
  f.push_back({oriented({{0, 0, 0}, {4, 0, 0}, {4, 0, 2}, {0, 0, 2}}, Vec3(0, -1, 0))});
  f.push_back({oriented({{0, 4, 0}, {4, 4, 0}, {4, 4, 2}, {0, 4, 2}}, Vec3(0, 1, 0))});
  f.push_back({oriented({{0, 0, 0}, {0, 4, 0}, {0, 4, 2}, {0, 0, 2}}, Vec3(-1, 0, 0))});
  f.push_back({oriented(
      {{4, 0, 0}, {4, 4, 0}, {4, 4, 2}, {4, 3, 2}, {4, 3, 0.5}, {4, 1, 0.5}, {4, 1, 2}, {4, 0, 2}},
      Vec3(1, 0, 0))});
  f.push_back({oriented(rect_xy(4, 1, 5.5, 3, 0.5), kDown)});  // the lug's floor
  f.push_back({oriented({{5.5, 1, 0.5}, {5.5, 3, 0.5}, {6, 3, 1.2}, {6, 1, 1.2}},
                        Vec3(0.7, 0, -0.5))});  // the chamfer
  f.push_back({oriented({{6, 1, 1.2}, {6, 3, 1.2}, {6, 3, 2}, {6, 1, 2}}, Vec3(1, 0, 0))});
  for (double y : {1.0, 3.0}) {
    f.push_back({oriented({{4, y, 0.5}, {5.5, y, 0.5}, {6, y, 1.2}, {6, y, 2}, {4, y, 2}},
                          Vec3(0, y > 2 ? 1 : -1, 0))});
  }
  for (const PolyFace& w : walls(1, 1, 2, 2, 0, 1.5, true)) f.push_back(w);
  f.push_back({oriented(rect_xy(1, 1, 2, 2, 1.5), kDown)});  // the hole's floor
  return f;
}

TEST(PlanSteps, AHolesFloorEndsTheBarrelAboveARingThatGainsAChamfer) {
  const VolumeFacts facts = facts_test::polyhedron_facts(chamfered_lug_and_blind_hole());
  ASSERT_EQ(facts.faces.size(), 16u);
  const int floor = facts.faces.back().id;
  const int lug_floor = 7, chamfer = 8;
  const Steps s = run_steps(facts, z_caps(facts), down());
  ASSERT_TRUE(s.tree.ok) << s.tree.why;
  ASSERT_EQ(s.slabs.slabs.size(), 3u);
  // The chamfer is in the ring of the middle slab only.
  for (size_t k = 0; k < 3; ++k) {
    bool has = false;
    for (const Cycle& c : s.slabs.slabs[k].cycles)
      has = has || std::count(c.faces.begin(), c.faces.end(), chamfer) > 0;
    EXPECT_EQ(has, k == 1) << k;
  }
  // Down from the top: the hole's floor ends the first barrel (with the
  // virtual cap of the ring that continues), the lug's floor the second.
  ASSERT_EQ(s.tree.barrels.size(), 3u);
  EXPECT_EQ(s.tree.cap_end.at(floor).first, 0);
  EXPECT_FALSE(s.tree.cap_end.at(floor).second);
  EXPECT_EQ(s.tree.cap_end.at(lug_floor).first, 1);
  EXPECT_FALSE(s.tree.cap_end.at(lug_floor).second);
  const auto& lower = s.tree.barrels[0].lower;
  EXPECT_TRUE(
      std::any_of(lower.begin(), lower.end(), [&](const EndPiece& e) { return e.interface >= 0; }));
}

// The same part: the ring where the chamfer meets the lug's wall (z = 1.2)
// lies 0.3 below the hole's floor and 0.7 above the lug's floor. It must
// not lie outside them (needs, rhs 0); where it is more than a quarter of
// an element from one, it is preferably a layer away from it, so that the
// layer through the level does not tilt down to the ring (plan => mesh
// campaign seed 10 case 169).
TEST(PlanSteps, ARingFarFromACapLevelPrefersALayerBetweenThem) {
  const VolumeFacts facts = facts_test::polyhedron_facts(chamfered_lug_and_blind_hole());
  const Steps s = run_steps(facts, z_caps(facts), down());
  ASSERT_TRUE(s.tree.ok) << s.tree.why;
  auto rows_of = [&](double layer_size, bool preferred) {
    std::vector<std::string> out;
    for (const IntervalRow& r :
         barrel_constraints(facts, s.lattice, s.order, s.tree, {}, "t", layer_size)) {
      if (r.preferred != preferred || r.label.find("the ring of vertices") == std::string::npos)
        continue;
      EXPECT_EQ(r.sense, intervals::Sense::GreaterEqual) << r.label;
      EXPECT_EQ(r.rhs, preferred ? 1 : 0) << r.label;
      out.push_back(r.label);
    }
    return out;
  };
  // Needs: the ring between the two levels, at every size.
  ASSERT_EQ(rows_of(0, false).size(), 2u);
  EXPECT_EQ(rows_of(1.0, false), rows_of(0, false));
  EXPECT_TRUE(rows_of(0, true).empty());  // no size: no preference
  // Size 1: both gaps exceed 0.25.
  const auto both = rows_of(1.0, true);
  ASSERT_EQ(both.size(), 2u);
  EXPECT_NE(both[0].find("a layer below the cap level above it"), std::string::npos) << both[0];
  EXPECT_NE(both[1].find("a layer above the cap level below it"), std::string::npos) << both[1];
  // Size 2: only the 0.7 to the lug's floor exceeds 0.5.
  const auto one = rows_of(2.0, true);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_NE(one[0].find("a layer above the cap level below it"), std::string::npos) << one[0];
  EXPECT_TRUE(rows_of(4.0, true).empty());  // both within a quarter of 4
}

/// Every slab, top down, is one region: the block's walls (outer) round
/// one hole of `hole_walls[k]` faces.
void expect_walls_round_one_hole(const SlabRegions& slabs, const std::vector<size_t>& hole_walls) {
  ASSERT_EQ(slabs.slabs.size(), hole_walls.size());
  for (size_t k = 0; k < hole_walls.size(); ++k) {
    const Slab& slab = slabs.slabs[k];
    ASSERT_EQ(slab.cycles.size(), 2u) << k;
    ASSERT_EQ(slab.regions.size(), 1u) << k;
    const Cycle& outer = slab.cycles[static_cast<size_t>(slab.regions[0].front())];
    const Cycle& hole = slab.cycles[static_cast<size_t>(slab.regions[0].back())];
    EXPECT_TRUE(outer.outer) << k;
    EXPECT_FALSE(hole.outer) << k;
    EXPECT_EQ(hole.faces.size(), hole_walls[k]) << k;
  }
}

// A 6 x 6 x 3 block with a 2 x 2 pocket 1 deep from the bottom and a
// 2 x 2 through hole overlapping a quarter of it (the plan => mesh
// campaign's seed 3 case 131, with circles). The pocket's floor ends at the
// hole's wall: a convex contact on the floor's outer loop, while the top's
// hole loop says the same wall walls a hole.
std::vector<PolyFace> pocket_crossed_by_hole() {
  std::vector<PolyFace> f = walls(0, 0, 6, 6, 0, 3);
  const Vec3 px(1, 0, 0), py(0, 1, 0), mx(-1, 0, 0), my(0, -1, 0);
  f.push_back(
      {oriented(rect_xy(0, 0, 6, 6, 0), kDown),
       oriented(
           {{1, 1, 0}, {3, 1, 0}, {3, 2, 0}, {4, 2, 0}, {4, 4, 0}, {2, 4, 0}, {2, 3, 0}, {1, 3, 0}},
           kDown, false)});
  f.push_back(
      {oriented(rect_xy(0, 0, 6, 6, 3), kUp), oriented(rect_xy(2, 2, 4, 4, 3), kUp, false)});
  // The pocket: its floor (an L, facing the cavity below) and four walls.
  f.push_back(
      {oriented({{1, 1, 1}, {3, 1, 1}, {3, 2, 1}, {2, 2, 1}, {2, 3, 1}, {1, 3, 1}}, kDown)});
  f.push_back({oriented({{1, 1, 0}, {1, 3, 0}, {1, 3, 1}, {1, 1, 1}}, px)});
  f.push_back({oriented({{1, 1, 0}, {3, 1, 0}, {3, 1, 1}, {1, 1, 1}}, py)});
  f.push_back({oriented({{3, 1, 0}, {3, 2, 0}, {3, 2, 1}, {3, 1, 1}}, mx)});
  f.push_back({oriented({{1, 3, 0}, {2, 3, 0}, {2, 3, 1}, {1, 3, 1}}, my)});
  // The hole: two walls notched where the pocket takes their foot.
  f.push_back({oriented({{2, 2, 1}, {2, 3, 1}, {2, 3, 0}, {2, 4, 0}, {2, 4, 3}, {2, 2, 3}}, px)});
  f.push_back({oriented({{2, 2, 1}, {3, 2, 1}, {3, 2, 0}, {4, 2, 0}, {4, 2, 3}, {2, 2, 3}}, py)});
  f.push_back({oriented({{4, 2, 0}, {4, 4, 0}, {4, 4, 3}, {4, 2, 3}}, mx)});
  f.push_back({oriented({{2, 4, 0}, {4, 4, 0}, {4, 4, 3}, {2, 4, 3}}, my)});
  return f;
}

TEST(PlanSteps, AHoleCrossingAPocketsFloorStillWallsAHole) {
  const VolumeFacts facts = facts_test::polyhedron_facts(pocket_crossed_by_hole());
  const Steps s = run_steps(facts, z_caps(facts), down());
  ASSERT_TRUE(s.slabs.ok) << s.slabs.why;
  ASSERT_EQ(s.slabs.slabs.size(), 2u);
  // Above the floor: the block's walls round the hole's; below it: the
  // block's walls round the pocket and the hole's feet, one cavity.
  expect_walls_round_one_hole(s.slabs, {4, 8});
  EXPECT_EQ(s.tree.barrels.size(), 2u);
}

// A 6 x 6 x 4 block with a 2 x 2 pocket from the top (floor at 1.5) and
// one from the bottom (ceiling at 2.5) overlapping a quarter of it: between
// 1.5 and 2.5 the two are one cavity, and no cap bounds that slab (the
// floor faces up, the ceiling down). The cavity's walls there are walls of
// faces that are holes' above and below.
std::vector<PolyFace> pockets_from_both_ends() {
  std::vector<PolyFace> f = walls(0, 0, 6, 6, 0, 4);
  const Vec3 px(1, 0, 0), py(0, 1, 0), mx(-1, 0, 0), my(0, -1, 0);
  f.push_back(
      {oriented(rect_xy(0, 0, 6, 6, 0), kDown), oriented(rect_xy(2, 2, 4, 4, 0), kDown, false)});
  f.push_back(
      {oriented(rect_xy(0, 0, 6, 6, 4), kUp), oriented(rect_xy(1, 1, 3, 3, 4), kUp, false)});
  f.push_back({oriented(
      {{1, 1, 1.5}, {3, 1, 1.5}, {3, 2, 1.5}, {2, 2, 1.5}, {2, 3, 1.5}, {1, 3, 1.5}}, kUp)});
  f.push_back({oriented(
      {{3, 2, 2.5}, {4, 2, 2.5}, {4, 4, 2.5}, {2, 4, 2.5}, {2, 3, 2.5}, {3, 3, 2.5}}, kDown)});
  // The top pocket's walls, two of them open at the foot onto the other.
  f.push_back({oriented({{1, 1, 1.5}, {1, 3, 1.5}, {1, 3, 4}, {1, 1, 4}}, px)});
  f.push_back({oriented({{1, 1, 1.5}, {3, 1, 1.5}, {3, 1, 4}, {1, 1, 4}}, py)});
  f.push_back(
      {oriented({{3, 1, 1.5}, {3, 2, 1.5}, {3, 2, 2.5}, {3, 3, 2.5}, {3, 3, 4}, {3, 1, 4}}, mx)});
  f.push_back(
      {oriented({{1, 3, 1.5}, {2, 3, 1.5}, {2, 3, 2.5}, {3, 3, 2.5}, {3, 3, 4}, {1, 3, 4}}, my)});
  // The bottom pocket's walls, likewise open at the head.
  f.push_back({oriented({{4, 2, 0}, {4, 4, 0}, {4, 4, 2.5}, {4, 2, 2.5}}, mx)});
  f.push_back({oriented({{2, 4, 0}, {4, 4, 0}, {4, 4, 2.5}, {2, 4, 2.5}}, my)});
  f.push_back(
      {oriented({{2, 2, 0}, {2, 4, 0}, {2, 4, 2.5}, {2, 3, 2.5}, {2, 3, 1.5}, {2, 2, 1.5}}, px)});
  f.push_back(
      {oriented({{2, 2, 0}, {4, 2, 0}, {4, 2, 2.5}, {3, 2, 2.5}, {3, 2, 1.5}, {2, 2, 1.5}}, py)});
  return f;
}

TEST(PlanSteps, PocketsFromBothEndsMeetInASlabTheirWallsFacingDecide) {
  const VolumeFacts facts = facts_test::polyhedron_facts(pockets_from_both_ends());
  const Steps s = run_steps(facts, z_caps(facts), down());
  ASSERT_TRUE(s.slabs.ok) << s.slabs.why;
  ASSERT_EQ(s.slabs.slabs.size(), 3u);
  expect_walls_round_one_hole(s.slabs, {4, 8, 4});  // top down: the cavity's walls
}

TEST(PlanSteps, TheSteppedLSplitsItsSideWallsAtTheShoulder) {
  const VolumeFacts facts = facts_test::polyhedron_facts(stepped_l());
  const Steps s = run_steps(facts, z_caps(facts), down());
  // The L-shaped walls span two slabs: the step's barrel ends at the
  // shoulder's level, its virtual cap beside the shoulder (Fig. 8d).
  ASSERT_EQ(s.slabs.slabs.size(), 2u);
  ASSERT_EQ(s.tree.barrels.size(), 2u);
  const BarrelNode& step = s.tree.barrels[0];
  const BarrelNode& block = s.tree.barrels[1];
  EXPECT_EQ(step.lower.size(), 1u);
  EXPECT_EQ(block.upper.size(), 2u);  // the shoulder and the step's virtual cap
  // The L walls are sides of both barrels.
  int shared = 0;
  for (int f : step.sides) shared += std::count(block.sides.begin(), block.sides.end(), f) ? 1 : 0;
  EXPECT_EQ(shared, 3);  // the front and the two L walls
}

TEST(PlanSteps, AFaceThatCannotBeASideIsRefusedWithAReason) {
  // The cube with its top declared a side and only the bottom a cap.
  const VolumeFacts facts = facts_test::polyhedron_facts(cube());
  const SideLattice l = side_lattice(facts, {facts.faces.back().id - 1});
  EXPECT_FALSE(l.ok);
  EXPECT_FALSE(l.why.empty());
}

TEST(PlanSteps, CandidatesOfTheBossAreAPairThenTheAxis) {
  const VolumeFacts facts = facts_test::polyhedron_facts(boss_on_block());
  std::string why;
  const auto pairs = pair_candidates(facts, {}, {}, why);
  // The shoulder has two loops and cannot be a side; pairs must contain it.
  const int shoulder = 6;
  ASSERT_FALSE(pairs.empty()) << why;
  for (const CapCandidate& c : pairs) EXPECT_TRUE(c.caps.count(shoulder)) << c.label;
  const auto axes = candidate_axes(facts, std::nullopt);
  ASSERT_FALSE(axes.empty());
  EXPECT_NEAR(std::abs(axes.front().z()), 1.0, 1e-12);  // the face with a hole first
  // A hinted axis is the only one.
  const auto hinted = candidate_axes(facts, Vec3(1, 0, 0));
  ASSERT_EQ(hinted.size(), 1u);
  EXPECT_NEAR(hinted.front().x(), 1.0, 1e-12);
}

}  // namespace
}  // namespace cooperage::cooper
