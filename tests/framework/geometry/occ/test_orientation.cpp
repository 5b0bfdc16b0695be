// The orientation contract: loops run with the face on the left seen against
// the natural normal (outer CCW, holes CW); shell senses give outward normals.
#include "occ_test_util.h"

namespace cooperage::occ::test {
namespace {

Model brick_model() {
  Workbench wb;
  wb.brick("b", Vec3(-1, 0.5, 2), Vec3(2, 3, 4));
  return wb.build_model();
}

Model plate_model() {
  Workbench wb;
  wb.brick("plate", Vec3(0, 0, 0), Vec3(10, 4, 1));
  for (int i = 0; i < 3; ++i)
    wb.cylinder("hole" + std::to_string(i), Vec3(2 + 3 * i, 2, -1), Vec3(0, 0, 1), 0.5, 3);
  wb.cut("part", {"plate", "hole0", "hole1", "hole2"});
  return wb.build_model();
}

Model boss_model() {
  Workbench wb;
  wb.cylinder("base", Vec3(0, 0, 0), Vec3(0, 0, 1), 2.0, 3.0);
  wb.cylinder("boss", Vec3(0, 0, 3), Vec3(0, 0, 1), 1.0, 2.0);
  wb.fuse("part", {"base", "boss"});
  return wb.build_model();
}

Model two_bricks_model() {
  Workbench wb;
  wb.brick("a", Vec3(0, 0, 0), Vec3(2, 2, 1));
  wb.brick("b", Vec3(0, 0, 1), Vec3(1, 1, 1));
  return wb.build_model();
}

/// For every planar surface: the outer loop's vector area points along the
/// natural normal and equals the face area plus the holes; holes point the
/// other way. Per volume, sense * natural normal is the outward normal.
void check_planar_loops(const Model& m) {
  int planar = 0;
  for (const auto& s : m.surfaces()) {
    if (s.geometry->type() != geom::SurfaceType::Plane) continue;
    ++planar;
    const Vec3 n = s.geometry->normal(uv_centre(s));
    ASSERT_NEAR(n.norm(), 1.0, 1e-12);
    double enclosed = 0;
    for (size_t i = 0; i < s.loops.size(); ++i) {
      const Vec3 a = area_vector(sample_loop(m, s.loops[i], 64));
      const double along = a.dot(n);
      if (i == 0) {
        EXPECT_GT(along, 0) << "surface " << s.id << " outer loop runs clockwise";
      } else {
        EXPECT_LT(along, 0) << "surface " << s.id << " hole loop " << i
                            << " runs counter-clockwise";
      }
      EXPECT_NEAR(std::abs(along), a.norm(), 1e-9 * a.norm()) << "loop not in the plane";
      enclosed += along;
    }
    EXPECT_NEAR(enclosed, s.area, 2e-3 * s.area) << "surface " << s.id;
    for (int v : s.volumes) {
      const Vec3 out = m.outward_normal(s.id, v, uv_centre(s));
      EXPECT_NEAR(out.dot(sign(m.sense_in(s.id, v)) * n), 1.0, 1e-12);
    }
  }
  EXPECT_GT(planar, 0);
}

/// Divergence theorem over the planar faces: V = 1/3 sum (p . n_out) A.
double planar_divergence_volume(const Model& m, int volume_id) {
  double v = 0;
  for (int sid : m.surfaces_of(volume_id)) {
    const auto& s = m.surface(sid);
    const Vec2 uv = uv_centre(s);
    v += s.geometry->point(uv).dot(m.outward_normal(sid, volume_id, uv)) * s.area / 3.0;
  }
  return v;
}

TEST(OccOrientation, BrickLoopsAndOutwardNormals) {
  const Model m = brick_model();
  check_planar_loops(m);
  EXPECT_NEAR(planar_divergence_volume(m, 1), 24.0, 1e-9);
  const auto box = m.volume(1).box;
  for (int sid : m.surfaces_of(1)) {
    const auto& s = m.surface(sid);
    const Vec2 uv = uv_centre(s);
    const Vec3 p = s.geometry->point(uv) + 1e-3 * m.outward_normal(sid, 1, uv);
    const bool outside = (p.array() < box.min.array()).any() || (p.array() > box.max.array()).any();
    EXPECT_TRUE(outside) << "surface " << sid << " normal points into the brick";
  }
}

TEST(OccOrientation, PlateWithHoles) {
  const Model m = plate_model();
  check_planar_loops(m);
  // Hole walls: the outward normal points towards the hole axis.
  int walls = 0;
  for (const auto& s : m.surfaces()) {
    if (s.geometry->type() != geom::SurfaceType::Cylinder) continue;
    ++walls;
    const Vec2 uv = uv_centre(s);
    const Vec3 p = s.geometry->point(uv);
    const Vec3 axis_point(std::round((p.x() - 2) / 3) * 3 + 2, 2, p.z());
    EXPECT_GT((axis_point - p).dot(m.outward_normal(s.id, 1, uv)), 0.49);
  }
  EXPECT_EQ(walls, 3);
}

TEST(OccOrientation, FusedBoss) {
  const Model m = boss_model();
  check_planar_loops(m);
  for (const auto& s : m.surfaces()) {
    if (s.geometry->type() != geom::SurfaceType::Cylinder) continue;
    const Vec2 uv = uv_centre(s);
    const Vec3 p = s.geometry->point(uv);
    const Vec3 radial = Vec3(p.x(), p.y(), 0).normalized();
    EXPECT_NEAR(radial.dot(m.outward_normal(s.id, 1, uv)), 1.0, 1e-9);
  }
}

TEST(OccOrientation, ImprintedNeighboursSeeOppositeNormals) {
  const Model m = two_bricks_model();
  check_planar_loops(m);
  EXPECT_NEAR(planar_divergence_volume(m, 1), 4.0, 1e-9);
  EXPECT_NEAR(planar_divergence_volume(m, 2), 1.0, 1e-9);
  for (const auto& s : m.surfaces()) {
    if (s.volumes.size() != 2) continue;
    const Vec2 uv = uv_centre(s);
    EXPECT_NEAR(m.outward_normal(s.id, 1, uv).z(), 1.0, 1e-12);  // up, out of the lower brick
    EXPECT_NEAR(m.outward_normal(s.id, 2, uv).z(), -1.0, 1e-12);
  }
}

TEST(OccOrientation, CurveUsesChainHeadToTail) {
  // validate() checks closure; check here that the chained points really
  // meet in space too, for a model with seams and circles.
  const Model m = boss_model();
  for (const auto& s : m.surfaces())
    for (const auto& loop : s.loops)
      for (size_t i = 0; i < loop.uses.size(); ++i) {
        const auto& a = loop.uses[i];
        const auto& b = loop.uses[(i + 1) % loop.uses.size()];
        const auto& ga = *m.curve(a.curve).geometry;
        const auto& gb = *m.curve(b.curve).geometry;
        const Vec3 end =
            ga.point(a.sense == geom::Sense::Forward ? ga.range().second : ga.range().first);
        const Vec3 start =
            gb.point(b.sense == geom::Sense::Forward ? gb.range().first : gb.range().second);
        EXPECT_LT((end - start).norm(), 1e-7);
      }
}

}  // namespace
}  // namespace cooperage::occ::test
