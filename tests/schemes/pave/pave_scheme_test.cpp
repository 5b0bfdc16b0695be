// Tests of the pave SurfaceScheme on CAD faces built with the OCCT
// workbench: applicable() both ways, the interval constraints, the
// rejection of odd boundaries, and valid all-quad meshes (quality printed)
// on planar, cylindrical and B-spline faces.
#include "schemes/pave/pave_scheme.h"

#include "framework/core/error.h"
#include "framework/geometry/occ/workbench.h"
#include "framework/intervals/solve.h"
#include "framework/pipeline/mesh_curves.h"
#include "framework/quality/quad_metrics.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <set>
#include <sstream>

namespace cooperage::pave {
namespace {

using geom::Vec3;

/// The surface of the model that best matches: planar with its box at the
/// top (max z), or of the given type with the largest area.
int top_planar_face(const geom::Model& m) {
  int best = 0;
  double z = -1e300;
  for (const auto& s : m.surfaces()) {
    if (s.geometry->type() != geom::SurfaceType::Plane) continue;
    if (s.box.size().z() > 1e-7) continue;
    if (s.box.min.z() > z) {
      z = s.box.min.z();
      best = s.id;
    }
  }
  return best;
}

int largest_face_of_type(const geom::Model& m, geom::SurfaceType type) {
  int best = 0;
  double area = -1;
  for (const auto& s : m.surfaces()) {
    if (s.geometry->type() == type && s.area > area) {
      area = s.area;
      best = s.id;
    }
  }
  return best;
}

struct FaceResult {
  int quads = 0;
  double min_sj = 2, median_sj = 0, irregular_per_100 = 0;
  std::string problems;
};

/// Assigns intervals (goal = length / size(curve)) under pave's constraints
/// for the face, meshes the curves and the face, and checks the result.
FaceResult mesh_face(const geom::Model& model, int sid, const std::function<double(int)>& size_of,
                     std::map<int, int> counts = {}) {
  const auto scheme = make_pave();
  const scheme::SurfaceView view{model, sid, nullptr};
  if (counts.empty()) {
    intervals::IntervalProblem problem;
    for (const auto& c : model.curves())
      problem.add_curve(c.id, std::max(c.length / size_of(c.id), 0.5));
    scheme->constrain(view, problem);
    counts = intervals::solve(problem).intervals;
  }
  mesh::MeshDB db;
  pipeline::mesh_curves(model, counts, io::MeshSettings{}, db);
  const scheme::SurfaceView meshed{model, sid, &db};
  const scheme::EntityMesh em = scheme->mesh(meshed, scheme::MeshParams{});

  FaceResult r;
  std::ostringstream err;
  if (!em.tris.empty()) err << "triangles; ";
  for (size_t i = 0; i < em.global.size(); ++i) {
    if (em.global[i] >= 0 && (em.coords[i] - db.node(em.global[i])).norm() > 0)
      err << "boundary node moved; ";
  }
  const geom::SurfaceGeometry& g = *model.surface(sid).geometry;
  std::vector<double> sj;
  std::map<std::pair<int, int>, int> dir;
  std::vector<int> valence(em.coords.size(), 0);
  for (const auto& q : em.quads) {
    quality::QuadNodes p;
    Vec3 c = Vec3::Zero();
    for (int k = 0; k < 4; ++k) {
      p[static_cast<size_t>(k)] = em.coords[static_cast<size_t>(q[static_cast<size_t>(k)])];
      c += p[static_cast<size_t>(k)] / 4;
      ++valence[static_cast<size_t>(q[static_cast<size_t>(k)])];
      ++dir[{q[static_cast<size_t>(k)], q[static_cast<size_t>((k + 1) % 4)]}];
    }
    sj.push_back(quality::quad_scaled_jacobian(p, g.project(c).normal));
    for (const auto& x : p) {
      if (g.project(x).distance > 1e-6 * (1 + x.norm())) err << "node off the surface; ";
    }
  }
  // Boundary edges in loop direction (global ids -> local ids).
  std::map<int, int> local_of;
  for (size_t i = 0; i < em.global.size(); ++i) {
    if (em.global[i] >= 0) local_of[em.global[i]] = static_cast<int>(i);
  }
  std::set<std::pair<int, int>> boundary;
  for (const auto& loop : model.surface(sid).loops) {
    for (const auto& use : loop.uses) {
      std::vector<int> chain = db.curve_nodes(use.curve);
      if (use.sense == geom::Sense::Reversed) std::reverse(chain.begin(), chain.end());
      for (size_t k = 0; k + 1 < chain.size(); ++k) {
        if (!local_of.count(chain[k]) || !local_of.count(chain[k + 1])) {
          err << "boundary node missing; ";
          continue;
        }
        boundary.insert({local_of[chain[k]], local_of[chain[k + 1]]});
      }
    }
  }
  for (const auto& [e, n] : dir) {
    // Interior edges are used in both directions; boundary edges once (a
    // seam is a boundary edge in both directions).
    const bool twin = dir.count({e.second, e.first}) > 0;
    const bool on_boundary = boundary.count(e) > 0;
    if (n != 1 || (on_boundary && twin && !boundary.count({e.second, e.first})) ||
        (!on_boundary && !twin)) {
      err << "bad edge " << e.first << "-" << e.second << "; ";
      break;
    }
  }
  for (const auto& e : boundary) {
    if (!dir.count(e)) err << "boundary edge unused; ";
  }
  std::sort(sj.begin(), sj.end());
  r.quads = static_cast<int>(sj.size());
  if (!sj.empty()) {
    r.min_sj = sj.front();
    r.median_sj = sj[sj.size() / 2];
    if (sj.front() <= 0) err << "inverted quad; ";
  }
  int irregular = 0;
  for (size_t i = 0; i < em.global.size(); ++i) irregular += em.global[i] < 0 && valence[i] != 4;
  r.irregular_per_100 = r.quads ? 100.0 * irregular / r.quads : 0;
  r.problems = err.str();
  return r;
}

void report(const char* name, const FaceResult& r) {
  std::printf("%-26s %6d %8.3f %8.3f %12.1f\n", name, r.quads, r.min_sj, r.median_sj,
              r.irregular_per_100);
}

TEST(PaveScheme, ApplicableToEveryFaceWithALoopOnly) {
  occ::Workbench b;
  b.brick("box", Vec3(0, 0, 0), Vec3(1, 1, 1));
  const geom::Model m = b.build_model();
  const auto scheme = make_pave();
  EXPECT_EQ(scheme->name(), "pave");
  for (const auto& s : m.surfaces()) {
    const auto a = scheme->applicable({m, s.id, nullptr});
    EXPECT_TRUE(a.ok) << a.why;
    EXPECT_GT(a.score, 0.0);
  }
  geom::Model bare;
  geom::Surface loose;
  loose.geometry = m.surface(1).geometry;
  const int sid = bare.add_surface(loose);
  const auto a = scheme->applicable({bare, sid, nullptr});
  EXPECT_FALSE(a.ok);
  EXPECT_NE(a.why.find("no boundary loop"), std::string::npos) << a.why;
}

TEST(PaveScheme, ConstrainMakesTheBoundaryEvenAndOddImpossible) {
  occ::Workbench b;
  b.cylinder("outer", Vec3(0, 0, 0), Vec3(0, 0, 1), 2.0, 1.0);
  b.cylinder("inner", Vec3(0, 0, -1), Vec3(0, 0, 1), 1.0, 3.0);
  b.cut("ring", {"outer", "inner"});
  const geom::Model m = b.build_model();
  const auto scheme = make_pave();
  for (const auto& s : m.surfaces()) {
    intervals::IntervalProblem problem;
    // Goals that would round to odd counts.
    for (const auto& c : m.curves()) problem.add_curve(c.id, 3.0);
    scheme->constrain({m, s.id, nullptr}, problem);
    int even = 0;
    for (const auto& c : problem.constraints()) even += c.kind == intervals::Constraint::Kind::Even;
    EXPECT_EQ(even, 1) << "surface " << s.id;
    const auto solution = intervals::solve(problem);
    int total = 0;
    for (const auto& loop : s.loops) {
      int sum = 0;
      for (const auto& use : loop.uses)
        sum += solution.intervals.at(use.curve);  // a seam counts twice
      EXPECT_GE(sum, 4) << "surface " << s.id;
      total += sum;
    }
    EXPECT_EQ(total % 2, 0) << "surface " << s.id;
  }
}

TEST(PaveScheme, OddLoopsWithAnEvenTotalAreMeshed) {
  occ::Workbench b;
  b.brick("plate", Vec3(0, 0, 0), Vec3(2, 2, 0.5));
  b.cylinder("h", Vec3(1, 1, -1), Vec3(0, 0, 1), 0.4, 3);
  b.cut("p", {"plate", "h"});
  const geom::Model m = b.build_model();
  const int sid = top_planar_face(m);
  ASSERT_GT(sid, 0);
  ASSERT_EQ(m.surface(sid).loops.size(), 2u);
  std::map<int, int> counts;
  for (const auto& c : m.curves()) counts[c.id] = 8;
  int outer = 0;
  for (const auto& use : m.surface(sid).loops[0].uses) {
    counts[use.curve] = 7;  // 28 ...
    outer += 7;
  }
  counts[m.surface(sid).loops[0].uses[0].curve] = 8;  // ... 29: odd
  int inner = 0;
  for (const auto& use : m.surface(sid).loops[1].uses) inner += (counts[use.curve] = 0);
  counts[m.surface(sid).loops[1].uses[0].curve] = 13;  // odd; total 42
  const FaceResult r = mesh_face(
      m, sid, [](int) { return 1.0; }, counts);
  report("plate, odd loops 29 + 13", r);
  EXPECT_EQ(r.problems, "");
  EXPECT_GT(r.min_sj, 0.3);
  (void)outer;
  (void)inner;
}

TEST(PaveScheme, LoopsAgainstTheNormalStillGiveQuadsAlongTheNormal) {
  occ::Workbench b;
  b.cylinder("c", Vec3(0, 0, 0), Vec3(0, 0, 1), 1.0, 1.0);
  geom::Model m = b.build_model();
  const int sid = top_planar_face(m);
  ASSERT_GT(sid, 0);
  // Walk every loop the other way: the face now lies on the loops' right.
  for (auto& loop : m.mutable_surface(sid).loops) {
    std::reverse(loop.uses.begin(), loop.uses.end());
    for (auto& use : loop.uses) use.sense = geom::flip(use.sense);
  }
  std::map<int, int> counts;
  for (const auto& c : m.curves()) counts[c.id] = 24;
  mesh::MeshDB db;
  pipeline::mesh_curves(m, counts, io::MeshSettings{}, db);
  const scheme::EntityMesh em = make_pave()->mesh({m, sid, &db}, scheme::MeshParams{});
  ASSERT_FALSE(em.quads.empty());
  const geom::SurfaceGeometry& g = *m.surface(sid).geometry;
  for (const auto& q : em.quads) {
    quality::QuadNodes p;
    Vec3 c = Vec3::Zero();
    for (int k = 0; k < 4; ++k) {
      p[static_cast<size_t>(k)] = em.coords[static_cast<size_t>(q[static_cast<size_t>(k)])];
      c += p[static_cast<size_t>(k)] / 4;
    }
    EXPECT_GT(quality::quad_scaled_jacobian(p, g.project(c).normal), 0.2);
  }
}

TEST(PaveScheme, OddBoundaryIsRejectedByApplicableAndMeshNamingTheSurface) {
  occ::Workbench b;
  b.brick("box", Vec3(0, 0, 0), Vec3(1, 1, 1));
  const geom::Model m = b.build_model();
  const int sid = top_planar_face(m);
  ASSERT_GT(sid, 0);
  // Before the curves are meshed applicable() cannot see intervals (constrain()
  // makes them even): it accepts the face.
  EXPECT_TRUE(make_pave()->applicable({m, sid, nullptr}).ok);
  std::map<int, int> counts;
  for (const auto& c : m.curves()) counts[c.id] = 3;
  counts[m.surface(sid).loops[0].uses[0].curve] = 4;  // 3 + 3 + 3 + 4 = 13
  mesh::MeshDB db;
  pipeline::mesh_curves(m, counts, io::MeshSettings{}, db);
  // With the curves meshed it rejects the odd total with the reason.
  const auto a = make_pave()->applicable({m, sid, &db});
  EXPECT_FALSE(a.ok);
  EXPECT_NE(a.why.find("odd number of intervals (13)"), std::string::npos) << a.why;
  EXPECT_NE(a.why.find("surface " + std::to_string(sid)), std::string::npos) << a.why;
  // An even total is accepted.
  {
    std::map<int, int> even = counts;
    even[m.surface(sid).loops[0].uses[0].curve] = 5;  // 14
    mesh::MeshDB db_even;
    pipeline::mesh_curves(m, even, io::MeshSettings{}, db_even);
    EXPECT_TRUE(make_pave()->applicable({m, sid, &db_even}).ok);
  }
  try {
    make_pave()->mesh({m, sid, &db}, scheme::MeshParams{});
    FAIL() << "an odd boundary was meshed";
  } catch (const MeshingError& e) {
    EXPECT_EQ(e.entity().dim, 2);
    EXPECT_EQ(e.entity().id, sid);
    EXPECT_NE(std::string(e.what()).find("odd"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("surface " + std::to_string(sid)), std::string::npos)
        << e.what();
  }
}

TEST(PaveScheme, CadFacesMeshAllQuadWithoutInversion) {
  std::printf("%-26s %6s %8s %8s %12s\n", "face", "quads", "min SJ", "med SJ", "irreg/100q");
  auto check = [](const char* name, const geom::Model& m, int sid,
                  const std::function<double(int)>& size) -> FaceResult {
    SCOPED_TRACE(name);
    if (sid <= 0) {
      ADD_FAILURE() << "face not found";
      return {};
    }
    const FaceResult r = mesh_face(m, sid, size);
    report(name, r);
    EXPECT_EQ(r.problems, "");
    EXPECT_GT(r.quads, 0);
    return r;
  };
  {
    occ::Workbench b;
    b.brick("box", Vec3(0, 0, 0), Vec3(1, 1, 1));
    const geom::Model m = b.build_model();
    const FaceResult r = check("square", m, top_planar_face(m), [](int) { return 0.1; });
    EXPECT_GT(r.median_sj, 0.8);
    EXPECT_GT(r.min_sj, 0.3);
  }
  {
    occ::Workbench b;
    b.cylinder("c", Vec3(0, 0, 0), Vec3(0, 0, 1), 1.0, 1.0);
    const geom::Model m = b.build_model();
    const FaceResult r = check("disk", m, top_planar_face(m), [](int) { return 0.15; });
    EXPECT_GT(r.median_sj, 0.8);
    EXPECT_GT(r.min_sj, 0.3);
    check("cylinder side (seam)", m, largest_face_of_type(m, geom::SurfaceType::Cylinder),
          [](int) { return 0.15; });
  }
  {
    occ::Workbench b;
    b.cylinder("outer", Vec3(0, 0, 0), Vec3(0, 0, 1), 2.0, 1.0);
    b.cylinder("inner", Vec3(0, 0, -1), Vec3(0, 0, 1), 1.0, 3.0);
    b.cut("ring", {"outer", "inner"});
    const geom::Model m = b.build_model();
    const FaceResult r = check("annulus", m, top_planar_face(m), [](int) { return 0.2; });
    EXPECT_GT(r.median_sj, 0.8);
    EXPECT_GT(r.min_sj, 0.3);
  }
  {
    occ::Workbench b;
    b.brick("plate", Vec3(0, 0, 0), Vec3(4, 2, 0.5));
    b.cylinder("h1", Vec3(1, 1, -1), Vec3(0, 0, 1), 0.4, 3);
    b.cylinder("h2", Vec3(2.2, 1, -1), Vec3(0, 0, 1), 0.3, 3);
    b.cylinder("h3", Vec3(3.2, 0.8, -1), Vec3(0, 0, 1), 0.25, 3);
    b.cut("p", {"plate", "h1", "h2", "h3"});
    const geom::Model m = b.build_model();
    const FaceResult r =
        check("plate with three holes", m, top_planar_face(m), [](int) { return 0.12; });
    EXPECT_GT(r.median_sj, 0.8);
    EXPECT_GT(r.min_sj, 0.3);
  }
  {
    occ::Workbench b;
    b.prism(
        "L",
        {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(2, 1, 0), Vec3(1, 1, 0), Vec3(1, 2, 0), Vec3(0, 2, 0)},
        {}, Vec3(0, 0, 0.5));
    const geom::Model m = b.build_model();
    const FaceResult r = check("L-shape", m, top_planar_face(m), [](int) { return 0.15; });
    EXPECT_GT(r.median_sj, 0.8);
    EXPECT_GT(r.min_sj, 0.3);
  }
  {
    occ::Workbench b;
    b.prism("neck",
            {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 0.45, 0), Vec3(2, 0.45, 0), Vec3(2, 0, 0),
             Vec3(3, 0, 0), Vec3(3, 1, 0), Vec3(2, 1, 0), Vec3(2, 0.55, 0), Vec3(1, 0.55, 0),
             Vec3(1, 1, 0), Vec3(0, 1, 0)},
            {}, Vec3(0, 0, 0.5));
    const geom::Model m = b.build_model();
    check("narrow neck", m, top_planar_face(m), [](int) { return 0.1; });
  }
  {
    // Boundary spacing 1:8: the outer square at size 1, the hole at 1/8.
    occ::Workbench b;
    b.brick("plate", Vec3(-4, -4, 0), Vec3(8, 8, 1));
    b.cylinder("h", Vec3(0, 0, -1), Vec3(0, 0, 1), 1.0, 3);
    b.cut("p", {"plate", "h"});
    const geom::Model m = b.build_model();
    check("spacing 1:8", m, top_planar_face(m), [&m](int c) {
      return m.curve(c).geometry->type() == geom::CurveType::Circle ? 0.125 : 1.0;
    });
  }
  {
    // A quarter of a thick tube: its outer face is a cylindrical patch.
    occ::Workbench b;
    b.revolve("tube", {Vec3(1, 0, 0), Vec3(1.5, 0, 0), Vec3(1.5, 0, 1), Vec3(1, 0, 1)},
              Vec3(0, 0, 0), Vec3(0, 0, 1), 90.0);
    const geom::Model m = b.build_model();
    const FaceResult r =
        check("cylindrical patch", m, largest_face_of_type(m, geom::SurfaceType::Cylinder),
              [](int) { return 0.1; });
    EXPECT_GT(r.median_sj, 0.8);
    EXPECT_GT(r.min_sj, 0.3);
  }
  {
    occ::Workbench b;
    b.cone("k", Vec3(0, 0, 0), Vec3(0, 0, 1), 1.0, 0.5, 1.0);
    const geom::Model m = b.build_model();
    check("cone side (seam)", m, largest_face_of_type(m, geom::SurfaceType::Cone),
          [](int) { return 0.1; });
  }
  {
    std::vector<std::vector<Vec3>> grid;
    for (int i = 0; i < 4; ++i) {
      grid.emplace_back();
      for (int j = 0; j < 4; ++j)
        grid.back().push_back(Vec3(i, j, 0.3 * std::sin(i) * std::cos(j)));
    }
    occ::Workbench b;
    b.bspline_patch("patch", grid, 0.0);
    const geom::Model m = b.build_model();
    check("B-spline patch", m, largest_face_of_type(m, geom::SurfaceType::BSpline),
          [](int) { return 0.2; });
  }
}

TEST(PaveScheme, RotatedFaceGivesTheRotatedMesh) {
  auto build = [](bool rotated) {
    occ::Workbench b;
    b.brick("plate", Vec3(0, 0, 0), Vec3(4, 2, 0.5));
    b.cylinder("h1", Vec3(1, 1, -1), Vec3(0, 0, 1), 0.4, 3);
    b.cylinder("h2", Vec3(2.6, 0.9, -1), Vec3(0, 0, 1), 0.3, 3);
    b.cut("p", {"plate", "h1", "h2"});
    if (rotated) b.rotate("p", Vec3(0.5, -1, 2), Vec3(1, 2, 3).normalized(), 37.0);
    return b.build_model();
  };
  const geom::Model m0 = build(false), m1 = build(true);
  ASSERT_EQ(m0.surfaces().size(), m1.surfaces().size());
  const Eigen::Matrix3d R =
      Eigen::AngleAxisd(37.0 * M_PI / 180.0, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  const Vec3 o(0.5, -1, 2);
  const int sid = top_planar_face(m0);
  ASSERT_GT(sid, 0);
  // The same face in the rotated model: the one whose centre is the rotated centre.
  const Vec3 c0 = 0.5 * (m0.surface(sid).box.min + m0.surface(sid).box.max);
  int sid1 = 0;
  double best = 1e300;
  for (const auto& s : m1.surfaces()) {
    if (s.geometry->type() != geom::SurfaceType::Plane) continue;
    const double d = std::abs(s.area - m0.surface(sid).area) +
                     (s.geometry->project(R * (c0 - o) + o).point - (R * (c0 - o) + o)).norm();
    if (d < best) {
      best = d;
      sid1 = s.id;
    }
  }
  ASSERT_GT(sid1, 0);
  auto mesh_of = [](const geom::Model& m, int s, mesh::MeshDB& db) {
    std::map<int, int> counts;
    for (const auto& c : m.curves())
      counts[c.id] = std::max(2, 2 * static_cast<int>(std::lround(c.length / 0.25)));
    pipeline::mesh_curves(m, counts, io::MeshSettings{}, db);
    return make_pave()->mesh({m, s, &db}, scheme::MeshParams{});
  };
  mesh::MeshDB db0, db1;
  const scheme::EntityMesh a = mesh_of(m0, sid, db0), b = mesh_of(m1, sid1, db1);
  ASSERT_EQ(a.quads.size(), b.quads.size());
  ASSERT_EQ(a.coords.size(), b.coords.size());
  // Same connectivity up to node numbering: map every node of the rotated
  // first mesh to the node of the second at the same place, then compare quads.
  std::vector<int> to_b(a.coords.size(), -1);
  for (size_t i = 0; i < a.coords.size(); ++i) {
    const Vec3 p = R * (a.coords[i] - o) + o;
    for (size_t j = 0; j < b.coords.size(); ++j) {
      if ((b.coords[j] - p).norm() < 1e-9 * (1 + p.norm())) to_b[i] = static_cast<int>(j);
    }
    ASSERT_GE(to_b[i], 0) << "node " << i << " of the rotated mesh has no counterpart";
  }
  auto canonical = [](mesh::Quad q) {
    std::rotate(q.begin(), std::min_element(q.begin(), q.end()), q.end());
    return q;
  };
  std::set<mesh::Quad> qb;
  for (const auto& q : b.quads) qb.insert(canonical(q));
  size_t common = 0;
  for (const auto& q : a.quads) {
    common +=
        qb.count(canonical({to_b[static_cast<size_t>(q[0])], to_b[static_cast<size_t>(q[1])],
                            to_b[static_cast<size_t>(q[2])], to_b[static_cast<size_t>(q[3])]}));
  }
  EXPECT_EQ(common, a.quads.size()) << "quads of the rotated face that are not the rotated quads";
}

TEST(PaveScheme, ThroughputIsPrinted) {
  occ::Workbench b;
  b.cylinder("c", Vec3(0, 0, 0), Vec3(0, 0, 1), 0.5, 1.0);
  const geom::Model m = b.build_model();
  for (int sid : {top_planar_face(m), largest_face_of_type(m, geom::SurfaceType::Cylinder)}) {
    std::map<int, int> counts;
    for (const auto& c : m.curves())
      counts[c.id] = 2 * static_cast<int>(std::lround(c.length / 0.006 / 2));
    mesh::MeshDB db;
    pipeline::mesh_curves(m, counts, io::MeshSettings{}, db);
    const auto t0 = std::chrono::steady_clock::now();
    const scheme::EntityMesh em = make_pave()->mesh({m, sid, &db}, scheme::MeshParams{});
    const double dt = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("pave on %s surface %d: %zu quads in %.3f s (%.0f quads/s)\n",
                geom::to_string(m.surface(sid).geometry->type()), sid, em.quads.size(), dt,
                em.quads.size() / dt);
    EXPECT_GT(em.quads.size(), 10000u);
  }
}

}  // namespace
}  // namespace cooperage::pave
