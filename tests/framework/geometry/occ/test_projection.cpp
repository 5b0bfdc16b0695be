// Surface projection (surface_projector.h): closed forms on elementary
// surfaces and the warm-started Newton step of project_near() agree with an
// independent brute-force search over the face's parameter box; a bad hint
// still gives the closest point; results do not depend on the thread.
#include "occ_test_util.h"

#include <algorithm>
#include <limits>
#include <set>
#include <thread>

namespace cooperage::occ::test {
namespace {

// Closest sample of a fine uv grid over the face's box, refined by a
// shrinking pattern search: slow, but shares no code with the projector.
double brute_distance(const geom::SurfaceGeometry& g, const Vec3& p) {
  const auto [u, v] = g.uv_bounds();
  const int n = 120;
  double best = std::numeric_limits<double>::max();
  Vec2 at(u.x(), v.x());
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      const Vec2 q(u.x() + (u.y() - u.x()) * i / n, v.x() + (v.y() - v.x()) * j / n);
      const double d = (g.point(q) - p).norm();
      if (d < best) best = d, at = q;
    }
  Vec2 step((u.y() - u.x()) / n, (v.y() - v.x()) / n);
  for (int it = 0; it < 60; ++it) {
    bool moved = false;
    for (const Vec2& d : {Vec2(1, 0), Vec2(-1, 0), Vec2(0, 1), Vec2(0, -1)}) {
      Vec2 q = at + d.cwiseProduct(step);
      q.x() = std::clamp(q.x(), u.x(), u.y());
      q.y() = std::clamp(q.y(), v.x(), v.y());
      const double dist = (g.point(q) - p).norm();
      if (dist < best) best = dist, at = q, moved = true;
    }
    if (!moved) step *= 0.5;
  }
  return best;
}

// Points around a face: on it, and off it along its normal both ways.
std::vector<Vec3> probes(const geom::SurfaceGeometry& g) {
  const auto [u, v] = g.uv_bounds();
  std::vector<Vec3> out;
  for (double fu : {0.13, 0.5, 0.81})
    for (double fv : {0.22, 0.5, 0.9})
      for (double d : {0.0, 0.05, -0.04}) {
        const Vec2 q(u.x() + fu * (u.y() - u.x()), v.x() + fv * (v.y() - v.x()));
        out.push_back(g.point(q) + d * g.normal(q));
      }
  return out;
}

Model elementary_model() {
  Workbench wb;
  wb.cone("cone", Vec3(0, 0, 0), Vec3(0, 0, 1), 2.0, 1.0, 2.0);
  wb.sphere("ball", Vec3(6, 0, 0), 1.5);
  wb.cylinder("can", Vec3(-6, 0, 0), Vec3(1, 1, 0), 1.0, 2.0);
  return wb.build_model();
}

TEST(OccProjection, ClosedFormsAreTheClosestPoints) {
  const Model m = elementary_model();
  std::set<geom::SurfaceType> seen;
  for (const auto& s : m.surfaces()) {
    seen.insert(s.geometry->type());
    for (const Vec3& p : probes(*s.geometry)) {
      const auto proj = s.geometry->project(p);
      EXPECT_NEAR((s.geometry->point(proj.uv) - proj.point).norm(), 0, 1e-12);
      EXPECT_NEAR(proj.distance, (p - proj.point).norm(), 1e-12);
      EXPECT_LE(proj.distance, brute_distance(*s.geometry, p) + 1e-9)
          << "surface " << s.id << " at " << p.transpose();
    }
  }
  EXPECT_TRUE(seen.count(geom::SurfaceType::Cone) && seen.count(geom::SurfaceType::Sphere) &&
              seen.count(geom::SurfaceType::Cylinder) && seen.count(geom::SurfaceType::Plane));
}

Model bspline_solid() {
  Workbench wb;
  std::vector<std::vector<Vec3>> grid;
  for (int i = 0; i < 7; ++i) {
    grid.emplace_back();
    for (int j = 0; j < 6; ++j) {
      const double x = 4.0 * i / 6, y = 3.0 * j / 5;
      grid.back().push_back(Vec3(x, y, 0.3 * std::sin(x) * std::cos(y)));
    }
  }
  wb.bspline_patch("patch", grid, 0.5);
  return wb.build_model();
}

// Its B-spline face (null when there is none).
const geom::Surface* bspline_face(const Model& m) {
  const geom::Surface* out = nullptr;
  for (const auto& s : m.surfaces())
    if (s.geometry->type() == geom::SurfaceType::BSpline) out = &s;
  return out;
}

TEST(OccProjection, WarmStartAgreesWithTheGlobalSearch) {
  const Model m = bspline_solid();
  int checked = 0;
  for (const auto& s : m.surfaces()) {
    if (s.geometry->type() != geom::SurfaceType::BSpline) continue;
    const auto [u, v] = s.geometry->uv_bounds();
    for (const Vec3& p : probes(*s.geometry)) {
      const auto global = s.geometry->project(p);
      // A good hint (the answer nudged), a poor one (the box centre), a
      // useless one (a far corner) and a non-finite one.
      for (const Vec2& hint : {Vec2(global.uv + 0.01 * Vec2(u.y() - u.x(), v.y() - v.x())),
                               Vec2(0.5 * (u.x() + u.y()), 0.5 * (v.x() + v.y())),
                               Vec2(u.y(), v.y()), Vec2(std::nan(""), 0.0)}) {
        const auto near = s.geometry->project_near(p, hint);
        EXPECT_NEAR((near.point - global.point).norm(), 0, 1e-7) << p.transpose();
        EXPECT_LE(near.distance, brute_distance(*s.geometry, p) + 1e-9);
        ++checked;
      }
    }
  }
  EXPECT_EQ(checked, 2 * 27 * 4);
}

TEST(OccProjection, SeededSearchFindsTheClosestPointFarFromTheFace) {
  const Model m = bspline_solid();
  int checked = 0;
  for (const auto& s : m.surfaces()) {
    if (s.geometry->type() != geom::SurfaceType::BSpline) continue;
    // Feet inside the face (on its boundary the global search clamps, not exact).
    for (const Vec3& p :
         {Vec3(2, 1.5, 1.5), Vec3(3, 1, -0.8), Vec3(0.7, 2.2, 1.1), Vec3(1, 2, 0.4)}) {
      const auto proj = s.geometry->project(p);
      EXPECT_LE(proj.distance, brute_distance(*s.geometry, p) + 1e-9) << p.transpose();
      ++checked;
    }
  }
  EXPECT_EQ(checked, 2 * 4);
}

// A node of a B-spline rim lies within its fitting error of an analytic
// face, a hair outside the face's parameter box (occt_Pump_TopCover's inner
// sphere, 1e-7 below its lowest latitude): its projection is the rim point
// beside it, never the far side of the sphere (the bounded global search
// gave the antipode, and a submap lattice through it inverted).
TEST(OccProjection, AFootJustOutsideAnAnalyticFaceIsTheRimBesideIt) {
  Workbench wb;
  wb.sphere("ball", Vec3(0, 0, 0), 1.5);
  wb.webcut("ball", Vec3(0, 0, 0), Vec3(0, 0, 1));
  const Model m = wb.build_model();
  int checked = 0;
  for (const auto& s : m.surfaces()) {
    if (s.geometry->type() != geom::SurfaceType::Sphere) continue;
    const auto [u, v] = s.geometry->uv_bounds();
    // > 0: the upper hemisphere.
    const double side = s.geometry->point(Vec2(0.5 * (u.x() + u.y()), 0.5 * (v.x() + v.y()))).z();
    for (double a : {0.3, 1.7, 2.9, 4.4, 5.8}) {
      for (double off : {1e-9, 1e-7, 1e-5}) {
        const double z = side > 0 ? -off : off;  // just beyond the rim (the equator)
        const Vec3 p(1.5 * std::cos(a), 1.5 * std::sin(a), z);
        const auto proj = s.geometry->project(p);
        EXPECT_LT(proj.distance, 2 * off) << "surface " << s.id << " at " << p.transpose();
        EXPECT_LE(proj.distance, brute_distance(*s.geometry, p) + 1e-9);
        ++checked;
      }
    }
  }
  EXPECT_EQ(checked, 2 * 5 * 3);
}

TEST(OccProjection, SameAnswerOnEveryThread) {
  const Model m = bspline_solid();
  const geom::Surface* bs = bspline_face(m);
  ASSERT_NE(bs, nullptr);
  const auto pts = probes(*bs->geometry);
  std::vector<geom::SurfaceProjection> serial, serial_near;
  for (const auto& p : pts) {
    serial.push_back(bs->geometry->project(p));
    serial_near.push_back(bs->geometry->project_near(p, serial.back().uv));
  }
  std::atomic<int> mismatches{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([&, t] {
      for (int rep = 0; rep < 3; ++rep)
        for (size_t k = 0; k < pts.size(); ++k) {
          const size_t i = (k + static_cast<size_t>(t) * 7) % pts.size();  // other orders
          if (bs->geometry->project(pts[i]).uv != serial[i].uv) ++mismatches;
          if (bs->geometry->project_near(pts[i], serial[i].uv).uv != serial_near[i].uv)
            ++mismatches;
        }
    });
  for (auto& th : threads) th.join();
  EXPECT_EQ(mismatches.load(), 0) << "bitwise equal results expected";
}

// The global search remembers its answers per face and thread (bounded):
// an answer asked again, before or after the memory is cleared, is the
// answer computed first.
TEST(OccProjection, AnAnswerAskedAgainIsTheSame) {
  const Model m = bspline_solid();
  const geom::Surface* bs = bspline_face(m);
  ASSERT_NE(bs, nullptr);
  const auto pts = probes(*bs->geometry);
  std::vector<Vec2> first;
  for (const auto& p : pts) first.push_back(bs->geometry->project(p).uv);
  for (size_t k = 0; k < pts.size(); ++k) EXPECT_EQ(bs->geometry->project(pts[k]).uv, first[k]);
  // More other points than the memory holds, then the first ones again.
  for (int k = 0; k < 600; ++k) bs->geometry->project(Vec3(0.007 * k, 0.005 * k, 1.0));
  for (size_t k = 0; k < pts.size(); ++k) EXPECT_EQ(bs->geometry->project(pts[k]).uv, first[k]);
}

// A backend without a local solver answers project_near with project.
class FlatOnly final : public geom::SurfaceGeometry {
 public:
  geom::SurfaceType type() const override { return geom::SurfaceType::Plane; }
  geom::SurfaceProjection project(const Vec3& p) const override {
    geom::SurfaceProjection r;
    r.point = Vec3(p.x(), p.y(), 0);
    r.uv = Vec2(p.x(), p.y());
    r.normal = Vec3(0, 0, 1);
    r.distance = std::abs(p.z());
    return r;
  }
  Vec3 point(const Vec2& uv) const override { return Vec3(uv.x(), uv.y(), 0); }
  Vec3 normal(const Vec2&) const override { return Vec3(0, 0, 1); }
  std::pair<Vec2, Vec2> uv_bounds() const override { return {Vec2(-1, 1), Vec2(-1, 1)}; }
};

TEST(OccProjection, DefaultProjectNearIsProject) {
  const FlatOnly f;
  const auto r = f.project_near(Vec3(0.25, -0.5, 3.0), Vec2(100, 100));
  EXPECT_EQ(r.uv, Vec2(0.25, -0.5));
  EXPECT_EQ(r.distance, 3.0);
}

}  // namespace
}  // namespace cooperage::occ::test
