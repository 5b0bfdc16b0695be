// The quad_dominant surface scheme: applicable() and constrain() are the
// quad scheme's (both ways, at a low score), mesh() keeps its nodes and good
// quads and splits the poor ones. On a CAD face with a 20-degree corner,
// paved: triangles only next to the corner, boundary nodes exactly the
// curve nodes, every quad at least the threshold.
#include "schemes/quad_dominant/quad_dominant_scheme.h"

#include "framework/geometry/occ/workbench.h"
#include "framework/io/job.h"
#include "framework/pipeline/mesh_curves.h"
#include "schemes/pave/pave_scheme.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <set>

namespace cooperage::quad_dominant {
namespace {

using geom::Vec3;

// A stand-in quad scheme: a square and a kite with a 20-degree corner at
// local node 4; applicable only to surface 1, one even constraint.
class FakeQuads final : public scheme::SurfaceScheme {
 public:
  std::string_view name() const override { return "fake"; }
  scheme::Applicability applicable(const scheme::SurfaceView& view) const override {
    if (view.surface_id != 1) return scheme::Applicability::no("fake: only surface 1");
    return scheme::Applicability::yes(0.9, "fake: quads");
  }
  void constrain(const scheme::SurfaceView&, intervals::IntervalProblem& problem) const override {
    problem.add_even({1}, "fake even");
  }
  scheme::EntityMesh mesh(const scheme::SurfaceView&, const scheme::MeshParams&) const override {
    scheme::EntityMesh m;
    const double h = 2.0 * std::tan(10.0 * M_PI / 180.0);
    for (const Vec3& p : {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)}) m.add(p, 7);
    // Curve nodes (global ids), so improve_split_nodes may not move them.
    for (const Vec3& p : {Vec3(-2.6, 0, 0), Vec3(-0.6, -h, 0), Vec3(0, 0, 0), Vec3(-0.6, h, 0)}) {
      m.add(p, 8);
    }
    m.quads = {{0, 1, 2, 3}, {4, 5, 6, 7}};
    return m;
  }
};

TEST(QuadDominantScheme, DelegatesApplicabilityAndConstraints) {
  geom::Model model;
  model.add_surface(geom::Surface{});
  model.add_surface(geom::Surface{});
  const QuadDominantScheme scheme(std::make_unique<FakeQuads>(), 0.5);
  EXPECT_EQ(scheme.name(), "quad_dominant");
  const scheme::Applicability yes = scheme.applicable({model, 1, nullptr});
  EXPECT_TRUE(yes.ok);
  EXPECT_DOUBLE_EQ(yes.score, 0.1);  // never preferred over a quad scheme
  EXPECT_NE(yes.why.find("fake: quads"), std::string::npos) << yes.why;
  EXPECT_NE(yes.why.find("below 0.5"), std::string::npos) << yes.why;
  const scheme::Applicability no = scheme.applicable({model, 2, nullptr});
  EXPECT_FALSE(no.ok);
  EXPECT_EQ(no.why, "fake: only surface 1");
  intervals::IntervalProblem problem;
  problem.add_curve(1, 1.0);
  scheme.constrain({model, 1, nullptr}, problem);
  ASSERT_EQ(problem.constraints().size(), 1u);
}

TEST(QuadDominantScheme, SplitsOnlyThePoorQuad) {
  geom::Model model;
  model.add_surface(geom::Surface{});
  const QuadDominantScheme scheme(std::make_unique<FakeQuads>(), 0.5);
  const scheme::EntityMesh m = scheme.mesh({model, 1, nullptr}, scheme::MeshParams{});
  const scheme::EntityMesh quads = FakeQuads().mesh({model, 1, nullptr}, scheme::MeshParams{});
  EXPECT_EQ(m.coords, quads.coords);
  EXPECT_EQ(m.global, quads.global);
  ASSERT_EQ(m.quads.size(), 1u);
  EXPECT_EQ(m.quads[0], quads.quads[0]);  // the square
  ASSERT_EQ(m.tris.size(), 2u);           // the kite, split along 5-7
  for (const auto& t : m.tris) {
    EXPECT_TRUE(std::set<int>(t.begin(), t.end()).count(5));
    EXPECT_TRUE(std::set<int>(t.begin(), t.end()).count(7));
  }
}

// The cap of a prism with profile (0,0) (8,0) (8,2) (2/tan 20, 2), curves
// meshed at size 0.25 (even total), paved, poor quads split.
TEST(QuadDominantScheme, PavedFaceWithA20DegreeCornerHasTrianglesOnlyThere) {
  const double size = 0.25, corner = 20.0 * M_PI / 180.0;
  occ::Workbench wb;
  wb.prism("blade", {{0, 0, 0}, {8, 0, 0}, {8, 2, 0}, {2.0 / std::tan(corner), 2, 0}}, {},
           {0, 0, 1});
  const geom::Model model = wb.build_model();
  int sid = 0;
  for (const auto& s : model.surfaces()) {
    if (s.geometry->type() == geom::SurfaceType::Plane && s.box.max.z() < 1e-9) sid = s.id;
  }
  ASSERT_GT(sid, 0);
  std::map<int, int> intervals;
  int total = 0;
  for (const auto& c : model.curves()) {
    intervals[c.id] = std::max(1, static_cast<int>(std::lround(c.length / size)));
  }
  for (const auto& use : model.surface(sid).loops.front().uses) total += intervals[use.curve];
  if (total % 2) ++intervals[model.surface(sid).loops.front().uses.front().curve];  // pave: even
  mesh::MeshDB db;
  pipeline::mesh_curves(model, intervals, io::MeshSettings{}, db);
  const QuadDominantScheme scheme(pave::make_pave(), 0.5);
  const scheme::EntityMesh m = scheme.mesh({model, sid, &db}, scheme::MeshParams{size});
  ASSERT_FALSE(m.tris.empty());
  ASSERT_FALSE(m.quads.empty());
  double farthest = 0;
  for (const auto& t : m.tris) {
    for (int n : t)
      farthest = std::max(farthest, m.coords[static_cast<size_t>(n)].head<2>().norm());
  }
  EXPECT_LE(farthest, 3 * size);
  const Vec3 normal = model.surface(sid).geometry->project(m.coords.front()).normal;
  for (const auto& q : m.quads) {
    double worst = 1;
    for (int k = 0; k < 4; ++k) {
      const Vec3& p = m.coords[static_cast<size_t>(q[k])];
      const Vec3 in = p - m.coords[static_cast<size_t>(q[(k + 3) % 4])];
      const Vec3 out = m.coords[static_cast<size_t>(q[(k + 1) % 4])] - p;
      worst = std::min(worst, in.cross(out).dot(normal) / (in.norm() * out.norm()));
    }
    EXPECT_GE(worst, 0.5 - 1e-9);
  }
  // Boundary nodes are the curve nodes, unmoved (pave's, no split adds any).
  std::set<int> curve_nodes, used;
  for (const auto& use : model.surface(sid).loops.front().uses) {
    for (int n : db.curve_nodes(use.curve)) curve_nodes.insert(n);
  }
  for (size_t k = 0; k < m.global.size(); ++k) {
    if (m.global[k] < 0) continue;
    used.insert(m.global[k]);
    EXPECT_EQ(m.coords[k], db.node(m.global[k]));
  }
  EXPECT_EQ(used, curve_nodes);
  std::printf("[quad_dominant] blade cap: %zu quads, %zu triangles within %.3f of the corner\n",
              m.quads.size(), m.tris.size(), farthest);
}

}  // namespace
}  // namespace cooperage::quad_dominant
