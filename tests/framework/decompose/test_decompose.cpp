// decompose.h: the search of cuts, with a stand-in volume scheme that
// applies to boxes only (six planar four-sided faces), so the search is
// tested apart from the real schemes' reach; and with the built-in schemes
// on Blacker 1996's Fig. 3a, which no scheme takes whole.
#include "framework/decompose/decompose.h"

#include "framework/core/error.h"
#include "framework/decompose/piece_verdict.h"
#include "framework/decompose/surface_fit.h"
#include "framework/decompose/volume_samples.h"
#include "framework/geometry/occ/solid_pieces.h"
#include "framework/geometry/occ/workbench.h"
#include "schemes/builtin_schemes.h"
#include "support/paper_parts.h"
#include "support/rigid_motion.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>

namespace cooperage::decompose {
namespace {

// Applies to a volume bounded by six planar faces of one four-curve loop.
class BoxScheme final : public scheme::VolumeScheme {
 public:
  std::string_view name() const override { return "box"; }
  scheme::Applicability applicable(const scheme::VolumeView& view) const override {
    const auto surfaces = view.model.surfaces_of(view.volume_id);
    if (surfaces.size() != 6) return scheme::Applicability::no("not six faces");
    for (int s : surfaces) {
      const auto& f = view.model.surface(s);
      if (f.geometry->type() != geom::SurfaceType::Plane || f.loops.size() != 1 ||
          f.loops[0].uses.size() != 4)
        return scheme::Applicability::no("surface " + std::to_string(s) + " is no rectangle");
    }
    return scheme::Applicability::yes(1.0);
  }
  void constrain(const scheme::VolumeView&, intervals::IntervalProblem&) const override {}
  scheme::SurfaceRoles roles(const scheme::VolumeView&) const override { return {}; }
  scheme::EntityMesh mesh(const scheme::VolumeView&, const scheme::MeshParams&) const override {
    return {};
  }
};

ModelCheck always_plans() {
  return [](const geom::Model&, bool) { return std::string(); };
}

Decomposed run(const occ::Workbench& bench, const scheme::Registry& registry, double size,
               const ModelCheck& check = always_plans(), int max_cuts = 80) {
  DecomposeOptions options;
  options.size = size;
  options.max_cuts = max_cuts;
  return decompose(occ::SolidPieces::of(bench), bench.build_model(), registry, check, options);
}

class Boxes : public ::testing::Test {
 protected:
  void SetUp() override { registry_.add(std::make_unique<BoxScheme>()); }
  scheme::Registry registry_;
};

double total_volume(const geom::Model& m) {
  double v = 0;
  for (const auto& vol : m.volumes()) v += vol.volume;
  return v;
}

// A T-shaped profile extruded along z: three boxes at least.
void tee(occ::Workbench& bench) {
  bench.prism("t",
              {{-3, 0, 0},
               {3, 0, 0},
               {3, 1, 0},
               {0.5, 1, 0},
               {0.5, 4, 0},
               {-0.5, 4, 0},
               {-0.5, 1, 0},
               {-3, 1, 0}},
              {}, {0, 0, 1});
}

TEST_F(Boxes, AnLPrismIsCutIntoThreeBoxes) {
  // One cut leaves a piece whose cut face and the coplanar face beside it
  // are two faces (seven in all): that piece is cut again.
  occ::Workbench bench;
  bench.prism("l", {{0, 0, 0}, {3, 0, 0}, {3, 1, 0}, {1, 1, 0}, {1, 3, 0}, {0, 3, 0}}, {},
              {0, 0, 1});
  const Decomposed d = run(bench, registry_, 0.25);
  ASSERT_EQ(d.report.volumes.size(), 1u);
  const auto& v = d.report.volumes[0];
  ASSERT_EQ(v.cuts.size(), 2u);
  EXPECT_EQ(v.cuts[0].pieces, 2);
  EXPECT_EQ(v.cuts[0].depth, 0);
  EXPECT_EQ(v.cuts[1].depth, 1);
  EXPECT_NEAR(v.cuts[0].thinnest, 1.0, 1e-9);
  EXPECT_EQ(v.pieces, (std::vector<int>{1, 2, 3}));
  EXPECT_EQ(d.model.volumes().size(), 3u);
  EXPECT_NEAR(total_volume(d.model), 5.0, 1e-9);
  EXPECT_TRUE(unmeshable_volumes(d.model, registry_).empty());
  // The boxes share the cut faces (imprinted and merged).
  int shared = 0;
  for (const auto& s : d.model.surfaces()) shared += s.volumes.size() == 2 ? 1 : 0;
  EXPECT_EQ(shared, 2);
}

TEST_F(Boxes, ATeeIsCutIntoFourBoxes) {
  occ::Workbench bench;
  tee(bench);
  const Decomposed d = run(bench, registry_, 0.25);
  ASSERT_EQ(d.report.volumes.size(), 1u);
  const auto& v = d.report.volumes[0];
  EXPECT_EQ(v.cuts.size(), 3u);
  EXPECT_EQ(d.model.volumes().size(), 4u);
  EXPECT_NEAR(total_volume(d.model), 9.0, 1e-9);
  EXPECT_TRUE(unmeshable_volumes(d.model, registry_).empty());
  EXPECT_GE(v.tried, 3);
}

TEST_F(Boxes, ARigidMotionGivesTheSameCuts) {
  occ::Workbench a, b;
  tee(a);
  tee(b);
  const auto motion = testing::RigidMotion::random(17);
  motion.apply(b, "t");
  const Decomposed da = run(a, registry_, 0.25), db = run(b, registry_, 0.25);
  const auto& ca = da.report.volumes.at(0).cuts;
  const auto& cb = db.report.volumes.at(0).cuts;
  ASSERT_EQ(ca.size(), cb.size());
  for (size_t k = 0; k < ca.size(); ++k) {
    EXPECT_EQ(ca[k].through.substr(0, ca[k].through.find(" along")),
              cb[k].through.substr(0, cb[k].through.find(" along")));
    // The moved cut is the cut of the moved part.
    EXPECT_NEAR(signed_distance(cb[k].surface, motion.apply(ca[k].surface.origin)), 0.0, 1e-7);
    EXPECT_NEAR(std::abs(cb[k].surface.direction.normalized().dot(
                    motion.apply(ca[k].surface.direction) - motion.apply(geom::Vec3::Zero()))),
                1.0, 1e-9);
  }
  ASSERT_EQ(da.model.volumes().size(), db.model.volumes().size());
  for (size_t k = 0; k < da.model.volumes().size(); ++k)
    EXPECT_NEAR(da.model.volumes()[k].volume, db.model.volumes()[k].volume, 1e-7);
}

TEST_F(Boxes, NoPieceThinnerThanOneElementLayer) {
  occ::Workbench bench;
  bench.prism("l", {{0, 0, 0}, {3, 0, 0}, {3, 1, 0}, {1, 1, 0}, {1, 3, 0}, {0, 3, 0}}, {},
              {0, 0, 1});
  // Both cuts leave a piece 1 thick: at size 1.5 neither is allowed.
  try {
    run(bench, registry_, 1.5);
    FAIL() << "expected a refusal";
  } catch (const MeshingError& e) {
    EXPECT_EQ(e.code(), ErrorCode::NotApplicable);
    EXPECT_EQ(e.entity().id, 1);
    const std::string what = e.what();
    EXPECT_NE(what.find("tried 0 cuts"), std::string::npos) << what;
    EXPECT_NE(what.find("one element layer"), std::string::npos) << what;
    // What to do: the size at which the thickest cut is allowed.
    EXPECT_NE(what.find("a size of at most 1 lets it cut"), std::string::npos) << what;
    EXPECT_NE(what.find("box: not six faces"), std::string::npos) << what;
  }
}

TEST_F(Boxes, ACutThatDoesNotPlanIsNotTaken) {
  occ::Workbench bench;
  bench.prism("l", {{0, 0, 0}, {3, 0, 0}, {3, 1, 0}, {1, 1, 0}, {1, 3, 0}, {0, 3, 0}}, {},
              {0, 0, 1});
  const ModelCheck never = [](const geom::Model&, bool) {
    return std::string("the faces disagree");
  };
  try {
    run(bench, registry_, 0.25, never);
    FAIL() << "expected a refusal";
  } catch (const MeshingError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("does not plan: the faces disagree"), std::string::npos) << what;
  }
}

TEST_F(Boxes, TheSearchIsBoundedAndSaysWhatTheBestCutLeft) {
  occ::Workbench bench;
  tee(bench);
  try {
    run(bench, registry_, 0.25, always_plans(), /*max_cuts=*/1);
    FAIL() << "expected a refusal";
  } catch (const MeshingError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("tried 1 cut;"), std::string::npos) << what;
    EXPECT_NE(what.find("that no scheme meshes: box: "), std::string::npos) << what;
  }
}

