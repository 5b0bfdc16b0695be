// cooper in wedge mode (journal elements="wedge"; Blacker 1996, abstract:
// "a wedge/hexahedral element mix ... by simply allowing triangle ... cap
// meshes"): the source cap is meshed by "tri", the one-to-one sweep makes
// wedges, side faces stay quads. Many-to-one volumes give their caps to
// "tri" in wedge mode (test_cooper_wedge_many.cpp meshes them), and the
// journal checks reject wedge or mixed + volume map.
#include "support/mixed_mesh_check.h"
#include "scheme_helpers.h"

#include "framework/core/error.h"
#include "framework/geometry/occ/workbench.h"
#include "framework/pipeline/mesher.h"
#include "framework/quality/wedge_metrics.h"
#include "schemes/builtin_schemes.h"
#include "schemes/cooper/cooper_scheme.h"
#include "selector/select_schemes.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace cooperage::cooper {
namespace {

using geom::Vec3;

io::MeshSettings wedge_settings(double size, const std::string& scheme = "cooper",
                                io::ElementKind elements = io::ElementKind::Wedge) {
  io::MeshSettings s;
  s.size = size;
  s.finer_retries = 0;  // the scheme at this size, not a retry at a finer one
  io::VolumeSetting v;
  v.id = 1;
  v.scheme = scheme;
  v.elements = elements;
  s.volumes.push_back(v);
  return s;
}

using testing::builtin;

quality::WedgeNodes wedge_points(const mesh::MeshDB& db, const mesh::Wedge& w) {
  quality::WedgeNodes p;
  for (size_t k = 0; k < 6; ++k) p[k] = db.node(w[k]);
  return p;
}

double tet_volume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return (b - a).dot((c - a).cross(d - a)) / 6.0;
}

// Exact for wedges with planar quad faces (straight extrusions): three tets.
double wedge_volume(const quality::WedgeNodes& p) {
  return tet_volume(p[0], p[1], p[2], p[3]) + tet_volume(p[1], p[2], p[3], p[4]) +
         tet_volume(p[2], p[3], p[4], p[5]);
}

struct WedgeMeasures {
  size_t wedges = 0, hexes = 0;
  double volume = 0.0, min_sj = 2.0;
};

WedgeMeasures wedge_measures(const mesh::MeshDB& db) {
  WedgeMeasures m;
  for (const auto& [id, v] : db.volumes()) {
    m.hexes += v.hexes.size();
    for (const auto& w : v.wedges) {
      const auto p = wedge_points(db, w);
      m.volume += wedge_volume(p);
      m.min_sj = std::min(m.min_sj, quality::wedge_scaled_jacobian(p));
      ++m.wedges;
    }
  }
  return m;
}

template <size_t N>
std::vector<int> key(const std::array<int, N>& f) {
  std::vector<int> k(f.begin(), f.end());
  std::sort(k.begin(), k.end());
  return k;
}

// Every wedge face used once or twice; the faces used once are exactly the
// surface elements: quads of the side faces, triangles of the caps.
void expect_conformal_wedges(const mesh::MeshDB& db) {
  std::map<std::vector<int>, int> tri_use, quad_use;
  for (const auto& [id, v] : db.volumes()) {
    for (const auto& w : v.wedges) {
      ++tri_use[key(std::array<int, 3>{w[0], w[1], w[2]})];
      ++tri_use[key(std::array<int, 3>{w[3], w[4], w[5]})];
      ++quad_use[key(std::array<int, 4>{w[0], w[1], w[4], w[3]})];
      ++quad_use[key(std::array<int, 4>{w[1], w[2], w[5], w[4]})];
      ++quad_use[key(std::array<int, 4>{w[2], w[0], w[3], w[5]})];
    }
  }
  std::set<std::vector<int>> boundary_tris, boundary_quads;
  for (const auto& [k, n] : tri_use) {
    ASSERT_LE(n, 2);
    if (n == 1) boundary_tris.insert(k);
  }
  for (const auto& [k, n] : quad_use) {
    ASSERT_LE(n, 2);
    if (n == 1) boundary_quads.insert(k);
  }
  std::set<std::vector<int>> surface_tris, surface_quads;
  for (const auto& [id, s] : db.surfaces()) {
    for (const auto& t : s.tris)
      EXPECT_TRUE(surface_tris.insert(key(t)).second) << "surface " << id;
    for (const auto& q : s.quads)
      EXPECT_TRUE(surface_quads.insert(key(q)).second) << "surface " << id;
  }
  EXPECT_EQ(boundary_tris, surface_tris);
  EXPECT_EQ(boundary_quads, surface_quads);
}

