// A face that comes back onto itself gives a boundary node two feet on the
// surface; loop_parameters() must keep the one continuous with the loop's
// other nodes, whichever foot the global projector returns.
#include "framework/mesh2d/loop_parameters.h"

#include <gtest/gtest.h>

#include <cmath>

namespace cooperage::mesh2d {
namespace {

using geom::Vec2;
using geom::Vec3;

/// The strip 0 <= u <= 1.9, 0 <= v <= 1 folded at u = 1 onto itself: (u, v)
/// and (2 - u, v) are the same point. Its global projection returns the far
/// sheet for points with x in (0.45, 0.55) (as OCCT's did on real-cad
/// occt_bottle's shoulder strip); the local one the foot nearest the hint.
class FoldedStrip : public geom::SurfaceGeometry {
 public:
  geom::SurfaceType type() const override { return geom::SurfaceType::BSpline; }
  Vec3 point(const Vec2& uv) const override {
    const double x = uv.x() <= 1 ? uv.x() : 2 - uv.x();
    return {x, uv.y(), 0.0};
  }
  Vec3 normal(const Vec2& uv) const override { return {0, 0, uv.x() <= 1 ? 1.0 : -1.0}; }
  std::pair<Vec2, Vec2> uv_bounds() const override { return {{0.0, 1.9}, {0.0, 1.0}}; }
  geom::SurfaceProjection project(const Vec3& p) const override {
    const bool unlucky = p.x() > 0.45 && p.x() < 0.55;
    return foot(p, unlucky ? 2 - p.x() : p.x());
  }
  geom::SurfaceProjection project_near(const Vec3& p, const Vec2& hint) const override {
    const double a = p.x(), b = 2 - p.x();
    return foot(p, std::abs(hint.x() - a) <= std::abs(hint.x() - b) ? a : b);
  }

 private:
  geom::SurfaceProjection foot(const Vec3& p, double u) const {
    geom::SurfaceProjection r;
    r.uv = {u, p.y()};
    r.point = point(r.uv);
    r.normal = normal(r.uv);
    r.distance = (r.point - p).norm();
    return r;
  }
};

TEST(LoopParameters, ANodeProjectedOntoTheFarSheetIsBroughtBack) {
  // A counter-clockwise square 0.2 .. 0.8 with 6 intervals a side: the
  // nodes at x = 0.5 (bottom and top) hit the unlucky band.
  std::vector<Vec3> square;
  const int k = 6;
  for (int i = 0; i < k; ++i) square.push_back({0.2 + 0.6 * i / k, 0.2, 0});
  for (int i = 0; i < k; ++i) square.push_back({0.8, 0.2 + 0.6 * i / k, 0});
  for (int i = 0; i < k; ++i) square.push_back({0.8 - 0.6 * i / k, 0.8, 0});
  for (int i = 0; i < k; ++i) square.push_back({0.2, 0.8 - 0.6 * i / k, 0});
  const FoldedStrip strip;
  int unlucky = 0;
  for (const Vec3& p : square) unlucky += strip.project(p).uv.x() > 1 ? 1 : 0;
  ASSERT_EQ(unlucky, 2);
  const LoopParameters lp = loop_parameters(strip, {square});
  ASSERT_EQ(lp.uv.size(), 1u);
  ASSERT_EQ(lp.uv[0].size(), square.size());
  double area = 0;
  for (size_t i = 0; i < square.size(); ++i) {
    const auto& a = lp.uv[0][i];
    const auto& b = lp.uv[0][(i + 1) % square.size()];
    EXPECT_NEAR(a.x(), square[static_cast<size_t>(lp.node[0][i])].x(), 1e-12) << "node " << i;
    area += 0.5 * (a.x() * b.y() - b.x() * a.y());
  }
  EXPECT_NEAR(std::abs(area), 0.36, 1e-12);
}

}  // namespace
}  // namespace cooperage::mesh2d
