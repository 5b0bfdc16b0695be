// The fallback chain of `--dim 2` (schemes/quad_dominant/fallback_chain.h):
// on the cap of a blade-shaped prism, pave's all-quad mesh is kept when it
// reaches what the face's sharpest corner allows (sin of its angle), and
// traded for a quad-dominant or triangle mesh only when the corner is no
// excuse. The quality is measured here, against the plane's normal.
#include "schemes/quad_dominant/fallback_chain.h"

#include "framework/core/error.h"
#include "framework/geometry/occ/workbench.h"
#include "framework/io/job.h"
#include "framework/mesh/loop_nodes.h"
#include "framework/pipeline/mesh_curves.h"
#include "schemes/pave/pave_scheme.h"
#include "schemes/tri/tri_scheme.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <string>

namespace cooperage::quad_dominant {
namespace {

using geom::Vec3;

TEST(FallbackChain, ReachableFloorIsTheSineOfTheSharpestCorner) {
  EXPECT_DOUBLE_EQ(reachable_floor(0.2, 120.0), 0.2);
  EXPECT_DOUBLE_EQ(reachable_floor(0.2, 30.0), 0.2);  // sin 30 = 0.5 >= 0.2
  EXPECT_NEAR(reachable_floor(0.2, 8.0), 0.95 * std::sin(8.0 * M_PI / 180.0), 1e-12);
  // A cusp counts as 3 degrees: its chords open an angle.
  EXPECT_DOUBLE_EQ(reachable_floor(0.2, 0.0), reachable_floor(0.2, 3.0));
}

/// The z = 0 cap of a prism with profile (0,0) (L,0) (L,2) (2/tan a, 2),
/// L = 2/tan a + 4:
/// its corner at the origin has angle `degrees`. Curves meshed at `size`
/// (even total), then meshed by the chain pave -> tri with floor 0.2.
struct BladeCap {
  scheme::EntityMesh mesh;
  Vec3 normal;
};

/// The blade's cap with its curves meshed at `size` (even total).
struct BladeModel {
  geom::Model model;
  int sid = 0;
  mesh::MeshDB db;
};

void build_blade(double degrees, double size, BladeModel& out) {
  const double corner = degrees * M_PI / 180.0;
  occ::Workbench wb;
  const double tip = 2.0 / std::tan(corner), length = tip + 4.0;
  wb.prism("blade", {{0, 0, 0}, {length, 0, 0}, {length, 2, 0}, {tip, 2, 0}}, {}, {0, 0, 1});
  out.model = wb.build_model();
  const geom::Model& model = out.model;
  int& sid = out.sid;
  for (const auto& s : model.surfaces()) {
    if (s.geometry->type() == geom::SurfaceType::Plane && s.box.max.z() < 1e-9) sid = s.id;
  }
  EXPECT_GT(sid, 0);
  std::map<int, int> intervals;
  int total = 0;
  for (const auto& c : model.curves())
    intervals[c.id] = std::max(1, static_cast<int>(std::lround(c.length / size)));
  for (const auto& use : model.surface(sid).loops.front().uses) total += intervals[use.curve];
  if (total % 2) ++intervals[model.surface(sid).loops.front().uses.front().curve];
  pipeline::mesh_curves(model, intervals, io::MeshSettings{}, out.db);
}

BladeCap mesh_blade_cap(double degrees, double size) {
  BladeModel blade;
  build_blade(degrees, size, blade);
  const geom::Model& model = blade.model;
  const int sid = blade.sid;
  mesh::MeshDB& db = blade.db;
  const FallbackChain chain(pave::make_pave(), nullptr, tri::make_tri(), 0.2);
  scheme::Settings settings;
  settings.size = size;
  settings.allow_fallback = true;
  BladeCap out;
  out.mesh = chain.mesh({model, sid, &db}, settings);
  out.normal = model.surface(sid).geometry->project(out.mesh.coords.front()).normal;
  return out;
}

/// The smallest corner sine of the quads and triangles (triangles scaled
/// by 2/sqrt 3, as the quality report does).
double worst_element(const BladeCap& cap) {
  const auto& x = cap.mesh.coords;
  auto corner = [&](int prev, int at, int next) {
    const Vec3 a = x[static_cast<size_t>(next)] - x[static_cast<size_t>(at)];
    const Vec3 b = x[static_cast<size_t>(prev)] - x[static_cast<size_t>(at)];
    return a.cross(b).dot(cap.normal) / (a.norm() * b.norm());
  };
  double worst = 1.0;
  for (const auto& q : cap.mesh.quads)
    for (int k = 0; k < 4; ++k)
      worst = std::min(worst, corner(q[(k + 3) % 4], q[k], q[(k + 1) % 4]));
  for (const auto& t : cap.mesh.tris)
    for (int k = 0; k < 3; ++k)
      worst = std::min(worst, 2 / std::sqrt(3.0) * corner(t[(k + 2) % 3], t[k], t[(k + 1) % 3]));
  return worst;
}

// An 8-degree corner allows at most sin 8 = 0.139: pave's quads that reach
// (nearly) that are what the face allows. Before the floor followed the
// corner, the chain gave them up for triangles.
TEST(FallbackChain, AFaceWithAnEightDegreeCornerKeepsItsQuads) {
  const BladeCap cap = mesh_blade_cap(8.0, 0.25);
  EXPECT_TRUE(cap.mesh.tris.empty()) << cap.mesh.tris.size() << " triangles";
  ASSERT_FALSE(cap.mesh.quads.empty());
  const double worst = worst_element(cap);
  EXPECT_GT(worst, 0.0);
  EXPECT_GE(worst, 0.95 * std::sin(8.0 * M_PI / 180.0) - 1e-9);
  ASSERT_EQ(cap.mesh.warnings.size(), 1u);
  EXPECT_NE(cap.mesh.warnings[0].find("corner of 8.00 degrees"), std::string::npos)
      << cap.mesh.warnings[0];
}

// A 30-degree corner allows 0.5: the chain keeps nothing below 0.2 without
// saying so (quads, or triangles where pave's quads are poor).
TEST(FallbackChain, AThirtyDegreeCornerIsNoExcuse) {
  const BladeCap cap = mesh_blade_cap(30.0, 0.25);
  const double worst = worst_element(cap);
  if (worst < 0.2) {
    ASSERT_FALSE(cap.mesh.warnings.empty());
  } else {
    EXPECT_TRUE(cap.mesh.warnings.empty()) << cap.mesh.warnings[0];
  }
  EXPECT_GT(worst, 0.0);
}

/// A structured scheme that fails on every face, as submap does where the
/// interval counts do not fit a face's shape.
class FailingScheme final : public scheme::SurfaceScheme {
 public:
  explicit FailingScheme(std::string why) : why_(std::move(why)) {}
  std::string_view name() const override { return "failing"; }
  scheme::Applicability applicable(const scheme::SurfaceView&) const override {
    return scheme::Applicability::yes(1.0, "");
  }
  void constrain(const scheme::SurfaceView&, intervals::IntervalProblem&) const override {}
  scheme::EntityMesh mesh(const scheme::SurfaceView&, const scheme::Settings&) const override {
    throw MeshingError(ErrorCode::MeshingFailed, why_);
  }

