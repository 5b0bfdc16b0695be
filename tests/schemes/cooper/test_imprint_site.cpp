// imprint_site.h: where the rims an imprint left unmatched come closest,
// on hand-made ends (a near miss, a contact that is no gap, one end only).
#include "schemes/cooper/imprint_site.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace cooperage::cooper {
namespace {

// A square loop of side `n` unit edges from (x0, y0), counter-clockwise,
// with node ids from `first`.
std::vector<int> square(ImprintResult& r, int first, double x0, double y0, int n) {
  std::vector<int> loop;
  const Vec2 corner[4] = {{x0, y0}, {x0 + n, y0}, {x0 + n, y0 + n}, {x0, y0 + n}};
  int id = first;
  for (int side = 0; side < 4; ++side) {
    const Vec2 a = corner[side], b = corner[(side + 1) % 4];
    for (int k = 0; k < n; ++k) {
      r.ends.xy[id] = a + (b - a) * (static_cast<double>(k) / n);
      loop.push_back(id++);
    }
  }
  return loop;
}

ImprintResult two_squares(double lower_x0) {
  ImprintResult r;
  r.ends.upper.push_back({1, {square(r, 100, 0, 0, 4)}});
  r.ends.lower.push_back({2, {square(r, 200, lower_x0, 0.5, 4)}});
  r.unmatched = {std::vector<int>{1}, std::vector<int>{2}};
  return r;
}

TEST(ImprintSite, ANearMissIsTheClosestApproach) {
  const ImprintResult r = two_squares(4.03);  // 0.03 right of the upper square
  const ImprintSite site = narrowest_gap(r);
  ASSERT_GE(site.node, 0);
  EXPECT_NEAR(site.gap, 0.03, 1e-12);
  EXPECT_NEAR(site.edge, 1.0, 1e-12);
  // On the upper square's right side or the lower square's left one.
  EXPECT_TRUE(std::abs(site.at.x() - 4.0) < 1e-12 || std::abs(site.at.x() - 4.03) < 1e-12)
      << site.at.transpose();
}

TEST(ImprintSite, ANodeOnTheOtherRimIsAContactNotAGap) {
  // The lower square's left side along the upper's right side (x = 4),
  // half an edge higher: their nodes lie on each other's edges (distance
  // 0), and the closest approach is between the corners, 0.5 apart.
  const ImprintResult r = two_squares(4.0);
  const ImprintSite site = narrowest_gap(r);
  ASSERT_GE(site.node, 0);
  EXPECT_NEAR(site.gap, 0.5, 1e-12);
}

TEST(ImprintSite, NothingUnmatchedOnOneEndIsNoSite) {
  ImprintResult r = two_squares(4.03);
  r.unmatched[1].clear();
  EXPECT_EQ(narrowest_gap(r).node, -1);
  EXPECT_TRUE(std::isinf(narrowest_gap(r).gap));
}

}  // namespace
}  // namespace cooperage::cooper