// Straight (z-parallel) curves: their interval count is the number of layers.
int layers_along_z(const geom::Model& model, const mesh::MeshDB& db) {
  for (const auto& c : model.curves()) {
    const Vec3 a = model.vertex(c.start_vertex).point;
    const Vec3 b = model.vertex(c.end_vertex).point;
    if ((a - b).head<2>().norm() < 1e-9 && std::abs(a.z() - b.z()) > 1e-9) {
      return static_cast<int>(db.curve_nodes(c.id).size()) - 1;
    }
  }
  return -1;
}

// The meshed source cap (the cap with triangles that is not a volume role).
int source_cap(const pipeline::MeshResult& r) {
  for (const auto& [id, entry] : r.plan.surfaces) {
    if (entry.scheme == "tri") return id;
  }
  return 0;
}

void expect_wedge_sweep(const geom::Model& model, const pipeline::MeshResult& r, const char* name) {
  ASSERT_EQ(r.plan.volumes.at(1).scheme, "cooper") << name;
  const int source = source_cap(r);
  ASSERT_GT(source, 0) << name << ": no source cap meshed by tri";
  const int layers = layers_along_z(model, r.mesh);
  ASSERT_GT(layers, 0) << name;
  const WedgeMeasures m = wedge_measures(r.mesh);
  EXPECT_EQ(m.hexes, 0u) << name;
  EXPECT_EQ(m.wedges, r.mesh.surface(source).tris.size() * static_cast<size_t>(layers)) << name;
  EXPECT_TRUE(r.mesh.surface(source).quads.empty()) << name;
  // Caps have triangles only, sides quads only.
  for (const auto& [id, s] : r.mesh.surfaces()) {
    EXPECT_TRUE(s.tris.empty() || s.quads.empty()) << name << ": surface " << id;
  }
  EXPECT_GT(m.min_sj, 0.5) << name;
  expect_conformal_wedges(r.mesh);
  ::testing::Test::RecordProperty(std::string(name) + "_min_wedge_scaled_jacobian",
                                  std::to_string(m.min_sj));
  std::printf("[cooper wedge] %s: %zu wedges, %d layers, min scaled Jacobian %.4f\n", name,
              m.wedges, layers, m.min_sj);
}

TEST(CooperWedge, PlateWithThreeRoundHolesSweepsWedges) {
  occ::Workbench wb;
  wb.brick("b", {0, 0, 0}, {10, 6, 1});
  const double radius = 0.8;
  for (auto [name, x] : {std::pair{"h1", 2.5}, {"h2", 5.0}, {"h3", 7.5}}) {
    wb.cylinder(name, {x, 3, 0}, {0, 0, 1}, radius, 1);
  }
  wb.cut("plate", {"b", "h1", "h2", "h3"});
  const geom::Model model = wb.build_model();
  const io::MeshSettings settings = wedge_settings(0.3);
  const auto registry = builtin();
  const pipeline::MeshResult r =
      pipeline::mesh_model(model, settings, *registry, selector::mesh_options());
  expect_wedge_sweep(model, r, "plate_three_round_holes");

  // The holes are polygons inscribed in the circles (n chords each): the
  // mesh volume exceeds the solid's by at most the three chordal deficits.
  size_t chords = 0;
  for (const auto& c : model.curves()) {
    if (c.start_vertex != c.end_vertex) continue;  // the hole circles are closed
    const size_t n = r.mesh.curve_nodes(c.id).size() - 1;
    chords = chords == 0 ? n : std::min(chords, n);
  }
  ASSERT_GE(chords, 3u);
  const double t = 2 * M_PI / static_cast<double>(chords);
  const double deficit = 3 * M_PI * radius * radius * (1 - std::sin(t) / t);
  const double solid = model.volume(1).volume;
  const WedgeMeasures m = wedge_measures(r.mesh);
  EXPECT_GT(m.volume, solid - 1e-9 * solid);
  EXPECT_LE(m.volume, solid + deficit + 1e-9 * solid);
}