TEST_F(Boxes, ASizeThatIsNotPositiveIsRefused) {
  occ::Workbench bench;
  tee(bench);
  EXPECT_THROW(run(bench, registry_, 0.0), MeshingError);
}

TEST_F(Boxes, OnlyTheVolumesWithoutASchemeAreCut) {
  occ::Workbench bench;
  bench.brick("b", {10, 0, 0}, {1, 1, 1});
  tee(bench);
  bench.brick("c", {20, 0, 0}, {1, 1, 1});
  const Decomposed d = run(bench, registry_, 0.25);
  ASSERT_EQ(d.report.volumes.size(), 1u);
  EXPECT_EQ(d.report.volumes[0].volume, 2);
  EXPECT_EQ(d.report.volumes[0].pieces, (std::vector<int>{2, 3, 4, 5}));
  EXPECT_EQ(d.report.origin, (std::vector<int>{1, 2, 2, 2, 2, 3}));
  EXPECT_EQ(d.model.volumes().size(), 6u);
  EXPECT_EQ(d.model.volume(1).name, "b");
  EXPECT_EQ(d.model.volume(2).name, "t.1");
  EXPECT_EQ(d.model.volume(6).name, "c");
}

// Applies to a convex volume of at most seven planar faces: a box, or a box
// whose one face is split where two neighbours meet on it. Imprinting more
// neighbours on a face takes the scheme away, as a conflict between the
// pieces of neighbouring cuts takes a real sweep's.
class ConvexScheme final : public scheme::VolumeScheme {
 public:
  std::string_view name() const override { return "convex"; }
  scheme::Applicability applicable(const scheme::VolumeView& view) const override {
    const auto surfaces = view.model.surfaces_of(view.volume_id);
    if (surfaces.size() > 7) return scheme::Applicability::no("more than seven faces");
    std::vector<geom::Vec3> points;
    for (int c : curves_of(view.model, view.volume_id)) {
      const auto& curve = view.model.curve(c);
      const auto [t0, t1] = curve.geometry->range();
      points.push_back(curve.geometry->point(t0));
      points.push_back(curve.geometry->point(t1));
    }
    for (int s : surfaces) {
      const auto plane = plane_of(view.model.surface(s));
      if (!plane) return scheme::Applicability::no("surface " + std::to_string(s) + " is curved");
      double lo = 0, hi = 0;
      for (const auto& p : points) {
        lo = std::min(lo, plane->normal.dot(p - plane->point));
        hi = std::max(hi, plane->normal.dot(p - plane->point));
      }
      if (lo < -1e-9 && hi > 1e-9) return scheme::Applicability::no("not convex");
    }
    return scheme::Applicability::yes(1.0);
  }
  void constrain(const scheme::VolumeView&, intervals::IntervalProblem&) const override {}
  scheme::SurfaceRoles roles(const scheme::VolumeView&) const override { return {}; }
  scheme::EntityMesh mesh(const scheme::VolumeView&, const scheme::MeshParams&) const override {
    return {};
  }
};

