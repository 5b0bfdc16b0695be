// SolidPieces (solid_pieces.h): cuts by planes and cylinders, checked by
// volumes (the pieces add up to the solid), shared cut faces and counts.
#include "framework/geometry/occ/solid_pieces.h"

#include "framework/core/error.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <thread>

namespace cooperage::occ {
namespace {

double total_volume(const geom::Model& m) {
  double v = 0;
  for (const auto& vol : m.volumes()) v += vol.volume;
  return v;
}

TEST(SolidPieces, ThePiecesOfAWorkbenchAreItsVolumesInOrder) {
  Workbench bench;
  bench.brick("a", {0, 0, 0}, {1, 1, 1});
  bench.brick("b", {1, 0, 0}, {2, 1, 1});
  const SolidPieces pieces = SolidPieces::of(bench);
  ASSERT_EQ(pieces.size(), 2);
  const geom::Model direct = bench.build_model();
  const geom::Model again = pieces.build_model(false);
  ASSERT_EQ(again.volumes().size(), 2u);
  EXPECT_EQ(again.surfaces().size(), direct.surfaces().size());
  EXPECT_NEAR(again.volume(2).volume, 2.0, 1e-9);
  EXPECT_EQ(again.volume(1).name, "a");
}

TEST(SolidPieces, APlaneSplitsABrickIntoTwoPiecesSharingTheCutFace) {
  Workbench bench;
  bench.brick("b", {0, 0, 0}, {4, 2, 1});
  const SolidPieces one = SolidPieces::of(bench);
  const SolidPieces cut = one.split(0, {CutSurface::Kind::Plane, {1, 0, 0}, {1, 0, 0}, 0});
  ASSERT_EQ(cut.size(), 2);
  const geom::Model m = cut.build_model(false);
  ASSERT_EQ(m.volumes().size(), 2u);
  EXPECT_NEAR(total_volume(m), 8.0, 1e-9);
  EXPECT_NEAR(std::min(m.volume(1).volume, m.volume(2).volume), 2.0, 1e-9);
  int shared = 0;
  for (const auto& s : m.surfaces()) shared += s.volumes.size() == 2 ? 1 : 0;
  EXPECT_EQ(shared, 1);
  EXPECT_EQ(m.volume(1).name, "b.1");
}

// Faces a cut leaves as they were keep their area and tight box from the
// thread's earlier builds (face_facts.cpp); a model built in a fresh thread,
// which remembers nothing, has the same areas and boxes, and so do the
// volumes' boxes (the union of their faces').
TEST(SolidPieces, RememberedFaceAreasAndBoxesEqualFreshOnes) {
  Workbench bench;
  bench.cylinder("c", {0, 0, 0}, {0, 0, 1}, 2.0, 3.0);
  const SolidPieces one = SolidPieces::of(bench);
  (void)one.build_model(false);  // the thread now knows the uncut faces
  const SolidPieces cut = one.split(0, {CutSurface::Kind::Plane, {0, 0, 1}, {0, 0, 1}, 0});
  ASSERT_EQ(cut.size(), 2);
  const geom::Model warm = cut.build_model(false);
  geom::Model fresh;
  std::thread([&] { fresh = cut.build_model(false); }).join();
  ASSERT_EQ(warm.surfaces().size(), fresh.surfaces().size());
  for (const auto& s : warm.surfaces()) {
    const auto& f = fresh.surface(s.id);
    EXPECT_EQ(s.area, f.area) << "surface " << s.id;
    EXPECT_EQ(s.box.min, f.box.min) << "surface " << s.id;
    EXPECT_EQ(s.box.max, f.box.max) << "surface " << s.id;
  }
  for (const auto& v : warm.volumes()) {
    EXPECT_EQ(v.box.min, fresh.volume(v.id).box.min);
    EXPECT_EQ(v.box.max, fresh.volume(v.id).box.max);
    // The uncut faces' remembered volume terms, the fresh ones alike.
    EXPECT_EQ(v.volume, fresh.volume(v.id).volume);
  }
  // Cut at z = 1 of 3: a third and two thirds of pi r^2 h.
  const double lower = std::min(warm.volume(1).volume, warm.volume(2).volume);
  EXPECT_NEAR(lower, M_PI * 4.0 * 1.0, 1e-9 * M_PI * 12.0);
  EXPECT_NEAR(total_volume(warm), M_PI * 4.0 * 3.0, 1e-9 * M_PI * 12.0);
  // The cylinder's tight box, not its control points' (a circle's B-spline
  // hull would reach past the radius).
  const geom::BoundingBox box = warm.volume(1).box;
  EXPECT_NEAR(box.max.x(), 2.0, 1e-6);
  EXPECT_NEAR(box.min.y(), -2.0, 1e-6);
}

// A face's projector is kept for the thread while the face lives on in later
// models (surface_geometry.cpp); what a model seen before projects equals
// what a fresh thread's model projects, whatever was asked before.
TEST(SolidPieces, ProjectionsOnAFaceSeenBeforeEqualFreshOnes) {
  Workbench bench;
  const auto square = [](double side, double z, double shift) {
    const double h = 0.5 * side;
    return std::vector<Vec3>{
        {-h + shift, -h, z}, {h + shift, -h, z}, {h + shift, h, z}, {-h + shift, h, z}};
  };
  bench.loft("l", {square(4, 0, 0), square(3, 2, 0.5), square(4, 4, 0)}, false);
  const SolidPieces one = SolidPieces::of(bench);
  const auto queries = [](const geom::Model& m, double offset) {
    std::vector<geom::SurfaceProjection> out;
    for (const auto& s : m.surfaces()) {
      const Vec3 c = 0.5 * (s.box.min + s.box.max);
      for (const Vec3& d :
           {Vec3(offset, 0, 0), Vec3(0, offset, 1), Vec3(-offset, 0.3, -1), Vec3(0, -offset, 2)})
        out.push_back(s.geometry->project(c + d));
    }
    return out;
  };
  (void)queries(one.build_model(false), 0.7);  // the thread's projectors answer these first
  const geom::Model again = one.build_model(false);
  const auto seen = queries(again, 1.3);
  geom::Model fresh_model;
  std::vector<geom::SurfaceProjection> fresh;
  std::thread([&] {
    fresh_model = one.build_model(false);
    fresh = queries(fresh_model, 1.3);
  }).join();
  ASSERT_EQ(seen.size(), fresh.size());
  ASSERT_GT(seen.size(), 20u);
  size_t bspline = 0;
  for (const auto& s : again.surfaces())
    bspline += s.geometry->type() == geom::SurfaceType::BSpline;
  EXPECT_GE(bspline, 4u);
  for (size_t k = 0; k < seen.size(); ++k) {
    EXPECT_EQ(seen[k].uv, fresh[k].uv) << k;
    EXPECT_EQ(seen[k].point, fresh[k].point) << k;
  }
}

TEST(SolidPieces, APlaneMissingTheSolidGivesOnePiece) {
  Workbench bench;
  bench.brick("b", {0, 0, 0}, {1, 1, 1});
  const SolidPieces cut =
      SolidPieces::of(bench).split(0, {CutSurface::Kind::Plane, {0, 0, 5}, {0, 0, 1}, 0});
  EXPECT_LT(cut.size(), 2);
}

TEST(SolidPieces, ACylinderCutsACoreOutOfABrick) {
  Workbench bench;
  bench.brick("b", {-2, -2, 0}, {4, 4, 1});
  const SolidPieces cut =
      SolidPieces::of(bench).split(0, {CutSurface::Kind::Cylinder, {0, 0, 0}, {0, 0, 1}, 1.0});
  ASSERT_EQ(cut.size(), 2);
  const geom::Model m = cut.build_model(false);
  const double core = std::min(m.volume(1).volume, m.volume(2).volume);
  EXPECT_NEAR(core, M_PI, 1e-6);
  EXPECT_NEAR(total_volume(m), 16.0, 1e-6);
}

TEST(SolidPieces, ReplacingASolidByItsPiecesKeepsTheOthersAndImprints) {
  Workbench bench;
  bench.brick("a", {0, 0, 0}, {2, 2, 1});
  bench.brick("b", {0, 0, 1}, {2, 2, 1});  // on top of a, sharing z = 1
  const SolidPieces all = SolidPieces::of(bench);
  const SolidPieces cut = all.split(0, {CutSurface::Kind::Plane, {1, 0, 0}, {1, 0, 0}, 0});
  const SolidPieces replaced = all.replace(0, cut);
  ASSERT_EQ(replaced.size(), 3);
  const geom::Model m = replaced.build_model(true);
  ASSERT_EQ(m.volumes().size(), 3u);
  EXPECT_EQ(m.volume(3).name, "b");
  // b's bottom face is imprinted by the cut: two faces, each shared.
  int shared = 0;
  for (const auto& s : m.surfaces()) shared += s.volumes.size() == 2 ? 1 : 0;
  EXPECT_EQ(shared, 3);  // the cut face and the two halves of z = 1
  EXPECT_NEAR(total_volume(m), 8.0, 1e-9);
}

// What decides the model: its volumes, faces, curves and the faces two
// volumes share.
struct Shape {
  size_t volumes, surfaces, curves;
  int shared;
  double volume;
};
Shape shape_of(const geom::Model& m) {
  int shared = 0;
  for (const auto& s : m.surfaces()) shared += s.volumes.size() == 2 ? 1 : 0;
  return {m.volumes().size(), m.surfaces().size(), m.curves().size(), shared, total_volume(m)};
}
void expect_same(const Shape& a, const Shape& b) {
  EXPECT_EQ(a.volumes, b.volumes);
  EXPECT_EQ(a.surfaces, b.surfaces);
  EXPECT_EQ(a.curves, b.curves);
  EXPECT_EQ(a.shared, b.shared);
  EXPECT_NEAR(a.volume, b.volume, 1e-9);
}

// A model glues pieces that only touch (build_model(true, true)); it
// must imprint as the full fuse does: a piece cut again whose cut ends
// inside a neighbour's face (b's bottom, split by the first cut and then
// by the second across one half), and an edge of a cut lying in it.
TEST(SolidPieces, AGluedModelOfTouchingPiecesImprintsAsTheFullFuse) {
  Workbench bench;
  bench.brick("a", {0, 0, 0}, {4, 4, 1});
  bench.brick("b", {0, 0, 1}, {4, 4, 1});
  const SolidPieces all = SolidPieces::of(bench);
  const SolidPieces halves = all.split(0, {CutSurface::Kind::Plane, {2, 0, 0}, {1, 0, 0}, 0});
  const SolidPieces once = all.replace(0, halves);
  const SolidPieces quarters =
      once.only(1).split(0, {CutSurface::Kind::Plane, {0, 1, 0}, {0, 1, 0}, 0});
  const SolidPieces twice = once.replace(1, quarters);
  ASSERT_EQ(twice.size(), 4);
  const Shape full = shape_of(twice.build_model(true));
  EXPECT_EQ(full.volumes, 4u);
  EXPECT_EQ(full.shared, 6);  // two cut faces, b's bottom in three, a's halves' cut face in two
  EXPECT_NEAR(full.volume, 32.0, 1e-9);
  expect_same(shape_of(twice.build_model(true, true)), full);
  // A cylinder cut of the top brick whose rim lies in the bottom's faces.
  const SolidPieces core =
      twice.only(3).split(0, {CutSurface::Kind::Cylinder, {1, 1, 0}, {0, 0, 1}, 0.5});
  const SolidPieces cored = twice.replace(3, core);
  expect_same(shape_of(cored.build_model(true, true)), shape_of(cored.build_model(true)));
}

// Solids imported without imprinting may overlap: a model fuses
// them in full, glue asked or not (glued, the overlap would be lost).
TEST(SolidPieces, OverlappingSolidsAreNeverGlued) {
  Workbench bench;
  bench.brick("a", {0, 0, 0}, {2, 2, 2});
  bench.brick("b", {1, 1, 1}, {2, 2, 2});
  BuildOptions separate;
  separate.imprint_merge = false;
  const SolidPieces all = SolidPieces::of(bench, separate);
  const Shape full = shape_of(all.build_model(true));
  EXPECT_EQ(full.volumes, 3u);  // a - b, a & b, b - a
  expect_same(shape_of(all.build_model(true, true)), full);
}

TEST(SolidPieces, AnIndexOutOfRangeIsAnError) {
  Workbench bench;
  bench.brick("a", {0, 0, 0}, {1, 1, 1});
  const SolidPieces all = SolidPieces::of(bench);
  EXPECT_THROW(all.only(1), MeshingError);
  EXPECT_THROW(all.split(-1, {}), MeshingError);
}

}  // namespace
}  // namespace cooperage::occ
