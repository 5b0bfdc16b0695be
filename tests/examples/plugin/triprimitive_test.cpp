// The example plug-in's scheme, compiled in-tree and loaded as cooperage
// loads it: applicable() both ways, chosen by the selector where it scores
// best (triangles, where pave scores 0.6), a source cap of cooper, and the
// meshes it makes checked against the geometry.
#include "framework/pipeline/mesher.h"
#include "framework/geometry/occ/workbench.h"
#include "framework/scheme/plugin_loader.h"
#include "schemes/builtin_schemes.h"
#include "selector/select_schemes.h"
#include "support/hex_mesh_check.h"

#include <gtest/gtest.h>

#include <cmath>

namespace cooperage {
namespace {

const std::string kTriPrimitive = COOPERAGE_TEST_TRIPRIMITIVE;
const double kSqrt3 = std::sqrt(3.0);

// An equilateral triangle of side 2 extruded by 1: surfaces 1..3 are the
// rectangles, the two triangles are told apart by their curve count.
geom::Model triangular_prism() {
  occ::Workbench bench;
  bench.prism("p", {{0, 0, 0}, {2, 0, 0}, {1, kSqrt3, 0}}, {}, {0, 0, 1});
  return bench.build_model();
}

std::vector<int> triangles(const geom::Model& model) {
  std::vector<int> out;
  for (const auto& s : model.surfaces()) {
    if (s.loops.size() == 1 && s.loops[0].uses.size() == 3) out.push_back(s.id);
  }
  return out;
}

class TriPrimitive : public ::testing::Test {
 protected:
  void SetUp() override {
    register_builtin_schemes(registry_);
    scheme::load_plugin(registry_, kTriPrimitive);
    scheme_ = registry_.surface_scheme("triprimitive");
    ASSERT_NE(scheme_, nullptr);
  }
  scheme::Registry registry_;
  const scheme::SurfaceScheme* scheme_ = nullptr;
  geom::Model model_ = triangular_prism();
};

TEST_F(TriPrimitive, AppliesToTrianglesOnlyAndScoresTheirCorners) {
  ASSERT_EQ(triangles(model_).size(), 2u);
  for (int t : triangles(model_)) {
    const auto a = scheme_->applicable(scheme::SurfaceView{model_, t, nullptr});
    EXPECT_TRUE(a.ok) << a.why;
    EXPECT_NEAR(a.score, std::sin(M_PI / 3), 1e-6);  // each 60-degree corner in one quad
  }
  for (const auto& s : model_.surfaces()) {
    if (s.loops[0].uses.size() != 4) continue;
    const auto a = scheme_->applicable(scheme::SurfaceView{model_, s.id, nullptr});
    EXPECT_FALSE(a.ok);
    EXPECT_NE(a.why.find("has 4 corners; triprimitive needs 3"), std::string::npos) << a.why;
  }
  // A face with a hole: one loop is required.
  occ::Workbench bench;
  bench.prism("h", {{0, 0, 0}, {4, 0, 0}, {2, 4, 0}}, {{{1.5, 1, 0}, {2.5, 1, 0}, {2, 2, 0}}},
              {0, 0, 1});
  const geom::Model holed = bench.build_model();
  bool saw_hole = false;
  for (const auto& s : holed.surfaces()) {
    if (s.loops.size() != 2) continue;
    saw_hole = true;
    const auto a = scheme_->applicable(scheme::SurfaceView{holed, s.id, nullptr});
    EXPECT_FALSE(a.ok);
    EXPECT_NE(a.why.find("2 loops"), std::string::npos) << a.why;
  }
  EXPECT_TRUE(saw_hole);
}

TEST_F(TriPrimitive, TheSelectorPicksItForTrianglesOverPave) {
  io::MeshSettings settings;
  settings.size = 0.25;
  selector::SelectOptions options;
  options.dim = 2;
  const auto sel = selector::select_schemes(model_, registry_, settings, options);
  for (const auto& c : sel.surfaces) {
    const bool triangle = model_.surface(c.id).loops[0].uses.size() == 3;
    EXPECT_EQ(c.scheme, triangle ? "triprimitive" : "map") << "surface " << c.id;
  }
}

// Surface meshes: quads s0 s1 + s1 s2 + s2 s0 from the side counts (each
// patch is s_i x s_j), areas summing to the triangle's, no inverted quad.
TEST_F(TriPrimitive, MeshesTrianglesIntoThreeMappedPatches) {
  io::MeshSettings settings;
  settings.size = 0.3;
  const auto result = pipeline::mesh_model(model_, settings, registry_, selector::mesh_options(2));
  for (int t : triangles(model_)) {
    EXPECT_EQ(result.plan.surfaces.at(t).scheme, "triprimitive");
    std::array<int, 3> n{};
    for (size_t k = 0; k < 3; ++k) {
      const int curve = model_.surface(t).loops[0].uses[k].curve;
      n[k] = static_cast<int>(result.mesh.curve_nodes(curve).size()) - 1;
    }
    const int sum = n[0] + n[1] + n[2];
    ASSERT_EQ(sum % 2, 0);
    const int s0 = sum / 2 - n[0], s1 = sum / 2 - n[1], s2 = sum / 2 - n[2];
    ASSERT_GE(std::min({s0, s1, s2}), 1);
    const auto& quads = result.mesh.surface(t).quads;
    EXPECT_EQ(quads.size(), static_cast<size_t>(s0 * s1 + s1 * s2 + s2 * s0));
    double area = 0;
    const geom::Vec3 normal =
        model_.surface(t).geometry->project(model_.vertex(1).point).normal;  // planar: one normal
    for (const auto& q : quads) {
      const auto& x = result.mesh;
      for (int c = 0; c < 4; ++c) {  // every corner turns the same way as the face normal
        const geom::Vec3 e1 = x.node(q[(c + 1) % 4]) - x.node(q[c]);
        const geom::Vec3 e0 = x.node(q[c]) - x.node(q[(c + 3) % 4]);
        EXPECT_GT(e0.cross(e1).dot(normal), 0);
      }
      area += 0.5 * (x.node(q[2]) - x.node(q[0])).cross(x.node(q[3]) - x.node(q[1])).dot(normal);
    }
    EXPECT_NEAR(area, kSqrt3, 1e-9);
  }
  for (const auto& block : result.quality.blocks) {
    EXPECT_GT(block.find("scaled_jacobian")->min, 0.5) << "surface " << block.id;
  }
}

// Cooper takes its source cap from the best quad-cap scheme: the plug-in's.
TEST_F(TriPrimitive, CooperSweepsATriPrimitiveCap) {
  io::MeshSettings settings;
  settings.size = 0.3;
  const auto result = pipeline::mesh_model(model_, settings, registry_, selector::mesh_options(3));
  EXPECT_EQ(result.plan.volumes.at(1).scheme, "cooper");
  int capped = 0;
  for (int t : triangles(model_)) {
    const std::string& s = result.plan.surfaces.at(t).scheme;
    capped += s == "triprimitive";
    EXPECT_TRUE(s == "triprimitive" || s == scheme::kMeshedByVolume) << s;
  }
  EXPECT_EQ(capped, 1);
  const auto summary = testing::check_hex_mesh(model_, result.mesh);
  EXPECT_NEAR(summary.volume, kSqrt3, 1e-9);
  int layers = 0;
  for (const auto& s : model_.surfaces()) {  // a rectangle's vertical curve count
    if (s.loops[0].uses.size() != 4) continue;
    for (const auto& use : s.loops[0].uses) {
      const auto& c = model_.curve(use.curve);
      if (std::abs(model_.vertex(c.start_vertex).point.z() -
                   model_.vertex(c.end_vertex).point.z()) > 0.5) {
        layers = static_cast<int>(result.mesh.curve_nodes(c.id).size()) - 1;
      }
    }
  }
  ASSERT_GT(layers, 0);
  for (int t : triangles(model_)) {
    EXPECT_EQ(summary.hexes, result.mesh.surface(t).quads.size() * static_cast<size_t>(layers));
  }
}

}  // namespace
}  // namespace cooperage
