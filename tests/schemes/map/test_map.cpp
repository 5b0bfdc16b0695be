// Tests of the surface and volume map schemes on analytic (CAD-free) models.
#include "analytic_model.h"
#include "mesh_helpers.h"

#include "framework/core/error.h"
#include "framework/scheme/vertex_angles.h"
#include "schemes/map/block_lattice.h"
#include "schemes/map/map_sides.h"
#include "schemes/map/surface_map.h"
#include "framework/mesh/tfi.h"
#include "schemes/map/volume_map.h"

#include <Eigen/Geometry>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace cooperage {
namespace {

using geom::Vec3;
using testing::commit_surface;
using testing::commit_volume;
using testing::mesh_curves;

// Meshes every surface of the model with the surface map.
void map_all_surfaces(const geom::Model& model, mesh::MeshDB& db) {
  const auto scheme = map::make_surface_map();
  for (const auto& s : model.surfaces()) {
    const scheme::SurfaceView view{model, s.id, &db};
    commit_surface(db, s.id, scheme->mesh(view, {}));
  }
}

// No two nodes of the mesh at the same place.
double min_node_distance(const mesh::MeshDB& db) {
  std::vector<Vec3> p = db.coords();
  std::sort(p.begin(), p.end(), [](const Vec3& a, const Vec3& b) {
    return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
  });
  double best = 1e300;
  for (size_t i = 0; i < p.size(); ++i) {
    for (size_t j = i + 1; j < p.size() && j < i + 64; ++j)
      best = std::min(best, (p[i] - p[j]).norm());
  }
  return best;
}

// ---- surface map: applicable ------------------------------------------------

TEST(SurfaceMapApplicable, RectangleYes) {
  const geom::Model model = testing::rectangle_model(4, 6);
  const auto a = map::make_surface_map()->applicable({model, 1, nullptr});
  EXPECT_TRUE(a.ok) << a.why;
  EXPECT_NEAR(a.score, 1.0, 1e-9);
}

TEST(SurfaceMapApplicable, LShapeNoWithCorner) {
  const geom::Model model = testing::l_shape_model();
  const auto a = map::make_surface_map()->applicable({model, 1, nullptr});
  EXPECT_FALSE(a.ok);
  EXPECT_NE(a.why.find("CORNER"), std::string::npos) << a.why;
  EXPECT_NE(a.why.find("surface 1"), std::string::npos) << a.why;
  EXPECT_NE(a.why.find("vertex 4"), std::string::npos) << a.why;
}

TEST(SurfaceMapApplicable, HoleNo) {
  const geom::Model model = testing::square_with_hole_model();
  const auto a = map::make_surface_map()->applicable({model, 1, nullptr});
  EXPECT_FALSE(a.ok);
  EXPECT_EQ(a.why, "surface 1 has 2 loops; map needs one");
}

TEST(SurfaceMapApplicable, QuarterAnnulusAndCylinderYes) {
  const geom::Model annulus = testing::quarter_annulus_model();
  const auto a = map::make_surface_map()->applicable({annulus, 1, nullptr});
  EXPECT_TRUE(a.ok) << a.why;
  EXPECT_NEAR(a.score, 1.0, 1e-6);
  const geom::Model cylinder = testing::cylinder_side_model(1.5, 2.0);
  const auto corners = scheme::loop_corners(cylinder, 1, 0);
  ASSERT_EQ(corners.size(), 4u);
  for (const auto& c : corners) EXPECT_NEAR(c.angle, 90.0, 1e-6);
  const auto b = map::make_surface_map()->applicable({cylinder, 1, nullptr});
  EXPECT_TRUE(b.ok) << b.why;
}

TEST(SurfaceMapApplicable, SkewedFaceScoresLower) {
  // A trapezoid with 60 and 120 degree corners still maps, with a lower score.
  testing::ModelBuilder m;
  const int v1 = m.vertex({0, 0, 0}), v2 = m.vertex({4, 0, 0});
  const int v3 = m.vertex({4 - std::sqrt(3.0), 3, 0}), v4 = m.vertex({0, 3, 0});
  m.planar({v1, v2, v3, v4});
  const geom::Model model = m.finish();
  const auto a = map::make_surface_map()->applicable({model, 1, nullptr});
  EXPECT_TRUE(a.ok) << a.why;
  EXPECT_LT(a.score, 0.9);
  EXPECT_GT(a.score, 0.0);
}

TEST(SurfaceMapApplicable, SixEndsNo) {
  // A hexagon: 6 corners at 120 degrees are all END.
  testing::ModelBuilder m;
  std::vector<int> v;
  for (int k = 0; k < 6; ++k) {
    const double t = k * 3.14159265358979323846 / 3;
    v.push_back(m.vertex({std::cos(t), std::sin(t), 0}));
  }
  m.planar(v);
  const geom::Model model = m.finish();
  const auto a = map::make_surface_map()->applicable({model, 1, nullptr});
  EXPECT_FALSE(a.ok);
  EXPECT_EQ(a.why, "surface 1: 6 END vertices (1, 2, 3, 4, 5, 6), map needs 4");
}

// ---- surface map: constrain -------------------------------------------------

TEST(SurfaceMapConstrain, RectangleOppositeSidesEqual) {
  const geom::Model model = testing::rectangle_model(4, 6);
  intervals::IntervalProblem problem;
  map::make_surface_map()->constrain({model, 1, nullptr}, problem);
  ASSERT_EQ(problem.constraints().size(), 2u);
  std::set<std::pair<int, int>> pairs;
  for (const auto& c : problem.constraints()) {
    ASSERT_EQ(c.terms.size(), 2u);
    EXPECT_EQ(c.terms[0].coeff + c.terms[1].coeff, 0);
    pairs.insert({std::min(c.terms[0].curve_id, c.terms[1].curve_id),
                  std::max(c.terms[0].curve_id, c.terms[1].curve_id)});
    EXPECT_NE(c.label.find("surface 1 (map): curves"), std::string::npos) << c.label;
  }
  // Curves 1..4 run around the rectangle: 1 = 3 and 2 = 4.
  EXPECT_EQ(pairs, (std::set<std::pair<int, int>>{{1, 3}, {2, 4}}));
}

// ---- surface map: mesh ------------------------------------------------------

TEST(SurfaceMapMesh, Rectangle4x6) {
  const geom::Model model = testing::rectangle_model(4, 6);
  mesh::MeshDB db;
  mesh_curves(model, db, 1.0);
  const size_t curve_nodes = db.node_count();
  const auto em = map::make_surface_map()->mesh({model, 1, &db}, {});
  EXPECT_EQ(em.quads.size(), 24u);
  // Boundary nodes are exactly the curve nodes; 3 x 5 interior nodes are new.
  std::set<int> boundary;
  for (int g : em.global) {
    if (g >= 0) boundary.insert(g);
  }
  EXPECT_EQ(boundary.size(), curve_nodes);
  EXPECT_EQ(em.global.size(), curve_nodes + 15);
  commit_surface(db, 1, em);
  for (size_t n = 0; n < db.node_count(); ++n)
    EXPECT_NEAR(db.node(static_cast<int>(n)).z(), 0.0, 1e-12);
  for (const auto& q : db.surface(1).quads) {
    EXPECT_NEAR(testing::quad_scaled_jacobian(db, q, Vec3::UnitZ()), 1.0, 1e-12);
  }
}

// A quadrilateral with corners of 40, 110, 100 and 110 degrees (the
// flanks of an angled clamp have 40-degree corners): the sharp corner is
// an END (scheme::kMinEndAngle), so the face maps, and no quad is worse
// than the corner allows (sin 40 = 0.64). Below kMinEndAngle a corner has
// no type and map refuses, naming it.
TEST(SurfaceMapMesh, FortyDegreeCornerIsAnEnd) {
  testing::ModelBuilder m;
  const int v1 = m.vertex({0, 0, 0}), v2 = m.vertex({10, 0, 0});
  const int v3 = m.vertex({10.874, 2.402, 0}), v4 = m.vertex({6.128, 5.142, 0});
  m.planar({v1, v2, v3, v4});
  const geom::Model model = m.finish();
  const auto corners = scheme::loop_corners(model, 1, 0);
  ASSERT_EQ(corners.size(), 4u);
  EXPECT_NEAR(corners[0].angle, 40.0, 0.1);
  const auto a = map::make_surface_map()->applicable({model, 1, nullptr});
  ASSERT_TRUE(a.ok) << a.why;
  mesh::MeshDB db;
  mesh_curves(model, db, 1.0, {{1, 10}, {2, 4}, {3, 10}, {4, 4}});
  commit_surface(db, 1, map::make_surface_map()->mesh({model, 1, &db}, {}));
  EXPECT_EQ(db.surface(1).quads.size(), 40u);
  double area = 0.0, worst = 1.0;
  for (const auto& q : db.surface(1).quads) {
    worst = std::min(worst, testing::quad_scaled_jacobian(db, q, Vec3::UnitZ()));
    area += 0.5 * (db.node(q[2]) - db.node(q[0])).cross(db.node(q[3]) - db.node(q[1])).z();
  }
  EXPECT_GT(worst, 0.5);
  EXPECT_LE(worst, std::sin(40.0 * 3.14159265358979323846 / 180.0) + 1e-6);
  // The shoelace area of the four corners.
  const double exact = 0.5 * ((10 * 2.402 - 10.874 * 0) + (10.874 * 5.142 - 6.128 * 2.402));
  EXPECT_NEAR(area, exact, 1e-9 * exact);

  testing::ModelBuilder sharp;
  const int w1 = sharp.vertex({0, 0, 0}), w2 = sharp.vertex({10, 0, 0});
  const int w3 = sharp.vertex({10, 2, 0}), w4 = sharp.vertex({2 / std::tan(0.436332), 2, 0});
  sharp.planar({w1, w2, w3, w4});
  const geom::Model sharp_model = sharp.finish();
  const auto b = map::make_surface_map()->applicable({sharp_model, 1, nullptr});
  EXPECT_FALSE(b.ok);
  EXPECT_NE(b.why.find("too sharp to classify (below 30)"), std::string::npos) << b.why;
}

TEST(SurfaceMapMesh, UnequalSidesThrow) {
  const geom::Model model = testing::rectangle_model(4, 6);
  mesh::MeshDB db;
  mesh_curves(model, db, 1.0, {{1, 3}});
  try {
    map::make_surface_map()->mesh({model, 1, &db}, {});
    FAIL() << "expected MeshingError";
  } catch (const MeshingError& e) {
    EXPECT_EQ(e.code(), ErrorCode::MeshingFailed);
    EXPECT_EQ(e.entity().dim, 2);
    EXPECT_EQ(e.entity().id, 1);
  }
}

TEST(SurfaceMapMesh, QuarterAnnulusNonUniformBoundary) {
  const geom::Model model = testing::quarter_annulus_model();
  mesh::MeshDB db;
  mesh_curves(model, db, 0.25, {{1, 8}, {2, 8}});
  commit_surface(db, 1, map::make_surface_map()->mesh({model, 1, &db}, {}));
  EXPECT_EQ(db.surface(1).quads.size(), 8u * 4u);
  double area = 0.0;
  for (const auto& q : db.surface(1).quads) {
    EXPECT_GT(testing::quad_scaled_jacobian(db, q, Vec3::UnitZ()), 0.5);
    area += 0.5 * (db.node(q[2]) - db.node(q[0])).cross(db.node(q[3]) - db.node(q[1])).z();
  }
  EXPECT_NEAR(area, 0.75 * 3.14159265358979323846, 0.05);
}

TEST(SurfaceMapMesh, CylinderSideWithSeam) {
  const double r = 1.5, h = 2.0;
  const geom::Model model = testing::cylinder_side_model(r, h);
  mesh::MeshDB db;
  mesh_curves(model, db, 0.5, {{1, 16}, {2, 16}, {3, 4}});
  const auto em = map::make_surface_map()->mesh({model, 1, &db}, {});
  // No local node twice for one global node (the seam is shared by both sides).
  std::set<int> globals;
  for (int g : em.global) {
    if (g >= 0) {
      EXPECT_TRUE(globals.insert(g).second) << "node " << g << " twice";
    }
  }
  commit_surface(db, 1, em);
  EXPECT_EQ(db.surface(1).quads.size(), 16u * 4u);
  EXPECT_EQ(db.node_count(), 16u * 5u);
  EXPECT_GT(min_node_distance(db), 1e-3);
  for (size_t n = 0; n < db.node_count(); ++n) {
    const Vec3& p = db.node(static_cast<int>(n));
    EXPECT_NEAR(std::hypot(p.x(), p.y()), r, 1e-9);
  }
  // Quads follow the natural (outward) normal.
  for (const auto& q : db.surface(1).quads) {
    const Vec3 c = 0.25 * (db.node(q[0]) + db.node(q[1]) + db.node(q[2]) + db.node(q[3]));
    const Vec3 n = Vec3(c.x(), c.y(), 0).normalized();
    EXPECT_GT(testing::quad_scaled_jacobian(db, q, n), 0.9);
  }
}

TEST(SurfaceMapMesh, CompositeSideWithSideVertex) {
  // Rectangle 4 x 2 with a vertex in the middle of the bottom side (180 degrees):
  // side 0 has two curves, 2 + 2 intervals against 4 on top.
  testing::ModelBuilder m;
  const int v1 = m.vertex({0, 0, 0}), v2 = m.vertex({2, 0, 0}), v3 = m.vertex({4, 0, 0});
  const int v4 = m.vertex({4, 2, 0}), v5 = m.vertex({0, 2, 0});
  m.planar({v1, v2, v3, v4, v5});
  const geom::Model model = m.finish();
  const auto scheme = map::make_surface_map();
  const auto a = scheme->applicable({model, 1, nullptr});
  ASSERT_TRUE(a.ok) << a.why;
  intervals::IntervalProblem problem;
  scheme->constrain({model, 1, nullptr}, problem);
  ASSERT_EQ(problem.constraints().size(), 2u);
  EXPECT_EQ(problem.constraints()[0].label, "surface 1 (map): curves 1+2 = 4");
  EXPECT_EQ(problem.constraints()[1].label, "surface 1 (map): curves 3 = 5");
  mesh::MeshDB db;
  mesh_curves(model, db, 0.5, {{1, 2}, {2, 2}, {3, 3}, {4, 4}, {5, 3}});
  commit_surface(db, 1, scheme->mesh({model, 1, &db}, {}));
  EXPECT_EQ(db.surface(1).quads.size(), 12u);
  EXPECT_EQ(db.node_count(), 20u);
  for (const auto& q : db.surface(1).quads) {
    EXPECT_NEAR(testing::quad_scaled_jacobian(db, q, Vec3::UnitZ()), 1.0, 1e-9);
  }
}

// ---- TFI ----------------------------------------------------------------------

TEST(Tfi, ReproducesBilinearPatch) {
  std::vector<Vec3> bottom, top, left, right;
  for (int i = 0; i <= 4; ++i) {
    bottom.push_back(Vec3(i, 0, 0));
    top.push_back(Vec3(i, 3, 0));
  }
  for (int j = 0; j <= 3; ++j) {
    left.push_back(Vec3(0, j, 0));
    right.push_back(Vec3(4, j, 0));
  }
  const mesh::Grid2 g = mesh::tfi_2d(bottom, top, left, right);
  for (int i = 0; i <= 4; ++i) {
    for (int j = 0; j <= 3; ++j) EXPECT_LT((g(i, j) - Vec3(i, j, 0)).norm(), 1e-12);
  }
}

// ---- volume map -----------------------------------------------------------------

TEST(VolumeMapApplicable, BrickYesSplitTopNo) {
  const geom::Model brick = testing::brick_model(2, 3, 4);
  const auto a = map::make_volume_map()->applicable({brick, 1, nullptr});
  EXPECT_TRUE(a.ok) << a.why;
  EXPECT_NEAR(a.score, 1.0, 1e-9);
  const geom::Model split = testing::split_top_brick_model();
  const auto b = map::make_volume_map()->applicable({split, 1, nullptr});
  EXPECT_FALSE(b.ok);
  EXPECT_EQ(b.why, "volume 1: volume map needs 6 mappable surfaces, volume has 7");
}

TEST(VolumeMapApplicable, RolesAndConstraints) {
  const geom::Model brick = testing::brick_model(2, 3, 4);
  const auto scheme = map::make_volume_map();
  const auto roles = scheme->roles({brick, 1, nullptr});
  ASSERT_EQ(roles.size(), 6u);
  for (const auto& [id, name] : roles) EXPECT_EQ(name, "map");
  intervals::IntervalProblem problem;
  scheme->constrain({brick, 1, nullptr}, problem);
  EXPECT_EQ(problem.constraints().size(), 12u);
}

TEST(VolumeMapMesh, Brick2x3x4) {
  const geom::Model model = testing::brick_model(2, 3, 4);
  ASSERT_TRUE(map::make_volume_map()->applicable({model, 1, nullptr}).ok);
  mesh::MeshDB db;
  mesh_curves(model, db, 0.5);
  map_all_surfaces(model, db);
  const size_t surface_nodes = db.node_count();
  commit_volume(db, 1, map::make_volume_map()->mesh({model, 1, &db}, {}));
  const auto& hexes = db.volume(1).hexes;
  ASSERT_EQ(hexes.size(), 4u * 6u * 8u);
  EXPECT_EQ(db.node_count(), 5u * 7u * 9u);
  EXPECT_EQ(db.node_count() - surface_nodes, 3u * 5u * 7u);
  double volume = 0.0;
  for (const auto& h : hexes) {
    const auto x = testing::hex_points(db, h);
    const double v = testing::hex_volume(x);
    EXPECT_GT(v, 0.0);
    volume += v;
    EXPECT_NEAR(testing::hex_scaled_jacobian(x), 1.0, 1e-9);
  }
  EXPECT_NEAR(volume, 24.0, 1e-9);
  // Conformity: interior faces twice, boundary faces once and exactly the surface quads.
  std::set<std::array<int, 4>> surface_quads;
  for (const auto& [id, s] : db.surfaces()) {
    for (const auto& q : s.quads) surface_quads.insert(testing::sorted(q));
  }
  std::set<std::array<int, 4>> boundary;
  for (const auto& [face, count] : testing::hex_face_counts(hexes)) {
    ASSERT_TRUE(count == 1 || count == 2) << count;
    if (count == 1) boundary.insert(face);
  }
  EXPECT_EQ(boundary, surface_quads);
  EXPECT_GT(min_node_distance(db), 0.4);
}

TEST(VolumeMapMesh, QuarterAnnulusBlock) {
  const geom::Model model = testing::quarter_annulus_block_model();
  const auto a = map::make_volume_map()->applicable({model, 1, nullptr});
  ASSERT_TRUE(a.ok) << a.why;
  mesh::MeshDB db;
  // Arcs 8 intervals, radial and vertical lines 4.
  std::map<int, int> counts;
  for (const auto& c : model.curves()) {
    counts[c.id] = c.geometry->type() == geom::CurveType::Circle ? 8 : 4;
  }
  mesh_curves(model, db, 0.25, counts);
  map_all_surfaces(model, db);
  commit_volume(db, 1, map::make_volume_map()->mesh({model, 1, &db}, {}));
  const auto& hexes = db.volume(1).hexes;
  ASSERT_EQ(hexes.size(), 8u * 4u * 4u);
  double volume = 0.0, worst = 1.0;
  for (const auto& h : hexes) {
    const auto x = testing::hex_points(db, h);
    const double v = testing::hex_volume(x);
    EXPECT_GT(v, 0.0);
    volume += v;
    worst = std::min(worst, testing::hex_scaled_jacobian(x));
  }
  EXPECT_GT(worst, 0.5);
  EXPECT_NEAR(volume, 0.75 * 3.14159265358979323846, 0.03);
  std::set<std::array<int, 4>> surface_quads;
  for (const auto& [id, s] : db.surfaces()) {
    for (const auto& q : s.quads) surface_quads.insert(testing::sorted(q));
  }
  size_t boundary = 0;
  for (const auto& [face, count] : testing::hex_face_counts(hexes)) {
    ASSERT_TRUE(count == 1 || count == 2) << count;
    if (count == 1) {
      ++boundary;
      EXPECT_TRUE(surface_quads.count(face));
    }
  }
  EXPECT_EQ(boundary, surface_quads.size());
}

// A brick [0,2]x[0,3]x[0,4] whose vertices are created in the order of
// `order` (indices of the standard corners), so the lattice recovered from
// the smallest node may come out left-handed.
geom::Model permuted_brick(const std::array<int, 8>& order) {
  const std::array<Vec3, 8> p = {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(2, 3, 0), Vec3(0, 3, 0),
                                 Vec3(0, 0, 4), Vec3(2, 0, 4), Vec3(2, 3, 4), Vec3(0, 3, 4)};
  testing::ModelBuilder m;
  std::array<int, 8> id{};
  for (int k : order) id[static_cast<size_t>(k)] = m.vertex(p[static_cast<size_t>(k)]);
  auto v = [&](std::initializer_list<int> corners) {
    std::vector<int> out;
    for (int c : corners) out.push_back(id[static_cast<size_t>(c)]);
    return out;
  };
  m.volume({m.planar(v({0, 3, 2, 1})), m.planar(v({4, 5, 6, 7})), m.planar(v({0, 1, 5, 4})),
            m.planar(v({3, 7, 6, 2})), m.planar(v({0, 4, 7, 3})), m.planar(v({1, 2, 6, 5}))});
  return m.finish();
}

TEST(VolumeMapMesh, EitherHandednessGivesPositiveHexes) {
  for (const auto& order :
       {std::array<int, 8>{0, 1, 2, 3, 4, 5, 6, 7}, std::array<int, 8>{0, 3, 2, 1, 4, 5, 6, 7},
        std::array<int, 8>{6, 2, 5, 7, 0, 1, 3, 4}}) {
    for (const double size : {10.0, 0.5}) {
      const geom::Model model = permuted_brick(order);
      mesh::MeshDB db;
      mesh_curves(model, db, size);
      map_all_surfaces(model, db);
      commit_volume(db, 1, map::make_volume_map()->mesh({model, 1, &db}, {}));
      double volume = 0.0;
      for (const auto& h : db.volume(1).hexes) {
        const auto x = testing::hex_points(db, h);
        EXPECT_NEAR(testing::hex_scaled_jacobian(x), 1.0, 1e-9);
        volume += testing::hex_volume(x);
      }
      EXPECT_NEAR(volume, 24.0, 1e-9) << "size " << size << " order " << order[1];
    }
  }
}

TEST(VolumeMapMesh, GradedEdgesKeepHexesValid) {
  // Geometrically graded nodes along the z edges: TFI carries the grading inside.
  const geom::Model model = testing::brick_model(2, 3, 4);
  mesh::MeshDB db;
  mesh_curves(model, db, 0.5);
  for (const auto& c : model.curves()) {
    const Vec3 a = model.vertex(c.start_vertex).point, b = model.vertex(c.end_vertex).point;
    if (std::abs(a.z() - b.z()) < 1e-12) continue;
    const std::vector<int> chain = db.curve_nodes(c.id);
    const int n = static_cast<int>(chain.size()) - 1;
    const bool up = a.z() < b.z();
    const double z0 = std::min(a.z(), b.z()), z1 = std::max(a.z(), b.z());
    for (int k = 1; k < n; ++k) {
      // Graded upward whichever way the curve runs, so the 4 z edges agree.
      const int from_bottom = up ? k : n - k;
      const double f = (std::pow(1.3, from_bottom) - 1) / (std::pow(1.3, n) - 1);
      db.mutable_node(chain[static_cast<size_t>(k)]).z() = z0 + f * (z1 - z0);
    }
  }
  map_all_surfaces(model, db);
  commit_volume(db, 1, map::make_volume_map()->mesh({model, 1, &db}, {}));
  double volume = 0.0;
  for (const auto& h : db.volume(1).hexes) {
    const auto x = testing::hex_points(db, h);
    EXPECT_NEAR(testing::hex_scaled_jacobian(x), 1.0, 1e-9);
    volume += testing::hex_volume(x);
  }
  EXPECT_NEAR(volume, 24.0, 1e-9);
}

TEST(VolumeMapMesh, InconsistentSurfaceMeshThrows) {
  const geom::Model model = testing::brick_model(2, 3, 4);
  mesh::MeshDB db;
  mesh_curves(model, db, 0.5);
  map_all_surfaces(model, db);
  db.mutable_surface(1).quads.pop_back();  // a hole in the boundary
  try {
    map::make_volume_map()->mesh({model, 1, &db}, {});
    FAIL() << "expected MeshingError";
  } catch (const MeshingError& e) {
    EXPECT_EQ(e.code(), ErrorCode::MeshingFailed);
    EXPECT_EQ(e.entity().dim, 3);
  }
}

TEST(BlockLattice, SingleHexBoundary) {
  // The 6 faces of one hex: a 1x1x1 lattice.
  const std::vector<mesh::Quad> quads = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                         {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  const map::BlockLattice l = map::recover_block_lattice(quads);
  ASSERT_TRUE(l.ok) << l.why;
  EXPECT_EQ(l.ni, 1);
  EXPECT_EQ(l.nj, 1);
  EXPECT_EQ(l.nk, 1);
  EXPECT_EQ(std::set<int>(l.node.begin(), l.node.end()).size(), 8u);
}

}  // namespace
}  // namespace cooperage
