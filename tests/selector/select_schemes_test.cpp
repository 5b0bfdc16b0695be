// The selector: a-priori choices on models whose right answer follows from
// their shape, explained rejections, pins, invariance.
#include "framework/core/error.h"
#include "framework/geometry/occ/workbench.h"
#include "schemes/builtin_schemes.h"
#include "selector/select_schemes.h"
#include "support/mesh_checks.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <map>
#include <memory>
#include <random>
#include <set>

namespace cooperage::selector {
namespace {

using geom::Vec3;

struct Fixture {
  scheme::Registry registry;
  Fixture() { register_builtin_schemes(registry); }
};

io::MeshSettings sized(double size) {
  io::MeshSettings s;
  s.size = size;
  return s;
}

const Choice& volume(const Selection& s, int id) {
  return s.volumes.at(static_cast<size_t>(id - 1));
}

// A plate 10 x 6 x 1 with three square through holes, as a prism.
geom::Model plate_with_square_holes(occ::Workbench& bench) {
  std::vector<std::vector<Vec3>> holes;
  for (double x : {2.0, 5.0, 8.0}) {
    holes.push_back({{x - 0.5, 2.5, 0}, {x - 0.5, 3.5, 0}, {x + 0.5, 3.5, 0}, {x + 0.5, 2.5, 0}});
  }
  bench.prism("plate", {{0, 0, 0}, {10, 0, 0}, {10, 6, 0}, {0, 6, 0}}, holes, {0, 0, 1});
  return bench.build_model();
}

TEST(Selector, BrickGoesToVolumeMapWithEverySurfaceMapped) {
  occ::Workbench bench;
  bench.brick("b", {0, 0, 0}, {2, 3, 4});
  const geom::Model model = bench.build_model();
  Fixture f;
  const Selection s = select_schemes(model, f.registry, sized(0.5));
  EXPECT_EQ(volume(s, 1).scheme, "map");
  for (const auto& c : s.surfaces) {
    EXPECT_EQ(c.scheme, "map") << "surface " << c.id;
    EXPECT_TRUE(c.fixed_by_volume);
  }
  // cooper also applies to a brick, with a lower score.
  bool cooper_ok = false;
  for (const auto& k : volume(s, 1).candidates)
    cooper_ok |= k.scheme == "cooper" && k.applicability.ok;
  EXPECT_TRUE(cooper_ok);
}

TEST(Selector, PlateWithHolesGoesToCooperOneToOne) {
  occ::Workbench bench;
  const geom::Model model = plate_with_square_holes(bench);
  Fixture f;
  const Selection s = select_schemes(model, f.registry, sized(0.5));
  EXPECT_EQ(volume(s, 1).scheme, "cooper");
  int targets = 0, sources = 0;
  for (const auto& c : s.surfaces) {
    if (c.scheme == scheme::kMeshedByVolume) ++targets;
    if (model.surface(c.id).loops.size() == 4 && c.scheme != scheme::kMeshedByVolume) ++sources;
  }
  EXPECT_EQ(targets, 1);
  EXPECT_EQ(sources, 1);
  // The volume map says why it does not apply.
  for (const auto& k : volume(s, 1).candidates) {
    if (k.scheme == "map") {
      EXPECT_FALSE(k.applicability.ok);
      EXPECT_FALSE(k.applicability.why.empty());
    }
  }
}

TEST(Selector, PlateWithRoundHolesGoesToCooperOneToOneWithAPavedSource) {
  occ::Workbench bench;
  bench.brick("plate", {0, 0, 0}, {10, 6, 1});
  std::vector<std::string> inputs{"plate"};
  for (int i = 0; i < 3; ++i) {
    bench.cylinder("h" + std::to_string(i), {2.5 * (i + 1), 3, -1}, {0, 0, 1}, 0.8, 3);
    inputs.push_back("h" + std::to_string(i));
  }
  bench.cut("part", inputs);
  const geom::Model model = bench.build_model();
  Fixture f;
  const Selection s = select_schemes(model, f.registry, sized(0.25));
  EXPECT_EQ(volume(s, 1).scheme, "cooper");
  EXPECT_NE(volume(s, 1).candidates[1].applicability.why.find("one-barrel"), std::string::npos)
      << volume(s, 1).candidates[1].applicability.why;
  int paved = 0;
  for (const auto& c : s.surfaces) paved += c.scheme == "pave";
  EXPECT_EQ(paved, 1);  // the source cap; the target is projected
}

TEST(Selector, CylinderWithBossGoesToCooperManyToOne) {
  occ::Workbench bench;
  bench.cylinder("body", {0, 0, 0}, {0, 0, 1}, 2.0, 3.0);
  bench.cylinder("boss", {0, 0, 3}, {0, 0, 1}, 1.0, 1.5);
  bench.fuse("part", {"body", "boss"});
  const geom::Model model = bench.build_model();
  Fixture f;
  const Selection s = select_schemes(model, f.registry, sized(0.25));
  EXPECT_EQ(volume(s, 1).scheme, "cooper");
  const auto& why = volume(s, 1).candidates[1].applicability.why;
  EXPECT_NE(why.find("many-to-one"), std::string::npos) << why;
  // Many-to-one ranks below one-to-one sweeps.
  EXPECT_LT(volume(s, 1).candidates[1].applicability.score, 0.5);
}

TEST(Selector, LShapedPlanarFaceGoesToSubmap) {
  occ::Workbench bench;
  bench.prism("l", {{0, 0, 0}, {3, 0, 0}, {3, 1, 0}, {1, 1, 0}, {1, 3, 0}, {0, 3, 0}}, {},
              {0, 0, 1});
  const geom::Model model = bench.build_model();
  Fixture f;
  SelectOptions surfaces_only;
  surfaces_only.dim = 2;
  const Selection s = select_schemes(model, f.registry, sized(0.5), surfaces_only);
  int submapped = 0;
  for (const auto& c : s.surfaces) {
    if (model.surface(c.id).loops[0].uses.size() == 6) {
      EXPECT_EQ(c.scheme, "submap") << "surface " << c.id;
      ++submapped;
      for (const auto& k : c.candidates) {
        if (k.scheme == "map") {
          EXPECT_FALSE(k.applicability.ok);  // 5 ENDs and a CORNER
        }
      }
    } else {
      EXPECT_EQ(c.scheme, "map") << "surface " << c.id;
    }
  }
  EXPECT_EQ(submapped, 2);
}

// The bottom cap of a prism along z (flat in z, at z = 0).
const Choice* bottom_cap(const Selection& s, const geom::Model& m) {
  for (const auto& c : s.surfaces) {
    const auto& box = m.surface(c.id).box;
    if (std::abs(box.max.z()) < 1e-9 && std::abs(box.min.z()) < 1e-9) return &c;
  }
  return nullptr;
}

TEST(Selector, DiskGoesToPave) {
  occ::Workbench bench;
  bench.cylinder("c", {0, 0, 0}, {0, 0, 1}, 1.0, 1.0);
  const geom::Model model = bench.build_model();
  Fixture f;
  SelectOptions surfaces_only;
  surfaces_only.dim = 2;
  const Selection s = select_schemes(model, f.registry, sized(0.2), surfaces_only);
  int disks = 0;
  for (const auto& c : s.surfaces) {
    if (model.surface(c.id).geometry->type() != geom::SurfaceType::Plane) continue;
    EXPECT_EQ(c.scheme, "pave") << "surface " << c.id;
    for (const auto& k : c.candidates) {
      if (k.scheme == "map" || k.scheme == "submap") {
        EXPECT_FALSE(k.applicability.ok) << k.scheme;  // a disk has no corners
      }
    }
    ++disks;
  }
  EXPECT_EQ(disks, 2);
}

TEST(Selector, AFaceMappableOnlyBySquashingA170DegreeCornerGoesToPave) {
  // A triangle with one edge bent by 10 degrees: three real corners and a
  // 170-degree vertex. Submap can meet the sum rule only by making the
  // 170-degree vertex an END (a quad corner of 170 degrees, scaled Jacobian
  // sin 170 = 0.17); pave does better.
  occ::Workbench bench;
  const double bend = 0.5 * std::tan(5.0 * M_PI / 180.0) * 4.0;
  bench.prism("t", {{0, 0, 0}, {2, -bend, 0}, {4, 0, 0}, {2, 3, 0}}, {}, {0, 0, 1});
  const geom::Model model = bench.build_model();
  Fixture f;
  SelectOptions surfaces_only;
  surfaces_only.dim = 2;
  const Selection s = select_schemes(model, f.registry, sized(0.25), surfaces_only);
  const Choice* cap = bottom_cap(s, model);
  ASSERT_NE(cap, nullptr);
  EXPECT_EQ(cap->scheme, "pave");
  // A rectangle still goes to map, and a mildly skewed quadrilateral too.
  occ::Workbench quad;
  quad.prism("q", {{0, 0, 0}, {4, 0, 0}, {4.8, 3, 0}, {0.8, 3, 0}}, {}, {0, 0, 1});
  const geom::Model qm = quad.build_model();
  const Selection qs = select_schemes(qm, f.registry, sized(0.25), surfaces_only);
  for (const auto& c : qs.surfaces) EXPECT_EQ(c.scheme, "map") << "surface " << c.id;
}

TEST(Selector, InfeasibleAutomaticChoiceIsRelaxedAndReported) {
  // Pinned counts 3 and 5 on opposite sides of a rectangle: map and submap
  // both need them equal; pave needs only an even total. The automatic
  // choice is relaxed map -> submap -> pave and every step is reported.
  occ::Workbench bench;
  bench.brick("b", {0, 0, 0}, {1, 1, 1});
  const geom::Model model = bench.build_model();
  io::MeshSettings settings = sized(0.25);
  io::CurveSetting a, b;
  a.id = 1;
  a.sizing.intervals = 3;
  b.id = 3;
  b.sizing.intervals = 5;
  settings.curves = {a, b};
  Fixture f;
  SelectOptions surfaces_only;
  surfaces_only.dim = 2;
  const Selection s = select_schemes(model, f.registry, settings, surfaces_only);
  ASSERT_FALSE(s.relaxations.empty());
  int paved = 0;
  for (const auto& c : s.surfaces) {
    if (c.scheme == "pave") {
      ++paved;
      EXPECT_NE(c.reason.find("relaxed"), std::string::npos) << c.reason;
    }
  }
  EXPECT_GE(paved, 1);
  EXPECT_NE(s.relaxations.front().find("map -> submap"), std::string::npos)
      << s.relaxations.front();
  // Deterministic: the same relaxations again.
  EXPECT_EQ(select_schemes(model, f.registry, settings, surfaces_only).relaxations, s.relaxations);
}

TEST(Selector, SphereHasNoHexSchemeAndEverySchemeSaysWhy) {
  occ::Workbench bench;
  bench.sphere("s", {0, 0, 0}, 1);
  const geom::Model model = bench.build_model();
  Fixture f;
  try {
    select_schemes(model, f.registry, sized(0.2));
    FAIL() << "a sphere got a scheme";
  } catch (const MeshingError& e) {
    EXPECT_EQ(e.code(), ErrorCode::NotApplicable);
    const std::string what = e.what();
    EXPECT_NE(what.find("no hex scheme applies"), std::string::npos) << what;
    EXPECT_NE(what.find("map:"), std::string::npos) << what;
    EXPECT_NE(what.find("cooper:"), std::string::npos) << what;
  }
}

TEST(Selector, PinnedVolumeSchemeIsObeyedOrRejectedWithItsReason) {
  occ::Workbench bench;
  bench.brick("b", {0, 0, 0}, {1, 1, 1});
  const geom::Model model = bench.build_model();
  io::MeshSettings settings = sized(0.25);
  io::VolumeSetting pin;
  pin.id = 1;
  pin.scheme = "cooper";
  pin.where = {"job.xml", 7, "volume"};
  settings.volumes.push_back(pin);
  Fixture f;
  const Selection s = select_schemes(model, f.registry, settings);
  EXPECT_EQ(volume(s, 1).scheme, "cooper");
  EXPECT_TRUE(volume(s, 1).pinned);
  EXPECT_NE(volume(s, 1).reason.find("job.xml:7"), std::string::npos);

  occ::Workbench ball;
  ball.sphere("s", {0, 0, 0}, 1);
  const geom::Model sphere = ball.build_model();
  settings.volumes[0].scheme = "map";
  try {
    select_schemes(sphere, f.registry, settings);
    FAIL();
  } catch (const MeshingError& e) {
    EXPECT_NE(std::string(e.what()).find("job.xml:7"), std::string::npos) << e.what();
  }
}

TEST(Selector, ContradictoryPinsNameBoth) {
  occ::Workbench bench;
  bench.brick("b", {0, 0, 0}, {1, 1, 1});
  const geom::Model model = bench.build_model();
  io::MeshSettings settings = sized(0.25);
  io::VolumeSetting v;
  v.id = 1;
  v.scheme = "map";
  v.where = {"job.xml", 5, "volume"};
  settings.volumes.push_back(v);
  io::SurfaceSetting s;
  s.id = 1;
  s.scheme = "submap";
  s.where = {"job.xml", 6, "surface"};
  settings.surfaces.push_back(s);
  Fixture f;
  try {
    select_schemes(model, f.registry, settings);
    FAIL() << "contradictory pins were accepted";
  } catch (const MeshingError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("job.xml:6"), std::string::npos) << what;
    EXPECT_NE(what.find("volume 1 (map)"), std::string::npos) << what;
  }
}

TEST(Selector, PinnedHardCountsThatConflictAreReportedNotRelaxed) {
  occ::Workbench bench;
  bench.brick("b", {0, 0, 0}, {1, 1, 1});
  const geom::Model model = bench.build_model();
  io::MeshSettings settings = sized(0.25);
  // Curves 1 and 3 are opposite sides of a brick face.
  io::CurveSetting a, b;
  a.id = 1;
  a.sizing.intervals = 3;
  b.id = 3;
  b.sizing.intervals = 5;
  settings.curves = {a, b};
  Fixture f;
  try {
    select_schemes(model, f.registry, settings);
    FAIL();
  } catch (const MeshingError& e) {
    EXPECT_EQ(e.code(), ErrorCode::Infeasible);
    EXPECT_NE(std::string(e.what()).find("no automatic scheme choice is left"), std::string::npos)
        << e.what();
    // The volume, and the two pins to change.
    EXPECT_EQ(std::string(e.what()).rfind("volume 1: ", 0), 0u) << e.what();
    EXPECT_NE(e.hint().find("curve 1"), std::string::npos) << e.hint();
    EXPECT_NE(e.hint().find("curve 3"), std::string::npos) << e.hint();
  }
}

// The plan of a moved model, or of the same shapes created in another
// order, is the same plan: compared through surface centroids, since ids
// follow creation order.
std::map<std::string, std::string> plan_by_place(const geom::Model& model, const Selection& s,
                                                 const Eigen::Isometry3d& back) {
  std::map<std::string, std::string> plan;
  for (const auto& c : s.surfaces) {
    Vec3 sum = Vec3::Zero();  // mean of the loop vertices: moves with the model
    int n = 0;
    for (const auto& loop : model.surface(c.id).loops) {
      for (const auto& use : loop.uses) {
        sum += model.vertex(model.curve(use.curve).start_vertex).point;
        ++n;
      }
    }
    const Vec3 centre = back * Vec3(sum / n);
    char key[96];  // in thousandths, so -0.000 and 0.000 agree
    std::snprintf(key, sizeof key, "%ld %ld %ld", std::lround(centre.x() * 1000),
                  std::lround(centre.y() * 1000), std::lround(centre.z() * 1000));
    plan[key] = c.scheme;
  }
  for (const auto& c : s.volumes) plan["volume " + model.volume(c.id).name] = c.scheme;
  return plan;
}

TEST(Selector, PlanIsInvariantUnderRigidMotionAndInputOrder) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  const Vec3 axis = Vec3(u(rng), u(rng), u(rng)).normalized();
  const double angle = 90 * u(rng);
  const Vec3 shift(3 * u(rng), 3 * u(rng), 3 * u(rng));
  auto build = [&](bool moved, bool reversed) {
    occ::Workbench bench;
    std::vector<std::pair<std::string, Vec3>> plates{
        {"a", {0, 0, 0}}, {"b", {2, 0, 0}}, {"c", {0, 2, 0}}};
    if (reversed) std::reverse(plates.begin(), plates.end());
    for (const auto& [name, origin] : plates) bench.brick(name, origin, {2, 2, 0.5});
    if (moved) {
      for (const auto& [name, origin] : plates) {
        bench.rotate(name, {0, 0, 0}, axis, angle);
        bench.translate(name, shift);
      }
    }
    return bench.build_model();
  };
  Fixture f;
  const Eigen::Isometry3d identity = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d undo = Eigen::Isometry3d::Identity();
  undo.rotate(Eigen::AngleAxisd(-angle * M_PI / 180, axis));
  undo.translate(-shift);
  const geom::Model m0 = build(false, false), m1 = build(true, false), m2 = build(false, true);
  const auto p0 = plan_by_place(m0, select_schemes(m0, f.registry, sized(0.25)), identity);
  const auto p1 = plan_by_place(m1, select_schemes(m1, f.registry, sized(0.25)), undo);
  const auto p2 = plan_by_place(m2, select_schemes(m2, f.registry, sized(0.25)), identity);
  EXPECT_EQ(p0, p1);
  EXPECT_EQ(p0, p2);
  EXPECT_EQ(p0.size(), m0.surfaces().size() + 3);
}

}  // namespace
}  // namespace cooperage::selector

