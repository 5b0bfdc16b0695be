// A barrel's lower end warped onto its upper end's chart along the ribs
// (schemes/cooper/chart_warp.h): ribbed nodes land on their partners, the
// rest follow the nearest ribs, and the inverse takes a point of the upper
// chart back to where it lies on the lower end.
#include "schemes/cooper/chart_warp.h"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

namespace cooperage::cooper {
namespace {

using Vec2 = ChartWarp::Vec2;

// Ribs round a circle of radius 2 whose lower nodes sit `shift` radians
// round from their partners (a hole whose two rims are split at different
// vertices), and a square of radius 5 whose ribs agree.
std::vector<std::pair<Vec2, Vec2>> twisted_hole_ribs(double shift) {
  std::vector<std::pair<Vec2, Vec2>> ribs;
  const int n = 12;
  for (int k = 0; k < n; ++k) {
    const double a = 2 * M_PI * k / n;
    ribs.push_back(
        {{2 * std::cos(a + shift), 2 * std::sin(a + shift)}, {2 * std::cos(a), 2 * std::sin(a)}});
  }
  for (int i = -1; i <= 1; ++i) {
    for (int j = -1; j <= 1; ++j) {
      if (i || j) ribs.push_back({Vec2(5.0 * i, 5.0 * j), Vec2(5.0 * i, 5.0 * j)});
    }
  }
  return ribs;
}

TEST(ChartWarp, RibsThatAgreeLeaveEveryPositionAsItIs) {
  const ChartWarp warp(twisted_hole_ribs(0));
  EXPECT_FALSE(warp.active());
  const Vec2 p(0.3, -3.1);
  EXPECT_EQ(warp.forward(p), p);
  EXPECT_EQ(warp.inverse(p), p);
}

TEST(ChartWarp, RibbedNodesLandOnTheirPartnersAndTheRestFollow) {
  const double shift = 0.2;  // 0.4 of an interval
  const auto ribs = twisted_hole_ribs(shift);
  const ChartWarp warp(ribs);
  ASSERT_TRUE(warp.active());
  for (const auto& [q, p] : ribs) EXPECT_LT((warp.forward(q) - p).norm(), 1e-12);
  // A node just outside the hole, where a foot's rim leaves it: turned back
  // by nearly the ribs' twist (the nearest ribs dominate), while a node at
  // the square's ribs barely moves.
  const double a = 0.5;
  const Vec2 near_hole(2.2 * std::cos(a + shift), 2.2 * std::sin(a + shift));
  const Vec2 moved = warp.forward(near_hole);
  const double turned = std::atan2(near_hole.y(), near_hole.x()) - std::atan2(moved.y(), moved.x());
  EXPECT_GT(turned, 0.6 * shift);
  EXPECT_LT(turned, 1.1 * shift);
  const Vec2 near_square(4.9, 4.9);
  EXPECT_LT((warp.forward(near_square) - near_square).norm(), 0.05);
  // The inverse takes forward's images back.
  for (const Vec2& q : {near_hole, near_square, Vec2(3.5, -1.0), Vec2(-2.6, 2.4)})
    EXPECT_LT((warp.inverse(warp.forward(q)) - q).norm(), 1e-6) << q.transpose();
}

}  // namespace
}  // namespace cooperage::cooper
