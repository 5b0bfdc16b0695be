// Tight face boxes (face_box.cpp) checked against boxes worked out by hand
// (sphere pieces, whose extremes lie inside a face or on its cut circle; a
// cone frustum), against the part turned a quarter about each axis (the
// turned part's boxes are the turned boxes, so a coordinate whose extremes
// are whole circles on a torus and one whose extremes are single points
// check each other), and by cutting: the pieces of a part together have the
// part's box.
#include "framework/geometry/occ/solid_pieces.h"

#include "support/real_cad.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace cooperage::occ {
namespace {

using geom::BoundingBox;
using geom::Vec2;

void expect_box(const BoundingBox& got, const Vec3& lo, const Vec3& hi, double tol,
                const std::string& what) {
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(got.min[i], lo[i], tol) << what << " min " << i;
    EXPECT_NEAR(got.max[i], hi[i], tol) << what << " max " << i;
  }
}

// One side of a sphere (centre c, radius r) cut by the plane through q with
// unit normal n; `above` the side n points to. Per axis: the pole when it
// lies on that side, else the extreme of the cut circle.
BoundingBox sphere_side_box(const Vec3& c, double r, const Vec3& q, const Vec3& n, bool above) {
  const double d = (c - q).dot(n);  // signed distance of the centre
  const Vec3 foot = c - d * n;
  const double rho = std::sqrt(r * r - d * d);
  BoundingBox b;
  Vec3 lo, hi;
  for (int i = 0; i < 3; ++i) {
    const double reach = rho * std::sqrt(std::max(0.0, 1.0 - n[i] * n[i]));
    const auto on_side = [&](double s) {  // the pole c + s r e_i
      const double h = d + s * r * n[i];
      return above ? h >= 0 : h <= 0;
    };
    lo[i] = on_side(-1) ? c[i] - r : foot[i] - reach;
    hi[i] = on_side(1) ? c[i] + r : foot[i] + reach;
  }
  b.add(lo);
  b.add(hi);
  return b;
}

TEST(FaceBox, APlaneCutsASphereIntoTwoPiecesWithTheirExactBoxes) {
  const Vec3 c(1.0, -2.0, 0.5);
  const double r = 2.0;
  for (const Vec3& normal : {Vec3(0, 0, 1), Vec3(1, 1, 1), Vec3(0.3, -1, 0.2)}) {
    const Vec3 n = normal.normalized();
    const Vec3 q = c + 0.9 * n + Vec3(0.1, 0.05, -0.02).cross(n);  // off centre, 0.9 from it
    Workbench bench;
    bench.sphere("s", c, r);
    const SolidPieces cut = SolidPieces::of(bench).split(0, {CutSurface::Kind::Plane, q, n, 0});
    ASSERT_EQ(cut.size(), 2);
    const geom::Model m = cut.build_model(false);
    int spheres = 0;
    for (const auto& s : m.surfaces()) {
      if (s.geometry->type() != geom::SurfaceType::Sphere) continue;
      ++spheres;
      // Which side: the face's area centroid.
      const bool above = (*s.centroid - q).dot(n) > 0;
      const BoundingBox want = sphere_side_box(c, r, q, n, above);
      expect_box(s.box, want.min, want.max, 1e-7, "surface " + std::to_string(s.id));
    }
    EXPECT_EQ(spheres, 2);
  }
}

TEST(FaceBox, AConeFrustumCutAcrossHasTheRadiiOfItsEnds) {
  Workbench bench;
  bench.cone("k", {0, 0, 0}, {0, 0, 1}, 2.0, 1.0, 3.0);
  const SolidPieces cut =
      SolidPieces::of(bench).split(0, {CutSurface::Kind::Plane, {0, 0, 1}, {0, 0, 1}, 0});
  ASSERT_EQ(cut.size(), 2);
  const geom::Model m = cut.build_model(false);
  int cones = 0;
  for (const auto& s : m.surfaces()) {
    if (s.geometry->type() != geom::SurfaceType::Cone) continue;
    ++cones;
    const double r1 = 2.0 - 1.0 / 3.0;  // the radius at z = 1
    if (s.centroid->z() < 1.0)
      expect_box(s.box, {-2, -2, 0}, {2, 2, 1}, 1e-7, "lower cone");
    else
      expect_box(s.box, {-r1, -r1, 1}, {r1, r1, 3}, 1e-7, "upper cone");
  }
  EXPECT_EQ(cones, 2);
}