 private:
  std::string why_;
};

std::string error_of(const FallbackChain& chain, const BladeModel& blade,
                     const scheme::Settings& settings) {
  try {
    chain.mesh({blade.model, blade.sid, &blade.db}, settings);
  } catch (const MeshingError& e) {
    return e.message();
  }
  return "";
}

// In 3D a volume scheme needs the surface scheme it chose, so a failure is
// the run's failure; but on a surface every volume takes as it finds it
// (cooper's uncut caps), any all-quad mesh will do: pave's, never triangles.
TEST(FallbackChain, ASurfaceTakenAsFoundFallsBackToQuadsOnly) {
  BladeModel blade;
  build_blade(30.0, 0.25, blade);
  const FallbackChain chain(std::make_unique<FailingScheme>("the lattice does not fit"),
                            pave::make_pave(), tri::make_tri(), 0.2);
  scheme::Settings settings;
  settings.size = 0.25;
  EXPECT_EQ(error_of(chain, blade, settings), "the lattice does not fit");

  settings.allow_quad_fallback = true;
  const scheme::EntityMesh m = chain.mesh({blade.model, blade.sid, &blade.db}, settings);
  EXPECT_TRUE(m.tris.empty());
  EXPECT_FALSE(m.quads.empty());
  ASSERT_EQ(m.warnings.size(), 1u);
  EXPECT_NE(m.warnings[0].find("failing failed (the lattice does not fit); pave's all-quad mesh"),
            std::string::npos)
      << m.warnings[0];

  // When the fallback fails too, the primary's reason is the one reported.
  const FallbackChain both(std::make_unique<FailingScheme>("the lattice does not fit"),
                           std::make_unique<FailingScheme>("no quads either"), tri::make_tri(),
                           0.2);
  EXPECT_EQ(error_of(both, blade, settings), "the lattice does not fit");
}

/// The z = 0 face of a lens prism (the common part of two cylinders of
/// radius 10, axes 19.6 apart): 0.4 wide, 4 long, its tips 23 degrees.
/// Curves meshed at `size`, with an even total.
void build_lens(double size, BladeModel& out) {
  occ::Workbench wb;
  wb.cylinder("left", {-9.8, 0, 0}, {0, 0, 1}, 10.0, 1.0);
  wb.cylinder("right", {9.8, 0, 0}, {0, 0, 1}, 10.0, 1.0);
  wb.common("lens", {"left", "right"});
  out.model = wb.build_model();
  for (const auto& s : out.model.surfaces()) {
    if (s.geometry->type() == geom::SurfaceType::Plane && s.box.max.z() < 1e-9) out.sid = s.id;
  }
  ASSERT_GT(out.sid, 0);
  std::map<int, int> intervals;
  int total = 0;
  for (const auto& c : out.model.curves())
    intervals[c.id] = std::max(1, static_cast<int>(std::lround(c.length / size)));
  for (const auto& use : out.model.surface(out.sid).loops.front().uses)
    total += intervals[use.curve];
  if (total % 2) ++intervals[out.model.surface(out.sid).loops.front().uses.front().curve];
  pipeline::mesh_curves(out.model, intervals, io::MeshSettings{}, out.db);
}

// A thread's flank on a bottle's neck, a sliver beside a fillet: a face
// thinner than its elements between two sharp tips. Where the quad schemes
// fail on it (on the bottle's thread, pave's worst quads were 0.16 and
// 0.04), triangles in it are needles; one row of quads between its arcs,
// with a triangle at each tip, reaches what its tips allow (their chords
// meet at about 20 degrees: 1.15 sin 20 = 0.39 for the triangle) and comes
// before them.
TEST(FallbackChain, AThinLensIsOneRowOfQuadsBetweenItsTips) {
  BladeModel lens;
  build_lens(0.3, lens);
  const FallbackChain chain(std::make_unique<FailingScheme>("the fronts collide"), nullptr,
                            tri::make_tri(), 0.2);
  scheme::Settings settings;
  settings.size = 0.3;
  settings.allow_fallback = true;
  BladeCap cap;
  cap.mesh = chain.mesh({lens.model, lens.sid, &lens.db}, settings);
  cap.normal = lens.model.surface(lens.sid).geometry->project(cap.mesh.coords.front()).normal;
  ASSERT_EQ(cap.mesh.warnings.size(), 1u);
  EXPECT_NE(cap.mesh.warnings[0].find("one row of elements between its two tips instead"),
            std::string::npos)
      << cap.mesh.warnings[0];
  // One row: no node inside, each quad takes an edge of either arc, each
  // tip triangle one of each, any other triangle one (where the arcs'
  // counts differ: the seams of the cylinders cut them unequally).
  const size_t boundary = cap.mesh.coords.size();
  EXPECT_EQ(2 * cap.mesh.quads.size() + cap.mesh.tris.size() + 2, boundary);
  EXPECT_GE(cap.mesh.tris.size(), 2u);
  EXPECT_LE(cap.mesh.tris.size(), 4u);
  EXPECT_GE(worst_element(cap), 0.3);
  // Conformal and whole: every boundary edge once, every other edge twice,
  // and the elements' area the polygon's.
  std::map<std::pair<int, int>, int> uses;
  double area = 0;
  const auto edge = [&](int a, int b) { ++uses[{std::min(a, b), std::max(a, b)}]; };
  const auto& x = cap.mesh.coords;
  for (const auto& q : cap.mesh.quads) {
    for (int k = 0; k < 4; ++k) edge(q[k], q[(k + 1) % 4]);
    area += 0.5 * ((x[q[2]] - x[q[0]]).cross(x[q[3]] - x[q[1]])).dot(cap.normal);
  }
  for (const auto& t : cap.mesh.tris) {
    for (int k = 0; k < 3; ++k) edge(t[k], t[(k + 1) % 3]);
    area += 0.5 * ((x[t[1]] - x[t[0]]).cross(x[t[2]] - x[t[0]])).dot(cap.normal);
  }
  const std::vector<int> ring = mesh::surface_loop_nodes(lens.model, lens.sid, lens.db)[0];
  double polygon = 0;
  for (size_t k = 0; k < ring.size(); ++k) {
    const Vec3 a = lens.db.node(ring[k]), b = lens.db.node(ring[(k + 1) % ring.size()]);
    polygon += 0.5 * a.cross(b).dot(cap.normal);
  }
  EXPECT_NEAR(area, polygon, 1e-9 * std::abs(polygon));
  int once = 0;
  for (const auto& [e, n] : uses) {
    EXPECT_TRUE(n == 1 || n == 2);
    once += n == 1;
  }
  EXPECT_EQ(static_cast<size_t>(once), ring.size());
}

}  // namespace
}  // namespace cooperage::quad_dominant