namespace cooperage::selector {
namespace {

// Issue 16, item 6: a brick (volume map: every face "map") glued to an
// L-shaped prism (cooper: its sides "submap") on one rectangular face. A
// rectangle submapped is the mesh mapped, so the two roles agree: the
// shared face is mapped, both volumes keep their schemes, and the model
// meshes conformally.
TEST(Selector, MapAndSubmapOnOneSharedRectangleAgree) {
  occ::Workbench bench;
  bench.brick("b", {0, 0, 0}, {2, 2, 2});
  bench.prism("l", {{2, 0, 0}, {5, 0, 0}, {5, 1, 0}, {3, 1, 0}, {3, 2, 0}, {2, 2, 0}}, {},
              {0, 0, 2});
  const geom::Model model = bench.build_model();
  ASSERT_EQ(model.volumes().size(), 2u);
  int shared = 0;
  for (const auto& s : model.surfaces()) {
    if (s.volumes.size() == 2) shared = s.id;
  }
  ASSERT_GT(shared, 0);
  Fixture f;
  const io::MeshSettings settings = sized(0.5);
  const Selection s = select_schemes(model, f.registry, settings);
  std::set<std::string> volume_schemes;
  for (const auto& v : s.volumes) volume_schemes.insert(v.scheme);
  EXPECT_EQ(volume_schemes, (std::set<std::string>{"map", "cooper"}));
  EXPECT_EQ(s.surfaces.at(static_cast<size_t>(shared - 1)).scheme, "map");

  const pipeline::MeshResult r = pipeline::mesh_model(model, settings, f.registry, mesh_options(3));
  size_t hexes = 0;
  for (const auto& v : model.volumes()) hexes += r.mesh.volume(v.id).hexes.size();
  EXPECT_GT(hexes, 0u);
  for (const auto& b : r.quality.blocks) {
    const auto* sj = b.find("scaled_jacobian");
    ASSERT_NE(sj, nullptr);
    EXPECT_EQ(sj->inverted, 0u);
  }
  // Conformal: the shared face's nodes are used by hexes of both volumes.
  std::set<int> face_nodes;
  for (const auto& q : r.mesh.surface(shared).quads) face_nodes.insert(q.begin(), q.end());
  for (const auto& v : model.volumes()) {
    std::set<int> used;
    for (const auto& h : r.mesh.volume(v.id).hexes) used.insert(h.begin(), h.end());
    for (int n : face_nodes)
      EXPECT_TRUE(used.count(n)) << "volume " << v.id << " misses node " << n;
  }
}

// Three 4 x 4 x 2 blocks stacked along z (issue 15: "two sweeps whose
// target is the same shared surface"). The bottom one carries a 1 x 1 x 1
// foot, so its top is imprinted by the foot whichever way it sweeps: its
// volume meshes that face itself. The middle block must then take that
// mesh as its source and end on the face above, which the top block takes
// in turn. In one order of the volumes the middle and top blocks were
// chosen first (map, or a sweep towards the foot's block) and the bottom
// one was refused; asked to plan around the face, they turn. Built in
// both orders and mirrored in z; the mesh is checked from geometry:
// conformal, the blocks' volume, no poor hex.
TEST(Selector, StackedSweepsTurnSoEachSharedFaceIsMeshedOnce) {
  for (const bool mirrored : {false, true}) {
    for (const bool foot_first : {false, true}) {
      SCOPED_TRACE(std::string(mirrored ? "mirrored, " : "") +
                   (foot_first ? "foot block first" : "foot block last"));
      occ::Workbench bench;
      auto footed = [&] {
        bench.brick("base", {0, 0, mirrored ? -2.0 : 0.0}, {4, 4, 2});
        bench.brick("foot", {1.5, 1.5, mirrored ? 0.0 : -1.0}, {1, 1, 1});
        bench.fuse("footed", {"base", "foot"});
      };
      if (foot_first) footed();
      bench.brick("top", {0, 0, mirrored ? -6.0 : 4.0}, {4, 4, 2});
      bench.brick("middle", {0, 0, mirrored ? -4.0 : 2.0}, {4, 4, 2});
      if (!foot_first) footed();
      const geom::Model model = bench.build_model();
      ASSERT_EQ(model.volumes().size(), 3u);
      Fixture f;
      const io::MeshSettings settings = sized(0.5);
      SelectOptions options;
      options.refuse_per_volume = true;
      const Selection s = select_schemes(model, f.registry, settings, options);
      EXPECT_TRUE(s.refused.empty()) << s.refused.begin()->second.message;
      ASSERT_EQ(s.volumes.size(), 3u);

      const pipeline::MeshResult r =
          pipeline::mesh_model(model, settings, f.registry, mesh_options(3));
      double volume = 0, worst = 1;
      size_t hexes = 0;
      for (const auto& [id, v] : r.mesh.volumes()) {
        for (const auto& h : v.hexes) {
          const auto p = testing::hex_points(r.mesh, h);
          volume += testing::hex_volume(p);
          worst = std::min(worst, testing::hex_scaled_jacobian(p));
          ++hexes;
        }
      }
      EXPECT_GT(hexes, 0u);
      EXPECT_NEAR(volume, 3 * 32.0 + 1.0, 0.005 * 97.0);
      EXPECT_GE(worst, 0.2);
      // Conformal: no duplicate node, no hex face used thrice, and the faces
      // used once are exactly the quads of the outer boundary.
      EXPECT_EQ(testing::duplicate_node_pairs(r.mesh, 1e-9), 0);
      size_t once = 0;
      for (const auto& [key, n] : testing::hex_face_counts(r.mesh)) {
        EXPECT_LE(n, 2);
        once += n == 1 ? 1 : 0;
      }
      size_t outer = 0;
      for (const auto& surface : model.surfaces()) {
        if (surface.volumes.size() == 1) outer += r.mesh.surface(surface.id).quads.size();
      }
      EXPECT_EQ(once, outer);
    }
  }
}

}  // namespace
}  // namespace cooperage::selector