// A two-step stair: no single cut leaves convex pieces. Of the first cut's
// partial pieces (the base, y < 1.2, and an L above it) the L has two cuts
// into convex pieces; the thicker one, x = 1, puts two pieces on the base,
// whose top then holds three faces (eight in all), so it does not plan with
// the base; the other one, y = 1.95, does.
TEST(DecomposeSearch, APieceWhoseBestCutConflictsWithItsNeighbourTakesTheNextCut) {
  scheme::Registry registry;
  registry.add(std::make_unique<ConvexScheme>());
  occ::Workbench bench;
  bench.prism("stair",
              {{0, 0, 0},
               {3, 0, 0},
               {3, 1.2, 0},
               {2, 1.2, 0},
               {2, 1.95, 0},
               {1, 1.95, 0},
               {1, 3, 0},
               {0, 3, 0}},
              {}, {0, 0, 1});
  // The planner's verdict: every piece keeps its scheme once imprinted.
  const ModelCheck conformal = [&](const geom::Model& m, bool) {
    const std::vector<int> lost = unmeshable_volumes(m, registry);
    return lost.empty() ? std::string()
                        : "volume " + std::to_string(lost.front()) + " lost its scheme";
  };
  DecomposeOptions options;
  options.size = 0.5;
  options.branches = 1;  // only the best first cut: its piece must find its own way
  const Decomposed d =
      decompose(occ::SolidPieces::of(bench), bench.build_model(), registry, conformal, options);
  ASSERT_EQ(d.report.volumes.size(), 1u);
  const auto& cuts = d.report.volumes[0].cuts;
  ASSERT_EQ(cuts.size(), 2u);
  EXPECT_EQ(cuts[1].depth, 1);
  // The second cut is the plane y = 1.95, not x = 1.
  EXPECT_NEAR(std::abs(cuts[1].surface.direction.normalized().y()), 1.0, 1e-9);
  EXPECT_NEAR(signed_distance(cuts[1].surface, {0.5, 1.95, 0.5}), 0.0, 1e-9);
  EXPECT_EQ(d.model.volumes().size(), 3u);
  EXPECT_NEAR(total_volume(d.model), 3.6 + 1.5 + 1.05, 1e-9);
  EXPECT_TRUE(conformal(d.model, false).empty()) << conformal(d.model, false);
}

