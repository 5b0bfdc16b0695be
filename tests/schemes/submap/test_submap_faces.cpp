// The submap scheme on whole faces built with the OCC workbench: L, T, U and
// comb caps of prisms, a plate with an off-centre square hole, a cylinder
// side with a notch, the sides of swept and revolved L-profiles; rejections
// with reasons; the comb's constraints through the interval solver.
#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "framework/geometry/occ/workbench.h"
#include "schemes/submap/directions.h"
#include "schemes/submap/submap_plan.h"
#include "schemes/submap/submap_scheme.h"
#include "submap_face_run.h"

namespace cooperage::submap {
namespace {

using test::cap_at;
using test::expect_valid_surface_mesh;
using test::min_scaled_jacobian;
using test::run_face;

constexpr double kPi = 3.14159265358979323846;

geom::Model prism(const std::vector<std::vector<double>>& xy,
                  const std::vector<std::vector<std::vector<double>>>& holes = {}, double h = 1.0) {
  auto pts = [](const std::vector<std::vector<double>>& p) {
    std::vector<Vec3> out;
    for (const auto& q : p) out.emplace_back(q[0], q[1], 0.0);
    return out;
  };
  occ::Workbench wb;
  std::vector<std::vector<Vec3>> hs;
  for (const auto& hole : holes) hs.push_back(pts(hole));
  wb.prism("p", pts(xy), hs, Vec3(0, 0, h));
  return wb.build_model();
}

const std::vector<std::vector<double>> kL = {{0, 0}, {6, 0}, {6, 2}, {2, 2}, {2, 5}, {0, 5}};
const std::vector<std::vector<double>> kT = {{2, 0}, {4, 0}, {4, 3}, {6, 3},
                                             {6, 5}, {0, 5}, {0, 3}, {2, 3}};
const std::vector<std::vector<double>> kU = {{0, 0}, {6, 0}, {6, 4}, {4, 4},
                                             {4, 2}, {2, 2}, {2, 4}, {0, 4}};
const std::vector<std::vector<double>> kComb = {{0, 0}, {7, 0}, {7, 3}, {6, 3}, {6, 1}, {5, 1},
                                                {5, 3}, {4, 3}, {4, 1}, {3, 1}, {3, 3}, {2, 3},
                                                {2, 1}, {1, 1}, {1, 3}, {0, 3}};

struct Shape {
  const char* name;
  std::vector<std::vector<double>> xy;
  double area;
};

TEST(SubmapFaces, RectilinearCapsMeshExactly) {
  const auto scheme = make_submap();
  for (const Shape& s :
       {Shape{"L", kL, 18}, Shape{"T", kT, 18}, Shape{"U", kU, 20}, Shape{"comb", kComb, 15}}) {
    SCOPED_TRACE(s.name);
    const geom::Model model = prism(s.xy);
    for (double z : {0.0, 1.0}) {  // both caps: opposite natural normals
      const int sid = cap_at(model, z);
      ASSERT_GT(sid, 0);
      const auto app = scheme->applicable({model, sid, nullptr});
      ASSERT_TRUE(app.ok) << app.why;
      for (double size : {1.0, 0.5}) {
        const auto run = run_face(model, sid, *scheme, size);
        EXPECT_EQ(run.mesh.quads.size(), static_cast<size_t>(std::lround(s.area / (size * size))));
        expect_valid_surface_mesh(model, sid, run);
        EXPECT_GE(min_scaled_jacobian(model.surface(sid), run.mesh), 0.9);
      }
    }
  }
}

TEST(SubmapFaces, LShapeWithUnitSizeHasAreaQuads) {
  const geom::Model model = prism(kL);
  const int sid = cap_at(model, 1.0);
  const auto run = run_face(model, sid, *make_submap(), 1.0);
  EXPECT_EQ(run.mesh.quads.size(), 18u);
  size_t fresh = 0;
  for (int g : run.mesh.global) fresh += g < 0;
  EXPECT_EQ(fresh, 8u);  // interior lattice points (1,1)..(5,1), (1,2)..(1,4)
}

// An L-shaped cap whose long edge (x = 0, 5 intervals) is graded threefold.
// Graded by the size function, the lattice is smoothed like any other; graded
// by a volume scheme (cooper's walls on its caps' levels), the lattice keeps
// it.
TEST(SubmapFaces, AnLShapeKeepsOnlyAGradingAVolumeSchemePlaced) {
  const geom::Model model = prism(kL);
  const int sid = cap_at(model, 1.0);
  const auto scheme = make_submap();
  auto mesh_graded = [&](bool placed) {
    auto run = run_face(model, sid, *scheme, 1.0);
    int edge = 0;
    for (int c : test::curves_of(model, sid)) {
      const Vec3 a = model.vertex(model.curve(c).start_vertex).point;
      const Vec3 b = model.vertex(model.curve(c).end_vertex).point;
      if (std::abs(a.x()) + std::abs(b.x()) < 1e-9 && std::abs(a.y() - b.y()) > 4.9) edge = c;
    }
    EXPECT_GT(edge, 0);
    const std::vector<int> chain = run.db.curve_nodes(edge);
    EXPECT_EQ(chain.size(), 6u);
    const double first_y = run.db.node(chain.front()).y();
    const double ys[] = {0.0, 0.5, 1.0, 2.0, 3.5, 5.0};  // steps 0.5 .. 1.5
    for (size_t k = 1; k + 1 < chain.size(); ++k)
      run.db.mutable_node(chain[k]).y() = first_y < 2.5 ? ys[k] : 5.0 - ys[k];
    if (placed) run.db.set_curve_placed_by_volume(edge);
    const scheme::SurfaceView view{model, sid, &run.db, nullptr};
    scheme::Settings params;
    params.size = 1.0;
    run.mesh = scheme->mesh(view, params);
    return run;
  };
  const auto sized = mesh_graded(false);
  const auto placed = mesh_graded(true);
  ASSERT_EQ(sized.mesh.coords.size(), placed.mesh.coords.size());
  double moved = 0.0;
  for (size_t i = 0; i < sized.mesh.coords.size(); ++i)
    moved = std::max(moved, (sized.mesh.coords[i] - placed.mesh.coords[i]).norm());
  EXPECT_GT(moved, 0.01) << "the sized grading was not smoothed, or the placed one was";
  expect_valid_surface_mesh(model, sid, sized);
  expect_valid_surface_mesh(model, sid, placed);
  EXPECT_GE(min_scaled_jacobian(model.surface(sid), sized.mesh), 0.5);
  EXPECT_GE(min_scaled_jacobian(model.surface(sid), placed.mesh), 0.5);
}

TEST(SubmapFaces, CombConstraintsAreSatisfiedByTheIntervalAssignment) {
  // Odd sizes make the goals fractional, so the constraints do real work.
  const geom::Model model = prism(kComb);
  const int sid = cap_at(model, 1.0);
  const auto scheme = make_submap();
  for (double size : {0.3, 0.45, 0.7}) {
    SCOPED_TRACE(size);
    const auto run = run_face(model, sid, *scheme, size);
    ASSERT_FALSE(run.problem.constraints().empty());
    for (const auto& c : run.problem.constraints()) {
      EXPECT_TRUE(test::satisfied(c, run.solution.intervals)) << c.label;
    }
    // Quads = the lattice area: sum over +i curves of x times their j level
    // is awkward to state; check the area formula by the shoelace of the walk.
    const SubmapPlan plan = plan_submap(model, sid, {});
    std::vector<int> counts;
    for (const auto& use : plan.loops[0].uses)
      counts.push_back(run.solution.intervals.at(use.curve));
    long twice_area = 0;
    int i = 0, j = 0;
    for (size_t u = 0; u < counts.size(); ++u) {
      const auto step = direction_step(plan.loops[0].directions[u]);
      const int ni = i + step[0] * counts[u], nj = j + step[1] * counts[u];
      twice_area += static_cast<long>(i) * nj - static_cast<long>(ni) * j;
      i = ni;
      j = nj;
    }
    EXPECT_EQ(static_cast<long>(run.mesh.quads.size()) * 2, twice_area);
    expect_valid_surface_mesh(model, sid, run);
  }
}

TEST(SubmapFaces, PlateWithOffCentreSquareHole) {
  const geom::Model model =
      prism({{0, 0}, {10, 0}, {10, 8}, {0, 8}}, {{{6, 2}, {8, 2}, {8, 4}, {6, 4}}});
  const auto scheme = make_submap();
  for (double z : {0.0, 1.0}) {
    const int sid = cap_at(model, z);
    ASSERT_GT(sid, 0);
    ASSERT_EQ(model.surface(sid).loops.size(), 2u);
    const auto app = scheme->applicable({model, sid, nullptr});
    ASSERT_TRUE(app.ok) << app.why;
    const auto run = run_face(model, sid, *scheme, 1.0);
    EXPECT_EQ(run.mesh.quads.size(), 76u);
    expect_valid_surface_mesh(model, sid, run);
    EXPECT_GE(min_scaled_jacobian(model.surface(sid), run.mesh), 0.9);
    // Off-size: still valid, hole placed where it is.
    const auto odd = run_face(model, sid, *scheme, 0.7);
    expect_valid_surface_mesh(model, sid, odd);
    EXPECT_GE(min_scaled_jacobian(model.surface(sid), odd.mesh), 0.5);
  }
}

TEST(SubmapFaces, PlateWithRectangularHoleKeepsItsOrientation) {
  // A 3 x 1 hole: a hole walked a quarter turn off would not fit the geometry.
  const geom::Model model =
      prism({{0, 0}, {10, 0}, {10, 8}, {0, 8}}, {{{2, 5}, {5, 5}, {5, 6}, {2, 6}}});
  const int sid = cap_at(model, 1.0);
  const auto run = run_face(model, sid, *make_submap(), 1.0);
  EXPECT_EQ(run.mesh.quads.size(), 77u);
  expect_valid_surface_mesh(model, sid, run);
  EXPECT_GE(min_scaled_jacobian(model.surface(sid), run.mesh), 0.9);
}

TEST(SubmapFaces, HoleFitConstraintIsAdded) {
  const geom::Model model =
      prism({{0, 0}, {10, 0}, {10, 8}, {0, 8}}, {{{6, 2}, {8, 2}, {8, 4}, {6, 4}}});
  const int sid = cap_at(model, 1.0);
  intervals::IntervalProblem problem;
  make_submap()->constrain({model, sid, nullptr}, problem);
  int fits = 0;
  for (const auto& c : problem.constraints()) {
    if (c.label.find("fits") != std::string::npos) {
      ++fits;
      EXPECT_EQ(c.sense, intervals::Sense::GreaterEqual);
      EXPECT_EQ(c.rhs, 2);
    }
  }
  EXPECT_EQ(fits, 2);

  // Needed: a hole nearly as wide as the plate at a coarse size. The goals
  // (outer 10/3, hole 8/3) round to 3 and 3, where the hole cannot fit; the
  // fit rows make the solver leave a row of cells on either side.
  const geom::Model wide =
      prism({{0, 0}, {10, 0}, {10, 8}, {0, 8}}, {{{1, 2}, {9, 2}, {9, 4}, {1, 4}}});
  const int wid = cap_at(wide, 1.0);
  const auto run = run_face(wide, wid, *make_submap(), 3.0);
  expect_valid_surface_mesh(wide, wid, run);
}

TEST(SubmapFaces, CylinderSideWithNotch) {
  for (double angle : {90.0, 0.0}) {  // notch away from the seam, and across it
    SCOPED_TRACE(angle);
    occ::Workbench wb;
    wb.cylinder("c", Vec3(0, 0, 0), Vec3(0, 0, 1), 2.0, 4.0);
    wb.brick("b", Vec3(1.0, -0.8, 2.5), Vec3(3.0, 1.6, 2.0));
    wb.rotate("b", Vec3(0, 0, 0), Vec3(0, 0, 1), angle);
    wb.cut("n", {"c", "b"});
    const geom::Model model = wb.build_model();
    const int sid = test::find_surface(model, [](const geom::Surface& s) {
      return s.geometry->type() == geom::SurfaceType::Cylinder;
    });
    ASSERT_GT(sid, 0);
    const auto scheme = make_submap();
    const auto app = scheme->applicable({model, sid, nullptr});
    ASSERT_TRUE(app.ok) << app.why;
    for (double size : {0.5, 0.3}) {
      const auto run = run_face(model, sid, *scheme, size);
      expect_valid_surface_mesh(model, sid, run);
      EXPECT_GE(min_scaled_jacobian(model.surface(sid), run.mesh), 0.5);
      double area = 0.0;
      for (const auto& q : run.mesh.quads) {
        const auto& p = run.mesh.coords;
        area += 0.5 * (p[static_cast<size_t>(q[2])] - p[static_cast<size_t>(q[0])])
                          .cross(p[static_cast<size_t>(q[3])] - p[static_cast<size_t>(q[1])])
                          .norm();
      }
      EXPECT_NEAR(area, model.surface(sid).area, 0.02 * model.surface(sid).area);
    }
  }
}

TEST(SubmapFaces, CylinderSideWithWindowHole) {
  // A box through the wall, clear of top and bottom: away from the seam the
  // side face gets a hole loop of two lines and two arcs (four CORNERs);
  // across the seam the seam is cut and the window joins the outer loop.
  for (double angle : {150.0, 0.0}) {
    SCOPED_TRACE(angle);
    occ::Workbench wb;
    wb.cylinder("c", Vec3(0, 0, 0), Vec3(0, 0, 1), 2.0, 4.0);
    wb.brick("b", Vec3(1.0, -0.8, 1.5), Vec3(3.0, 1.6, 1.0));
    wb.rotate("b", Vec3(0, 0, 0), Vec3(0, 0, 1), angle);
    wb.cut("w", {"c", "b"});
    const geom::Model model = wb.build_model();
    const int sid = test::find_surface(model, [](const geom::Surface& s) {
      return s.geometry->type() == geom::SurfaceType::Cylinder;
    });
    ASSERT_GT(sid, 0);
    const auto scheme = make_submap();
    const auto app = scheme->applicable({model, sid, nullptr});
    ASSERT_TRUE(app.ok) << app.why;
    for (double size : {0.5, 0.35}) {
      const auto run = run_face(model, sid, *scheme, size);
      expect_valid_surface_mesh(model, sid, run);
      EXPECT_GE(min_scaled_jacobian(model.surface(sid), run.mesh), 0.5);
    }
  }
}

TEST(SubmapFaces, SidesOfSweptAndRevolvedLProfiles) {
  const auto scheme = make_submap();
  occ::Workbench wb;
  std::vector<Vec3> l;
  for (const auto& q : kL) l.emplace_back(q[0], q[1], 0.0);
  wb.prism("swept", l, {}, Vec3(0, 0, 3));
  std::vector<Vec3> profile;  // the L in the xz-plane, revolved about z
  for (const auto& q : kL) profile.emplace_back(23.0 + 0.5 * q[0], 0.0, 0.5 * q[1]);
  wb.revolve("turned", profile, Vec3(20, 0, 0), Vec3(0, 0, 1), 90);
  const geom::Model model = wb.build_model();
  int meshed = 0;
  for (const auto& s : model.surfaces()) {
    const auto app = scheme->applicable({model, s.id, nullptr});
    ASSERT_TRUE(app.ok) << app.why;
    const auto run = run_face(model, s.id, *scheme, 0.5);
    expect_valid_surface_mesh(model, s.id, run);
    if (s.box.max.x() < 10.0) {  // the swept L: rectangles and L caps
      EXPECT_GE(min_scaled_jacobian(s, run.mesh), 0.9);
    }
    ++meshed;
  }
  EXPECT_EQ(meshed, 8 + 8);
}

TEST(SubmapFaces, RejectionsSayWhy) {
  const auto scheme = make_submap();
  {  // equilateral triangle: three ENDs, sum 3
    const geom::Model m = prism({{0, 0}, {4, 0}, {2, 2 * std::sqrt(3.0)}});
    const auto app = scheme->applicable({m, cap_at(m, 1.0), nullptr});
    EXPECT_FALSE(app.ok);
    EXPECT_EQ(
        app.why.rfind("surface " + std::to_string(cap_at(m, 1.0)) + ": loop sum 3, needs 4", 0), 0u)
        << app.why;
  }
  {  // a sharp triangle: a vertex at ~14 degrees has no type
    const geom::Model m = prism({{0, 0}, {8, 0}, {8, 2}});
    const auto app = scheme->applicable({m, cap_at(m, 1.0), nullptr});
    EXPECT_FALSE(app.ok);
    EXPECT_NE(app.why.find("at 14 degrees cannot be END/SIDE/CORNER/REVERSAL"), std::string::npos)
        << app.why;
    EXPECT_NE(app.why.find("vertex "), std::string::npos);
  }
  {  // a disk: one circle, one vertex at 180 degrees, sum 0
    occ::Workbench wb;
    wb.cylinder("c", Vec3(0, 0, 0), Vec3(0, 0, 1), 1.0, 1.0);
    const geom::Model m = wb.build_model();
    const int sid = cap_at(m, 1.0);
    ASSERT_GT(sid, 0);
    const auto app = scheme->applicable({m, sid, nullptr});
    EXPECT_FALSE(app.ok);
    EXPECT_NE(app.why.find("loop sum 0, needs 4"), std::string::npos) << app.why;
    EXPECT_THROW(scheme->mesh({m, sid, nullptr}, {}), MeshingError);
  }
  {  // a needle notch: a REVERSAL vertex (sum rule met), a slit the lattice cannot fill
    const geom::Model m = prism({{0, 0}, {10, 0}, {10, 10}, {5.2, 10}, {5, 2}, {4.8, 10}, {0, 10}});
    const auto app = scheme->applicable({m, cap_at(m, 1.0), nullptr});
    EXPECT_FALSE(app.ok);
    EXPECT_NE(app.why.find("is a REVERSAL"), std::string::npos) << app.why;
  }
  {  // and the positive side of the same test: a rectangle is accepted
    const geom::Model m = prism({{0, 0}, {3, 0}, {3, 2}, {0, 2}});
    EXPECT_TRUE(scheme->applicable({m, cap_at(m, 1.0), nullptr}).ok);
  }
}

TEST(SubmapFaces, PinnedVertexTypeIsKept) {
  // Pentagon with angles 90, 90, 116.6, 126.9, 116.6: five ENDs (sum 5);
  // the repair makes the apex SIDE. Pinning the apex END moves the change
  // to the first other candidate instead.
  const geom::Model m = prism({{0, 0}, {4, 0}, {4, 3}, {2, 4}, {0, 3}});
  const int sid = cap_at(m, 1.0);
  int apex = 0;
  for (const auto& v : m.vertices()) {
    if ((v.point - Vec3(2, 4, 1)).norm() < 1e-9) apex = v.id;
  }
  ASSERT_GT(apex, 0);
  auto type_at = [&](const SubmapPlan& plan, int vertex) {
    for (size_t k = 0; k < plan.loops[0].corners.size(); ++k) {
      if (plan.loops[0].corners[k].vertex == vertex) return plan.loops[0].types.types[k];
    }
    return VertexType::Reversal;
  };
  const auto repaired = make_submap()->applicable({m, sid, nullptr});
  ASSERT_TRUE(repaired.ok) << repaired.why;
  EXPECT_NE(repaired.why.find("1 reclassified"), std::string::npos) << repaired.why;
  const SubmapPlan free_plan = plan_submap(m, sid, {});
  ASSERT_TRUE(free_plan.ok) << free_plan.why;
  EXPECT_EQ(type_at(free_plan, apex), VertexType::Side);

  io::VertexTypeSetting pin;
  pin.surface = sid;
  pin.vertex = apex;
  pin.type = io::VertexType::End;
  const SubmapPlan pinned = plan_submap(m, sid, {pin});
  ASSERT_TRUE(pinned.ok) << pinned.why;
  EXPECT_EQ(type_at(pinned, apex), VertexType::End);
  int sides = 0;
  for (VertexType t : pinned.loops[0].types.types) sides += t == VertexType::Side;
  EXPECT_EQ(sides, 1);

  // Through the scheme: the pin reaches the classification and the face meshes.
  io::MeshSettings job;
  job.vertex_types = {pin};
  const scheme::Settings settings = scheme::Settings::of(job);
  const auto scheme = make_submap();
  ASSERT_TRUE(scheme->applicable({m, sid, nullptr, &settings}).ok);
  const auto run = run_face(m, sid, *scheme, 0.5, &settings);
  expect_valid_surface_mesh(m, sid, run);
  // A pin on another surface changes nothing.
  pin.surface = sid + 100;
  EXPECT_EQ(type_at(plan_submap(m, sid, {pin}), apex), VertexType::Side);
}

TEST(SubmapFaces, MeshingIsDeterministic) {
  const geom::Model model =
      prism({{0, 0}, {10, 0}, {10, 8}, {0, 8}}, {{{6, 2}, {8, 2}, {8, 4}, {6, 4}}});
  const int sid = cap_at(model, 1.0);
  const auto a = run_face(model, sid, *make_submap(), 0.7);
  const auto b = run_face(model, sid, *make_submap(), 0.7);
  EXPECT_EQ(a.mesh.quads, b.mesh.quads);
  EXPECT_EQ(a.mesh.global, b.mesh.global);
  ASSERT_EQ(a.mesh.coords.size(), b.mesh.coords.size());
  for (size_t k = 0; k < a.mesh.coords.size(); ++k) EXPECT_EQ(a.mesh.coords[k], b.mesh.coords[k]);
}

}  // namespace
}  // namespace cooperage::submap