// A torus (R 3, r 1) about a tilted axis, cut across by planes: every piece's
// torus faces together have the whole torus's box, which is known: per
// axis, the centre +- (R |sin| + r), with the angle between axis and
// coordinate axis. The tube's outermost points lie inside the faces, away
// from every edge.
TEST(FaceBox, PiecesOfATiltedTorusTogetherHaveItsBox) {
  const Vec3 c(0.5, -1.0, 2.0);
  const Vec3 axis = Vec3(0.2, 0.4, 1.0).normalized();
  const double R = 3.0, r = 1.0;
  Vec3 reach;
  for (int i = 0; i < 3; ++i) reach[i] = R * std::sqrt(1.0 - axis[i] * axis[i]) + r;
  for (const Vec3& normal : {Vec3(0, 0, 1), Vec3(1, -1, 0.5)}) {
    Workbench bench;
    bench.torus("t", c, axis, R, r);
    const SolidPieces whole = SolidPieces::of(bench);
    const geom::Model one = whole.build_model(false);
    ASSERT_EQ(one.surfaces().size(), 1u);
    expect_box(one.surface(1).box, c - reach, c + reach, 1e-7, "the whole torus");
    const SolidPieces cut =
        whole.split(0, {CutSurface::Kind::Plane, c + Vec3(0.3, 0.2, 0.1), normal.normalized(), 0});
    ASSERT_EQ(cut.size(), 2);
    const geom::Model m = cut.build_model(false);
    BoundingBox together;
    int tori = 0;
    for (const auto& s : m.surfaces()) {
      if (s.geometry->type() != geom::SurfaceType::Torus) continue;
      ++tori;
      together.add(s.box);
    }
    EXPECT_GE(tori, 2);
    expect_box(together, c - reach, c + reach, 1e-6, "the torus pieces together");
  }
}

// The highest point of a B-spline face over its whole parameter box, by
// dense sampling refined by a shrinking pattern search (shares no code
// with face_box.cpp).
double highest(const geom::SurfaceGeometry& g) {
  const auto [u, v] = g.uv_bounds();
  const int n = 200;
  double best = -1e300;
  Vec2 at(u.x(), v.x());
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      const Vec2 q(u.x() + (u.y() - u.x()) * i / n, v.x() + (v.y() - v.x()) * j / n);
      const double z = g.point(q).z();
      if (z > best) best = z, at = q;
    }
  Vec2 step((u.y() - u.x()) / n, (v.y() - v.x()) / n);
  for (int it = 0; it < 60; ++it, step *= 0.5) {
    for (const Vec2& d : {Vec2(1, 0), Vec2(-1, 0), Vec2(0, 1), Vec2(0, -1)}) {
      Vec2 q = at + Vec2(d.x() * step.x(), d.y() * step.y());
      q.x() = std::clamp(q.x(), u.x(), u.y());
      q.y() = std::clamp(q.y(), v.x(), v.y());
      const double z = g.point(q).z();
      if (z > best) best = z, at = q;
    }
  }
  return best;
}

// A B-spline slab with a bump inside its top face: the face's top is the
// bump's peak, off every edge. Cut through the bump, the two top pieces
// together reach it too (one of them holds the peak inside or on the cut).
TEST(FaceBox, ABSplineBumpIsInsideItsFacesBox) {
  std::vector<std::vector<Vec3>> grid;
  for (int i = 0; i <= 4; ++i) {
    grid.emplace_back();
    for (int j = 0; j <= 4; ++j)
      grid.back().push_back({1.0 * i, 1.0 * j, (i == 2 && j == 1) ? 1.5 : 0.1 * i});
  }
  Workbench bench;
  bench.bspline_patch("slab", grid, -0.5);
  const SolidPieces whole = SolidPieces::of(bench);
  const geom::Model m = whole.build_model(false);
  const geom::Surface* top = nullptr;
  for (const auto& s : m.surfaces())
    if (s.geometry->type() == geom::SurfaceType::BSpline &&
        (!top || s.box.max.z() > top->box.max.z()))
      top = &s;
  ASSERT_NE(top, nullptr);
  const double peak = highest(*top->geometry);
  EXPECT_GT(peak, 1.4);
  // The kernel's edge boxes carry its confusion distance (1e-7) as a gap.
  EXPECT_NEAR(top->box.max.z(), peak, 1e-6);
  // Across the bump's ridge, through its peak's x.
  const SolidPieces cut =
      whole.split(0, {CutSurface::Kind::Plane, {2.0, 0.8, 0.0}, {0.3, 1.0, 0.0}, 0});
  ASSERT_EQ(cut.size(), 2);
  const geom::Model pieces = cut.build_model(false);
  double highest_piece = -1e300;
  for (const auto& s : pieces.surfaces())
    if (s.geometry->type() == geom::SurfaceType::BSpline)
      highest_piece = std::max(highest_piece, s.box.max.z());
  EXPECT_NEAR(highest_piece, peak, 1e-6);
}

