// Curve and surface evaluators: projection accuracy on analytic and B-spline
// faces, arc length, closest parameters, thread safety.
#include "occ_test_util.h"

#include <thread>

namespace cooperage::occ::test {
namespace {

constexpr double kPi = 3.14159265358979323846;

const geom::Surface& first_of_type(const Model& m, geom::SurfaceType type) {
  for (const auto& s : m.surfaces())
    if (s.geometry->type() == type) return s;
  throw std::runtime_error("no surface of the requested type");
}

TEST(OccEvaluators, CylinderProjection) {
  Workbench wb;
  const double R = 2.0;
  wb.cylinder("c", Vec3(0, 0, 0), Vec3(0, 0, 1), R, 5.0);
  const Model m = wb.build_model();
  const auto& side = first_of_type(m, geom::SurfaceType::Cylinder);
  EXPECT_TRUE(near_rel(side.area, 2 * kPi * R * 5, 1e-9));
  for (double rp : {0.5, 1.0, 1.9, 2.0, 2.1, 3.0, 7.5})
    for (double phi : {0.1, 1.0, 2.5, 3.3, 5.9})
      for (double z : {0.3, 2.5, 4.9}) {
        const Vec3 p(rp * std::cos(phi), rp * std::sin(phi), z);
        const auto proj = side.geometry->project(p);
        EXPECT_NEAR(proj.distance, std::abs(rp - R), 1e-9) << rp << " " << phi << " " << z;
        const Vec3 radial(std::cos(phi), std::sin(phi), 0);
        EXPECT_NEAR((proj.point - (R * radial + Vec3(0, 0, z))).norm(), 0, 1e-9);
        EXPECT_NEAR(proj.normal.dot(radial), 1.0, 1e-9);  // out of the cylinder
        EXPECT_NEAR((side.geometry->point(proj.uv) - proj.point).norm(), 0, 1e-12);
      }
}

TEST(OccEvaluators, PlaneProjectionStaysInTheFaceBox) {
  Workbench wb;
  wb.brick("b", Vec3(0, 0, 0), Vec3(1, 1, 1));
  const Model m = wb.build_model();
  for (const auto& s : m.surfaces()) {
    const Vec3 c = s.geometry->point(uv_centre(s));
    const Vec3 n = s.geometry->normal(uv_centre(s));
    const auto proj = s.geometry->project(c + 0.25 * n);
    EXPECT_NEAR(proj.distance, 0.25, 1e-12);
    EXPECT_NEAR((proj.point - c).norm(), 0, 1e-12);
    // A far point projects onto the face's boundary, not the infinite plane.
    const auto far = s.geometry->project(c + Vec3(10, 10, 10));
    EXPECT_TRUE((far.point.array() >= -1e-9).all() && (far.point.array() <= 1 + 1e-9).all());
  }
}

Model bspline_model() {
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

TEST(OccEvaluators, BSplineProjectionRecoversTheFootPoint) {
  const Model m = bspline_model();
  ASSERT_EQ(m.volumes().size(), 1u);
  int checked = 0;
  for (const auto& s : m.surfaces()) {
    if (s.geometry->type() != geom::SurfaceType::BSpline) continue;
    const auto b = s.geometry->uv_bounds();
    for (double fu : {0.2, 0.5, 0.77})
      for (double fv : {0.15, 0.5, 0.9})
        for (double d : {0.01, 0.05, -0.03}) {
          const Vec2 uv(b.first.x() + fu * (b.first.y() - b.first.x()),
                        b.second.x() + fv * (b.second.y() - b.second.x()));
          const Vec3 p = s.geometry->point(uv);
          const Vec3 n = s.geometry->normal(uv);
          const auto proj = s.geometry->project(p + d * n);
          EXPECT_NEAR((proj.point - p).norm(), 0, 1e-7 * 4.0);
          EXPECT_NEAR(proj.distance, std::abs(d), 1e-7 * std::abs(d));
          EXPECT_NEAR(proj.normal.dot(n), 1.0, 1e-7);
          ++checked;
        }
  }
  EXPECT_EQ(checked, 2 * 27);
}

TEST(OccEvaluators, CurveLengthsAndParameters) {
  Workbench wb;
  wb.cylinder("c", Vec3(0, 0, 0), Vec3(0, 0, 1), 1.5, 2.0);
  const Model m = wb.build_model();
  int circles = 0, lines = 0;
  for (const auto& c : m.curves()) {
    const auto& g = *c.geometry;
    const auto r = g.range();
    EXPECT_LT(r.first, r.second);
    EXPECT_NEAR((g.point(r.first) - m.vertex(c.start_vertex).point).norm(), 0, 1e-9);
    EXPECT_NEAR((g.point(r.second) - m.vertex(c.end_vertex).point).norm(), 0, 1e-9);
    const double half = g.parameter_at_length(0.5 * c.length);
    EXPECT_NEAR(g.length(r.first, half), 0.5 * c.length, 1e-9 * c.length);
    EXPECT_NEAR(g.parameter_at_length(0), r.first, 1e-12);
    EXPECT_NEAR(g.parameter_at_length(c.length), r.second, 1e-12);
    const Vec3 mid = g.point(half);
    EXPECT_NEAR(g.closest_parameter(mid + 0.1 * Vec3(mid.x(), mid.y(), 0)), half, 1e-7);
    EXPECT_GT(g.tangent(half).norm(), 0);
    if (g.type() == geom::CurveType::Circle) {
      ++circles;
      EXPECT_TRUE(near_rel(c.length, 2 * kPi * 1.5, 1e-9));
    } else if (g.type() == geom::CurveType::Line) {
      ++lines;
      EXPECT_TRUE(near_rel(c.length, 2.0, 1e-12));
      // Beyond the ends: clamped to the range.
      const Vec3 above = g.point(r.second) + (g.point(r.second) - g.point(r.first));
      EXPECT_NEAR(g.closest_parameter(above), r.second, 1e-12);
    }
  }
  EXPECT_EQ(circles, 2);
  EXPECT_EQ(lines, 1);
}

TEST(OccEvaluators, ThreadSafeProjection) {
  const Model m = bspline_model();
  const auto& s = first_of_type(m, geom::SurfaceType::BSpline);
  const auto& c = m.curve(1);
  std::vector<Vec3> pts;
  for (int i = 0; i < 40; ++i) pts.push_back(Vec3(0.1 * i, 0.07 * i, 0.5 - 0.02 * i));
  std::vector<Vec3> serial;
  std::vector<double> serial_t;
  for (const auto& p : pts) {
    serial.push_back(s.geometry->project(p).point);
    serial_t.push_back(c.geometry->closest_parameter(p));
  }
  std::vector<std::thread> threads;
  std::atomic<int> mismatches{0};
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([&] {
      for (int rep = 0; rep < 5; ++rep)
        for (size_t i = 0; i < pts.size(); ++i) {
          if ((s.geometry->project(pts[i]).point - serial[i]).norm() > 1e-12) ++mismatches;
          if (std::abs(c.geometry->closest_parameter(pts[i]) - serial_t[i]) > 1e-12) ++mismatches;
        }
    });
  for (auto& th : threads) th.join();
  EXPECT_EQ(mismatches.load(), 0);
}

}  // namespace
}  // namespace cooperage::occ::test
