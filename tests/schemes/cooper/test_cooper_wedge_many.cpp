// Many-to-one sweeps in wedge and mixed mode (Blacker 1996, abstract:
// "a wedge/hexahedral element mix ... by simply allowing triangle and/or
// mixed triangle/quadrilateral cap meshes"): every cap stack is meshed once
// with triangles (or quad-dominant) and projected through its barrels;
// wedge count = sum over stacks of cap triangles x layers, volume of the
// (faceted) solid, conformal, no inverted element, side faces quads only.
#include "support/mixed_mesh_check.h"
#include "support/rigid_motion.h"

#include "framework/geometry/occ/workbench.h"
#include "framework/pipeline/mesher.h"
#include "schemes/builtin_schemes.h"
#include "schemes/cooper/elements.h"
#include "selector/select_schemes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

namespace cooperage::cooper {
namespace {

using geom::Vec3;

io::MeshSettings settings_for(double size, io::ElementKind elements) {
  io::MeshSettings s;
  s.size = size;
  io::VolumeSetting v;
  v.id = 1;
  v.elements = elements;
  s.volumes.push_back(v);
  return s;
}

pipeline::MeshResult mesh(const geom::Model& model, const io::MeshSettings& settings) {
  scheme::Registry registry;
  register_builtin_schemes(registry);
  return pipeline::mesh_model(model, settings, registry, selector::mesh_options());
}

int first_node(const mesh::SurfaceMeshData& s) {
  return s.quads.empty() ? s.tris.front()[0] : s.quads.front()[0];
}

// A planar surface facing z (a cap), or -1e300 when it is not one; else its height.
double cap_height(const geom::Model& model, const mesh::MeshDB& db, int id) {
  const auto& g = *model.surface(id).geometry;
  const Vec3 x = db.node(first_node(db.surface(id)));
  if (g.type() != geom::SurfaceType::Plane ||
      std::abs(std::abs(g.project(x).normal.z()) - 1) > 1e-9) {
    return -1e300;
  }
  return x.z();
}

// The cap surface at height z (the only one there in these models).
int cap_at(const geom::Model& model, const mesh::MeshDB& db, double z) {
  for (const auto& [id, s] : db.surfaces()) {
    if (std::abs(cap_height(model, db, id) - z) < 1e-9) return id;
  }
  return 0;
}

// Intervals of a straight z-parallel curve from z0 to z1 (the layers there).
int layers_between(const geom::Model& model, const mesh::MeshDB& db, double z0, double z1) {
  for (const auto& c : model.curves()) {
    const Vec3 a = model.vertex(c.start_vertex).point;
    const Vec3 b = model.vertex(c.end_vertex).point;
    if ((a - b).head<2>().norm() > 1e-9) continue;
    if (std::abs(std::min(a.z(), b.z()) - z0) < 1e-9 &&
        std::abs(std::max(a.z(), b.z()) - z1) < 1e-9) {
      return static_cast<int>(db.curve_nodes(c.id).size()) - 1;
    }
  }
  return -1;
}

// Side faces (every surface but the caps) carry quads only.
void expect_quad_sides(const geom::Model& model, const mesh::MeshDB& db, const char* name) {
  for (const auto& [id, s] : db.surfaces()) {
    if (cap_height(model, db, id) > -1e300) continue;
    EXPECT_TRUE(s.tris.empty()) << name << ": side surface " << id << " has triangles";
  }
}

// A boss of height hb on a body of height h (body from z = 0): two stacks,
// the boss top swept through both barrels, the shoulder through the body.
void expect_two_stacks(const geom::Model& model, const pipeline::MeshResult& r, double h, double hb,
                       const char* name) {
  ASSERT_EQ(r.plan.volumes.at(1).scheme, "cooper") << name;
  const int top = cap_at(model, r.mesh, h + hb), shoulder = cap_at(model, r.mesh, h);
  ASSERT_GT(top, 0) << name;
  ASSERT_GT(shoulder, 0) << name;
  const int lb = layers_between(model, r.mesh, h, h + hb), l = layers_between(model, r.mesh, 0, h);
  ASSERT_GT(lb, 0) << name;
  ASSERT_GT(l, 0) << name;
  const auto& T = r.mesh.surface(top);
  const auto& S = r.mesh.surface(shoulder);
  size_t wedges = 0, hexes = 0;
  for (const auto& [id, v] : r.mesh.volumes()) {
    wedges += v.wedges.size();
    hexes += v.hexes.size();
  }
  EXPECT_EQ(wedges,
            T.tris.size() * static_cast<size_t>(lb + l) + S.tris.size() * static_cast<size_t>(l))
      << name;
  EXPECT_EQ(hexes,
            T.quads.size() * static_cast<size_t>(lb + l) + S.quads.size() * static_cast<size_t>(l))
      << name;
  expect_quad_sides(model, r.mesh, name);
}

double polygon_area(const geom::Model& model, const mesh::MeshDB& db, double z, double radius) {
  for (const auto& c : model.curves()) {
    if (c.start_vertex != c.end_vertex) continue;
    const auto& nodes = db.curve_nodes(c.id);
    const Vec3 p = db.node(nodes.front());
    if (std::abs(p.z() - z) > 1e-9 || std::abs(p.head<2>().norm() - radius) > 1e-6) continue;
    double a = 0;
    for (size_t k = 0; k + 1 < nodes.size(); ++k) {
      const Vec3 u = db.node(nodes[k]), v = db.node(nodes[k + 1]);
      a += 0.5 * (u.x() * v.y() - u.y() * v.x());
    }
    return std::abs(a);
  }
  return -1;
}

// Two appendages on top and one below a 6 x 4 x 2 block (volume 52.875):
// the middle barrel has imprinted subcaps on both ends.
void appendages(occ::Workbench& wb) {
  wb.brick("b", {0, 0, 0}, {6, 4, 2});
  wb.brick("t1", {1, 1, 2}, {1.5, 1.5, 1});
  wb.brick("t2", {4, 0.25, 2}, {1, 0.75, 0.5});
  wb.brick("d1", {3.5, 1.5, -1}, {1.5, 1.5, 1});
  wb.fuse("part", {"b", "t1", "t2", "d1"});
}

void cylinder_boss(occ::Workbench& wb) {
  wb.cylinder("body", {0, 0, 0}, {0, 0, 1}, 2.0, 3.0);
  wb.cylinder("boss", {0, 0, 3}, {0, 0, 1}, 1.0, 1.5);
  wb.fuse("part", {"body", "boss"});
}

// The faceted solid: the curve meshes of the circles are polygons, and the
// sweep is straight, so the mesh fills exactly the polygonal prisms.
double faceted_cylinder_boss(const geom::Model& model, const mesh::MeshDB& db) {
  return polygon_area(model, db, 0.0, 2.0) * 3.0 + polygon_area(model, db, 4.5, 1.0) * 1.5;
}

TEST(CooperWedgeMany, CylinderWithBossSweepsWedges) {
  occ::Workbench wb;
  cylinder_boss(wb);
  const geom::Model model = wb.build_model();
  const auto r = mesh(model, settings_for(0.25, io::ElementKind::Wedge));
  expect_two_stacks(model, r, 3.0, 1.5, "cylinder_boss wedge");
  const testing::MixedMeshSummary s = testing::check_mixed_mesh(model, r.mesh);
  EXPECT_EQ(s.hexes, 0u);
  const double faceted = faceted_cylinder_boss(model, r.mesh);
  EXPECT_NEAR(s.volume, faceted, 1e-9 * faceted);
  const double solid = model.volume(1).volume;  // the polygons lie inside the circles
  EXPECT_LT(s.volume, solid);
  EXPECT_GT(s.volume, 0.99 * solid);
  EXPECT_GE(s.min_wedge_sj, 0.5);
  ::testing::Test::RecordProperty("cylinder_boss_min_wedge_scaled_jacobian",
                                  std::to_string(s.min_wedge_sj));
  std::printf(
      "[cooper wedge II] cylinder_boss: %zu wedges, min wedge SJ %.4f, volume %.6f "
      "(faceted %.6f, solid %.6f)\n",
      s.wedges, s.min_wedge_sj, s.volume, faceted, solid);
}

TEST(CooperWedgeMany, SquareBossOnBrickHasTheExactVolume) {
  occ::Workbench wb;
  wb.brick("b", {0, 0, 0}, {4, 4, 2});
  wb.brick("boss", {1.5, 1.5, 2}, {1, 1, 1});
  wb.fuse("part", {"b", "boss"});
  const geom::Model model = wb.build_model();
  const auto r = mesh(model, settings_for(0.25, io::ElementKind::Wedge));
  expect_two_stacks(model, r, 2.0, 1.0, "square_boss wedge");
  const testing::MixedMeshSummary s = testing::check_mixed_mesh(model, r.mesh);
  EXPECT_EQ(s.hexes, 0u);
  EXPECT_NEAR(s.volume, 33.0, 33.0 * 1e-9);
  EXPECT_GE(s.min_wedge_sj, 0.5);
  std::printf("[cooper wedge II] square_boss: %zu wedges, min wedge SJ %.4f\n", s.wedges,
              s.min_wedge_sj);
}

// Appendages on top and bottom: both real caps of the middle barrel are
// imprinted and meshed in 2D by the triangle polygon mesher (sec. 5.2, 6.1).
TEST(CooperWedgeMany, AppendagesOnTopAndBottomWithTriangleSubcaps) {
  occ::Workbench wb;
  appendages(wb);
  const geom::Model model = wb.build_model();
  const auto r = mesh(model, settings_for(0.25, io::ElementKind::Wedge));
  ASSERT_EQ(r.plan.volumes.at(1).scheme, "cooper");
  const testing::MixedMeshSummary s = testing::check_mixed_mesh(model, r.mesh);
  EXPECT_EQ(s.hexes, 0u);
  EXPECT_NEAR(s.volume, 52.875, 52.875 * 1e-9);
  EXPECT_GT(s.min_wedge_sj, 0.3);
  expect_quad_sides(model, r.mesh, "appendages wedge");
  std::printf("[cooper wedge II] appendages: %zu wedges, min wedge SJ %.4f\n", s.wedges,
              s.min_wedge_sj);
}

// Mixed mode on the same cylinder: the round caps (a disc and an annulus,
// no corner below 90 degrees) are no map/submap faces, so they are meshed
// quad_dominant, i.e. paved with the quads below the mixed quality split.
// Pave reaches that quality on round caps, so no quad is split: no wedge,
// and the mesh is hex mode's, which paves the same caps.
TEST(CooperWedgeMany, CylinderWithBossMixedNeedsNoTriangles) {
  occ::Workbench wb;
  cylinder_boss(wb);
  const geom::Model model = wb.build_model();
  const auto r = mesh(model, settings_for(0.25, io::ElementKind::Mixed));
  expect_two_stacks(model, r, 3.0, 1.5, "cylinder_boss mixed");
  for (const auto& [id, entry] : r.plan.surfaces) {
    EXPECT_TRUE(entry.scheme != "tri" && entry.scheme != "pave")
        << "surface " << id << ": " << entry.scheme;
  }
  const testing::MixedMeshSummary s = testing::check_mixed_mesh(model, r.mesh);
  EXPECT_GT(s.hexes, 0u);
  EXPECT_EQ(s.wedges, 0u);
  const double faceted = faceted_cylinder_boss(model, r.mesh);
  EXPECT_NEAR(s.volume, faceted, 1e-9 * faceted);
  EXPECT_GE(s.min_hex_sj, kMixedMinQuadQuality);
  const auto h = mesh(model, settings_for(0.25, io::ElementKind::Hex));
  ASSERT_EQ(h.mesh.node_count(), r.mesh.node_count());
  EXPECT_EQ(h.mesh.volume(1).hexes, r.mesh.volume(1).hexes);
  std::printf("[cooper mixed II] cylinder_boss: %zu hexes, %zu wedges, min SJ hex %.4f\n", s.hexes,
              s.wedges, s.min_hex_sj);
}

// Mixed mode with imprinted subcaps on both ends of the middle barrel: they
// are meshed in 2D by the quad-dominant polygon mesher (pave's 2D core, poor
// quads split), which needs even loops as in hex mode. Rectangles only:
// every cap quad reaches the mixed quality, so every element is a hex and
// the mesh is hex mode's.
TEST(CooperWedgeMany, AppendagesMixedAreHexes) {
  occ::Workbench wb;
  appendages(wb);
  const geom::Model model = wb.build_model();
  const auto r = mesh(model, settings_for(0.25, io::ElementKind::Mixed));
  ASSERT_EQ(r.plan.volumes.at(1).scheme, "cooper");
  const testing::MixedMeshSummary s = testing::check_mixed_mesh(model, r.mesh);
  EXPECT_NEAR(s.volume, 52.875, 52.875 * 1e-9);
  EXPECT_EQ(s.wedges, 0u);
  EXPECT_GE(s.min_hex_sj, kMixedMinQuadQuality);
  expect_quad_sides(model, r.mesh, "appendages mixed");
  const auto h = mesh(model, settings_for(0.25, io::ElementKind::Hex));
  ASSERT_EQ(h.mesh.node_count(), r.mesh.node_count());
  EXPECT_EQ(h.mesh.volume(1).hexes, r.mesh.volume(1).hexes);
  std::printf("[cooper mixed II] appendages: %zu hexes, min SJ hex %.4f\n", s.hexes, s.min_hex_sj);
}

// Orientation insensitivity of a many-to-one wedge sweep: the wedge mesh of
// the rigidly moved cylinder with boss is the moved mesh.
TEST(CooperWedgeMany, RigidMotionGivesTheMovedWedgeMesh) {
  const auto motion = testing::RigidMotion::random(1001);
  auto build = [&](bool moved) {
    occ::Workbench wb;
    cylinder_boss(wb);
    if (moved) motion.apply(wb, "part");
    return wb.build_model();
  };
  const geom::Model m0 = build(false), m1 = build(true);
  const auto r0 = mesh(m0, settings_for(0.25, io::ElementKind::Wedge));
  const auto r1 = mesh(m1, settings_for(0.25, io::ElementKind::Wedge));
  ASSERT_FALSE(r0.mesh.volume(1).wedges.empty());
  ASSERT_EQ(r0.mesh.node_count(), r1.mesh.node_count());
  EXPECT_EQ(r0.mesh.volume(1).wedges, r1.mesh.volume(1).wedges);
  EXPECT_LT(testing::moved_node_distance(r0.mesh, r1.mesh, motion), 1e-8);
}

}  // namespace
}  // namespace cooperage::cooper