TEST(CooperWedge, PlateWithThreeSquareHolesHasTheExactVolume) {
  // 10 x 4 x 2 with three 1 x 1 square holes: volume 74, meshed exactly.
  occ::Workbench wb;
  std::vector<std::vector<Vec3>> holes;
  for (double x0 : {1.5, 4.5, 7.5}) {
    holes.push_back({{x0, 1.5, 0}, {x0 + 1, 1.5, 0}, {x0 + 1, 2.5, 0}, {x0, 2.5, 0}});
  }
  wb.prism("plate", {{0, 0, 0}, {10, 0, 0}, {10, 4, 0}, {0, 4, 0}}, holes, {0, 0, 2});
  const geom::Model model = wb.build_model();
  const io::MeshSettings settings = wedge_settings(0.5, "auto");
  const auto registry = builtin();
  const pipeline::MeshResult r =
      pipeline::mesh_model(model, settings, *registry, selector::mesh_options());
  expect_wedge_sweep(model, r, "plate_three_square_holes");
  EXPECT_NEAR(wedge_measures(r.mesh).volume, 74.0, 74.0 * 1e-9);
}

TEST(CooperWedge, AutoOnABrickPicksCooperNotTheVolumeMap) {
  occ::Workbench wb;
  wb.brick("b", {0, 0, 0}, {2, 1, 1});
  const geom::Model model = wb.build_model();
  const io::MeshSettings settings = wedge_settings(0.25, "auto");
  const auto registry = builtin();
  const pipeline::MeshResult r =
      pipeline::mesh_model(model, settings, *registry, selector::mesh_options());
  EXPECT_EQ(r.plan.volumes.at(1).scheme, "cooper");
  const WedgeMeasures m = wedge_measures(r.mesh);
  EXPECT_EQ(m.hexes, 0u);
  EXPECT_GT(m.wedges, 0u);
  EXPECT_NEAR(m.volume, 2.0, 2.0 * 1e-9);
  EXPECT_GT(m.min_sj, 0.5);
  expect_conformal_wedges(r.mesh);
}

// Two bricks touching on a face, both in wedges: the first sweeps along y,
// so the shared face is one of its quad sides; the second must sweep so
// that the face is a side of it too (along y or z), not its triangle cap.
// It used to take the shared face as its source and be refused ("needs tri
// for volume 2 but submap for volume 1").
TEST(CooperWedge, TouchingBricksKeepTheirSharedFaceASide) {
  occ::Workbench wb;
  wb.brick("a", {0, 0, 0}, {2, 1, 1});
  wb.brick("b", {2, 0, 0}, {1, 1, 1});
  const geom::Model model = wb.build_model();
  ASSERT_EQ(model.volumes().size(), 2u);
  io::MeshSettings settings = wedge_settings(0.25, "auto");
  io::VolumeSetting second = settings.volumes.front();
  second.id = 2;
  settings.volumes.push_back(second);
  const auto registry = builtin();
  const pipeline::MeshResult r =
      pipeline::mesh_model(model, settings, *registry, selector::mesh_options());
  EXPECT_EQ(r.plan.volumes.at(1).scheme, "cooper");
  EXPECT_EQ(r.plan.volumes.at(2).scheme, "cooper");
  // Conformal across the shared face (its quads used by both volumes).
  const testing::MixedMeshSummary m = testing::check_mixed_mesh(model, r.mesh);
  EXPECT_EQ(m.hexes, 0u);
  EXPECT_GT(m.wedges, 0u);
  EXPECT_NEAR(m.volume, 3.0, 3.0 * 1e-9);
  EXPECT_GT(m.min_wedge_sj, 0.5);
}