// The built-in schemes: Fig. 3a is refused whole by every scheme, and the
// refusal of a decomposition that cannot work names them all, cooper's
// reason (which face stops the sweep) before the volume map's count of
// faces.
TEST(DecomposeBuiltin, Fig3aIsRefusedWholeAndTooCoarseASizeIsExplained) {
  scheme::Registry registry;
  register_builtin_schemes(registry);
  occ::Workbench bench;
  testing::build_fig3a(bench);
  EXPECT_EQ(unmeshable_volumes(bench.build_model(), registry), std::vector<int>{1});
  try {
    run(bench, registry, 2.5);
    FAIL() << "expected a refusal";
  } catch (const MeshingError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("map: "), std::string::npos) << what;
    EXPECT_NE(what.find("cooper: "), std::string::npos) << what;
    EXPECT_LT(what.find("cooper: "), what.find("map: ")) << what;
    EXPECT_NE(what.find("tried 0 cuts"), std::string::npos) << what;
  }
}

// A volume without a planar or cylindrical face gives the search nothing
// to cut along; the refusal says so, not that every cut is too thin.
TEST(DecomposeBuiltin, AVolumeWithoutPlanesOrCylindersHasNoCutToTry) {
  scheme::Registry registry;
  register_builtin_schemes(registry);
  occ::Workbench bench;
  bench.sphere("ball", {0, 0, 0}, 1.0);
  try {
    run(bench, registry, 0.2);
    FAIL() << "expected a refusal";
  } catch (const MeshingError& e) {
    EXPECT_EQ(e.code(), ErrorCode::NotApplicable);
    const std::string what = e.what();
    EXPECT_NE(what.find("tried 0 cuts; none of its faces is a plane, a cylinder or a torus to cut "
                        "along (1 sphere)"),
              std::string::npos)
        << what;
    EXPECT_EQ(what.find("element layer"), std::string::npos) << what;
  }
}

// A piece is answered as the selector would answer it: a brick is the
// volume map's in hexes (score 1 against cooper's 0.9), but in wedges or
// mixed elements only the schemes that make wedges count, and a refusal
// lists only theirs.
TEST(DecomposeBuiltin, InWedgesAPieceIsNotTheVolumeMaps) {
  scheme::Registry registry;
  register_builtin_schemes(registry);
  occ::Workbench bench;
  bench.brick("b", {0, 0, 0}, {2, 1, 1});
  const geom::Model brick = bench.build_model();
  occ::Workbench fig3a;
  testing::build_fig3a(fig3a);
  const geom::Model part = fig3a.build_model();
  for (const io::ElementKind kind :
       {io::ElementKind::Hex, io::ElementKind::Wedge, io::ElementKind::Mixed}) {
    io::MeshSettings job;
    job.size = 0.25;
    job.elements = kind;
    const scheme::Settings settings = scheme::Settings::of(job);
    const PieceVerdict b = best_scheme(brick, 1, registry, &settings);
    ASSERT_TRUE(b.ok);
    EXPECT_EQ(b.scheme, kind == io::ElementKind::Hex ? "map" : "cooper");
    const PieceVerdict p = best_scheme(part, 1, registry, &settings);
    ASSERT_FALSE(p.ok);
    EXPECT_EQ(p.why.find("map: ") != std::string::npos, kind == io::ElementKind::Hex) << p.why;
    EXPECT_NE(p.why.find("cooper: "), std::string::npos) << p.why;
  }
}

}  // namespace
}  // namespace cooperage::decompose