// A quarter turn about axis `k` maps a box exactly onto another box.
BoundingBox turned(const BoundingBox& b, int k) {
  const int i = (k + 1) % 3, j = (k + 2) % 3;  // (i, j) -> (-j, i)
  Vec3 lo = b.min, hi = b.max;
  lo[i] = -b.max[j];
  hi[i] = -b.min[j];
  lo[j] = b.min[i];
  hi[j] = b.max[i];
  BoundingBox out;
  out.add(lo);
  out.add(hi);
  return out;
}

geom::Model real_part(const std::string& file, double turn_about = -1) {
  Workbench bench;
  bench.import_file("p", testing::real_cad(file));
  if (turn_about >= 0) {
    Vec3 axis = Vec3::Zero();
    axis[static_cast<int>(turn_about)] = 1.0;
    bench.rotate("p", Vec3::Zero(), axis, 90.0);
  }
  return bench.build_model();
}

TEST(FaceBox, APartTurnedAQuarterHasItsFacesBoxesTurned) {
  const std::string file = "occt_bottle.brep";  // tori, spheres, cylinders, planes
  if (!std::filesystem::exists(testing::real_cad(file)))
    GTEST_SKIP() << testing::real_cad(file) << " is absent (../shared/real-cad)";
  const geom::Model part = real_part(file);
  const double tol = 1e-9 * part.box().diagonal();
  int tori = 0;
  for (const auto& s : part.surfaces()) tori += s.geometry->type() == geom::SurfaceType::Torus;
  EXPECT_GE(tori, 4);
  for (int k = 0; k < 3; ++k) {
    const geom::Model moved = real_part(file, k);
    ASSERT_EQ(moved.surfaces().size(), part.surfaces().size());
    for (const auto& s : part.surfaces()) {
      const BoundingBox want = turned(s.box, k);
      expect_box(moved.surface(s.id).box, want.min, want.max, tol,
                 "surface " + std::to_string(s.id) + " turned about axis " + std::to_string(k));
    }
  }
}

TEST(FaceBox, PiecesOfAPartTogetherHaveThePartsBox) {
  const std::string file = "occt_bottle.brep";
  if (!std::filesystem::exists(testing::real_cad(file)))
    GTEST_SKIP() << testing::real_cad(file) << " is absent (../shared/real-cad)";
  Workbench bench;
  bench.import_file("p", testing::real_cad(file));
  const SolidPieces whole = SolidPieces::of(bench);
  const geom::Model part = whole.build_model(false);
  // The cut's edges are fitted B-splines, within ~1e-7 of the surfaces; a
  // torus extreme missed would be off by a good part of a fillet's radius.
  const double tol = 1e-6 * part.box().diagonal();
  // Planes through the middle of each torus face, across each axis: they
  // split the fillets, whose pieces' extremes then lie on the cut or inside.
  int cuts = 0;
  for (const auto& s : part.surfaces()) {
    if (s.geometry->type() != geom::SurfaceType::Torus) continue;
    for (int axis : {0, 2}) {
      Vec3 n = Vec3::Zero();
      n[axis] = 1.0;
      const SolidPieces cut =
          whole.split(0, {CutSurface::Kind::Plane, 0.5 * (s.box.min + s.box.max), n, 0});
      if (cut.size() < 2) continue;
      ++cuts;
      const geom::Model m = cut.build_model(false);
      BoundingBox together;
      for (const auto& v : m.volumes()) together.add(v.box);
      expect_box(
          together, part.box().min, part.box().max, tol,
          "cut across axis " + std::to_string(axis) + " through surface " + std::to_string(s.id));
    }
  }
  EXPECT_GE(cuts, 4);
}

}  // namespace
}  // namespace cooperage::occ