// <mesh elements="wedge"> for every volume, one volume back to hexes by
// its own <volume elements="hex">: two bricks apart, one of each.
TEST(CooperWedge, AVolumesOwnKindOverridesTheMeshes) {
  occ::Workbench wb;
  wb.brick("a", {0, 0, 0}, {2, 1, 1});
  wb.brick("b", {3, 0, 0}, {1, 1, 1});
  const geom::Model model = wb.build_model();
  ASSERT_EQ(model.volumes().size(), 2u);
  io::MeshSettings settings;
  settings.size = 0.25;
  settings.finer_retries = 0;
  settings.elements = io::ElementKind::Wedge;
  io::VolumeSetting hexes;
  hexes.id = 2;
  hexes.elements = io::ElementKind::Hex;
  settings.volumes.push_back(hexes);
  const auto registry = builtin();
  const pipeline::MeshResult r =
      pipeline::mesh_model(model, settings, *registry, selector::mesh_options());
  const mesh::MeshDB& db = r.mesh;
  const auto& first = db.volumes().at(1);
  const auto& second = db.volumes().at(2);
  EXPECT_TRUE(first.hexes.empty());
  EXPECT_FALSE(first.wedges.empty());
  EXPECT_FALSE(second.hexes.empty());
  EXPECT_TRUE(second.wedges.empty());
  const testing::MixedMeshSummary m = testing::check_mixed_mesh(model, db);
  EXPECT_NEAR(m.volume, 3.0, 3.0 * 1e-9);
}

TEST(CooperWedge, ApplicableBothWays) {
  // A one-barrel plate: applicable in both modes, tri source cap in wedge mode.
  occ::Workbench plate;
  plate.brick("b", {0, 0, 0}, {4, 3, 1});
  plate.cylinder("h", {2, 1.5, 0}, {0, 0, 1}, 0.5, 1);
  plate.cut("p", {"b", "h"});
  const geom::Model one = plate.build_model();
  // A brick with a boss: many-to-one, applicable in both modes, tri caps in wedge mode.
  occ::Workbench boss;
  boss.brick("b", {0, 0, 0}, {4, 4, 2});
  boss.brick("boss", {1.5, 1.5, 2}, {1, 1, 1});
  boss.fuse("part", {"b", "boss"});
  const geom::Model many = boss.build_model();

  // One registry for both jobs: the element kind is the job's (scheme::Settings).
  scheme::Registry registry;
  register_builtin_schemes(registry);
  const auto* cooper = registry.volume_scheme("cooper");
  const io::MeshSettings hex_job = wedge_settings(0.5, "cooper", io::ElementKind::Hex);
  const io::MeshSettings wedge_job = wedge_settings(0.5);
  const scheme::Settings hex = scheme::Settings::of(hex_job),
                         wedge = scheme::Settings::of(wedge_job);
  EXPECT_TRUE(cooper->applicable({one, 1, nullptr, &hex}).ok);
  EXPECT_TRUE(cooper->applicable({one, 1, nullptr, &wedge}).ok);
  const scheme::SurfaceRoles roles = cooper->roles({one, 1, nullptr, &wedge});
  EXPECT_EQ(
      std::count_if(roles.begin(), roles.end(), [](const auto& r) { return r.second == "tri"; }),
      1);
  const scheme::SurfaceRoles hex_roles = cooper->roles({one, 1, nullptr, &hex});
  EXPECT_EQ(std::count_if(hex_roles.begin(), hex_roles.end(),
                          [](const auto& r) { return r.second == "tri"; }),
            0);

  EXPECT_TRUE(cooper->applicable({many, 1, nullptr, &hex}).ok);
  const scheme::Applicability a = cooper->applicable({many, 1, nullptr, &wedge});
  EXPECT_TRUE(a.ok) << a.why;
  const scheme::SurfaceRoles many_roles = cooper->roles({many, 1, nullptr, &wedge});
  EXPECT_EQ(std::count_if(many_roles.begin(), many_roles.end(),
                          [](const auto& r) { return r.second == "tri"; }),
            2);  // the boss top and the shoulder
  // Without the tri scheme, wedge mode does not apply, and says why.
  scheme::Registry bare;
  const auto bare_cooper = make_cooper(bare);
  const scheme::Applicability no = bare_cooper->applicable({one, 1, nullptr, &wedge});
  EXPECT_FALSE(no.ok);
}

