// geom::ProjectionWalk: local searches from the previous answer, and the
// global search when the local answer is farther than the reach.
#include "framework/geometry/projection_walk.h"

#include <gtest/gtest.h>

#include <cmath>

namespace cooperage::geom {
namespace {

// The unit sphere, parameters (longitude, latitude). project() is exact;
// project_near() is a local search that, started on the far side of the
// sphere from p, stops at the farthest point (a stationary point of the
// distance, as a Newton iteration can). Both count their calls.
class Sphere : public SurfaceGeometry {
 public:
  SurfaceType type() const override { return SurfaceType::Sphere; }
  Vec3 point(const Vec2& uv) const override {
    return {std::cos(uv.y()) * std::cos(uv.x()), std::cos(uv.y()) * std::sin(uv.x()),
            std::sin(uv.y())};
  }
  Vec3 normal(const Vec2& uv) const override { return point(uv); }
  std::pair<Vec2, Vec2> uv_bounds() const override {
    return {{-M_PI, M_PI}, {-M_PI / 2, M_PI / 2}};
  }
  SurfaceProjection project(const Vec3& p) const override {
    ++global;
    return at(p, p.normalized());
  }
  SurfaceProjection project_near(const Vec3& p, const Vec2& hint) const override {
    ++local;
    const bool far_side = point(hint).dot(p) < 0;
    return at(p, far_side ? Vec3(-p.normalized()) : p.normalized());
  }
  mutable int global = 0, local = 0;

 private:
  SurfaceProjection at(const Vec3& p, const Vec3& q) const {
    SurfaceProjection r;
    r.point = q;
    r.normal = q;
    r.uv = {std::atan2(q.y(), q.x()), std::asin(std::clamp(q.z(), -1.0, 1.0))};
    r.distance = (q - p).norm();
    return r;
  }
};

TEST(ProjectionWalk, NearbyPointsStartFromThePreviousAnswer) {
  Sphere s;
  ProjectionWalk walk(s);
  for (int k = 0; k < 20; ++k) {
    const double a = 0.05 * k;
    const Vec3 p = 1.01 * Vec3(std::cos(a), std::sin(a), 0.1);  // just off the sphere
    const SurfaceProjection r = walk.project(p, 0.1);
    EXPECT_NEAR((r.point - p.normalized()).norm(), 0.0, 1e-12) << k;
  }
  EXPECT_EQ(s.global, 1);  // the first point only
  EXPECT_EQ(s.local, 19);
}

TEST(ProjectionWalk, ALocalAnswerBeyondTheReachIsReplacedByTheGlobalOne) {
  Sphere s;
  ProjectionWalk walk(s);
  walk.project(Vec3(1.01, 0, 0), 0.1);
  // The antipode: the local search from (1, 0, 0) ends on the far side,
  // 2 away; the walk takes the global answer instead.
  const Vec3 p(-1.01, 0, 0);
  const SurfaceProjection r = walk.project(p, 0.1);
  EXPECT_NEAR((r.point - Vec3(-1, 0, 0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR(r.distance, 0.01, 1e-12);
  EXPECT_EQ(s.global, 2);
  // And the walk goes on from there.
  walk.project(Vec3(-1.01, 0.05, 0), 0.1);
  EXPECT_EQ(s.global, 2);
}

}  // namespace
}  // namespace cooperage::geom