// Flush steps (a boss flush with the front wall on top, a foot flush with
// three walls below: virtual caps beside real ones on both ends of the
// block's barrel) sweep in every element kind: the subcaps are node loops,
// whatever the cap elements. Volume 32 + 6 + 8 = 46.
TEST(CooperWedge, FlushStepsSweepInEveryElementKind) {
  occ::Workbench wb;
  wb.brick("b", {0, 0, 0}, {4, 4, 2});
  wb.brick("boss", {1, 0, 2}, {2, 3, 1});
  wb.brick("foot", {0, 2, -1}, {4, 2, 1});
  wb.fuse("part", {"b", "boss", "foot"});
  const geom::Model model = wb.build_model();
  for (io::ElementKind kind :
       {io::ElementKind::Hex, io::ElementKind::Wedge, io::ElementKind::Mixed}) {
    io::MeshSettings settings = wedge_settings(0.5, "cooper", kind);
    settings.volumes.front().direction = Vec3(0, 0, 1);  // along the steps: flush
    const auto registry = builtin();
    const scheme::Applicability a =
        registry->volume_scheme("cooper")->applicable({model, 1, nullptr});
    ASSERT_TRUE(a.ok) << a.why;
    const auto r = pipeline::mesh_model(model, settings, *registry, selector::mesh_options());
    const testing::MixedMeshSummary m = testing::check_mixed_mesh(model, r.mesh);
    EXPECT_NEAR(m.volume, 46.0, 46.0 * 1e-6);
    EXPECT_GE(m.min_hex_sj, 0.3);
    EXPECT_GE(m.min_wedge_sj, 0.3);
    if (kind == io::ElementKind::Wedge) {
      EXPECT_EQ(m.hexes, 0u);
    }
    if (kind == io::ElementKind::Hex) {
      EXPECT_EQ(m.wedges, 0u);
    }
    std::printf(
        "[cooper wedge] flush steps, kind %d: %zu hexes, %zu wedges, min SJ hex %.4f wedge %.4f\n",
        static_cast<int>(kind), m.hexes, m.wedges, m.min_hex_sj, m.min_wedge_sj);
  }
}

TEST(CooperWedge, JournalChecksRejectWedgeAndMixedWithTheVolumeMap) {
  occ::Workbench wb;
  wb.brick("b", {0, 0, 0}, {2, 1, 1});
  const geom::Model model = wb.build_model();
  const auto expect_error = [&](const io::MeshSettings& settings, ErrorCode code,
                                const std::string& text) {
    const auto registry = builtin();
    try {
      pipeline::mesh_model(model, settings, *registry, selector::mesh_options());
      ADD_FAILURE() << "meshed: " << text;
    } catch (const MeshingError& e) {
      EXPECT_EQ(e.code(), code) << e.what();
      EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
    }
  };
  expect_error(wedge_settings(0.5, "map"), ErrorCode::InvalidInput, "makes hexes only");
  expect_error(wedge_settings(0.5, "map", io::ElementKind::Mixed), ErrorCode::InvalidInput,
               "elements=\"mixed\" with scheme=\"map\"");
}

}  // namespace
}  // namespace cooperage::cooper
