// A hollow stepped shaft with a concave fillet at its shoulder: a solid of
// revolution that no axial sweep takes (the fillet is tangent to the
// shoulder face, a concave blend) and that no plane, cylinder or cone of
// its faces cuts into sweepable pieces. The last resort cuts it along a
// meridian plane; the two halves sweep round the axis, the second one
// ending on the first one's source (a ring of sweeps). Built with OCCT
// directly (the journal's revolve takes polygons, not arcs).
#include "framework/pipeline/build_geometry.h"
#include "framework/pipeline/mesher.h"
#include "framework/pipeline/model_job.h"
#include "schemes/builtin_schemes.h"
#include "selector/select_schemes.h"
#include "support/hex_mesh_check.h"

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepPrimAPI_MakeRevol.hxx>
#include <BRepTools.hxx>
#include <GC_MakeArcOfCircle.hxx>
#include <gp_Ax1.hxx>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <unistd.h>

namespace cooperage::pipeline {
namespace {

namespace fs = std::filesystem;

// Profile in the xz-plane (x the radius), revolved about z: a bore of
// radius `bore` (0: none); r = 40 for z in [0, 30]; the shoulder z = 30 in
// to r = 28; a fillet of radius 8 (centre (28, 38)) up to r = 20 at z = 38;
// r = 20 up to z = 80.
std::string write_filleted_shaft(double bore) {
  BRepBuilderAPI_MakeWire wire;
  auto line = [&](double x0, double z0, double x1, double z1) {
    wire.Add(BRepBuilderAPI_MakeEdge(gp_Pnt(x0, 0, z0), gp_Pnt(x1, 0, z1)).Edge());
  };
  line(bore, 0, 40, 0);
  line(40, 0, 40, 30);
  line(40, 30, 28, 30);
  const double m = 8 / std::sqrt(2.0);
  wire.Add(BRepBuilderAPI_MakeEdge(
               GC_MakeArcOfCircle(gp_Pnt(28, 0, 30), gp_Pnt(28 - m, 0, 38 - m), gp_Pnt(20, 0, 38))
                   .Value())
               .Edge());
  line(20, 38, 20, 80);
  line(20, 80, bore, 80);
  line(bore, 80, bore, 0);
  const TopoDS_Face profile = BRepBuilderAPI_MakeFace(wire.Wire(), true).Face();
  const TopoDS_Shape shaft =
      BRepPrimAPI_MakeRevol(profile, gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), 2 * M_PI).Shape();
  const fs::path path =
      fs::temp_directory_path() / ("cooperage_shaft_" + std::to_string(::getpid()) + ".brep");
  BRepTools::Write(shaft, path.string().c_str());
  return path.string();
}

// The exact volume by Pappus: the profile's area times the path of its
// centroid, summed over a rectangle decomposition less the fillet's cove.
double exact_volume(double bore) {
  auto ring = [](double r0, double r1, double h) { return M_PI * (r1 * r1 - r0 * r0) * h; };
  // Bore to r = 40 below the shoulder, to r = 20 above it, and the 8 x 8
  // corner square at r in [20, 28], z in [30, 38] less its quarter disc.
  const double square = ring(20, 28, 8);
  const double quarter_area = M_PI * 64 / 4;
  // The quarter disc about (28, 38) towards smaller r and z: its centroid
  // lies 4 r / (3 pi) from the centre along each axis.
  const double centroid_r = 28 - 4 * 8 / (3 * M_PI);
  const double quarter = 2 * M_PI * centroid_r * quarter_area;
  return ring(bore, 40, 30) + ring(bore, 20, 50) + square - quarter;
}

// The shaft with a bore of radius `bore` meshed as `cooperage mesh` would
// at D/40, with the independent hex checks; `exact` is its volume.
struct Meshed {
  RunResult run;
  testing::HexMeshSummary summary;
  double exact = 0;
};

Meshed mesh_shaft(double bore) {
  const std::string path = write_filleted_shaft(bore);
  const geom::Model part = load_any(path);
  EXPECT_EQ(part.volumes().size(), 1u);
  Meshed m;
  m.exact = exact_volume(bore);
  EXPECT_NEAR(part.volume(1).volume, m.exact, 1e-6 * m.exact);  // the formula is the part
  ModelJobOptions options;
  options.size = part.box().diagonal() / 40.0;
  const io::Job job = model_job(path, options);
  scheme::Registry registry;
  register_builtin_schemes(registry);
  m.run = run_job(job, registry, selector::mesh_options());
  fs::remove(path);
  m.summary = testing::check_hex_mesh(m.run.model, m.run.mesh.mesh);
  EXPECT_EQ(m.run.mesh.mesh.wedge_count(), 0u);
  EXPECT_NEAR(m.summary.volume, m.exact, 0.01 * m.exact);
  return m;
}

TEST(DecomposeRevolved, AFilletedShaftIsCutAlongAMeridianAndSweptRoundItsAxis) {
  const Meshed m = mesh_shaft(10);
  const RunResult& r = m.run;
  EXPECT_GE(m.summary.min_sj, 0.2);
  ASSERT_EQ(r.decomposition.volumes.size(), 1u) << "not cut";
  const auto& cuts = r.decomposition.volumes.front().cuts;
  ASSERT_EQ(cuts.size(), 1u);
  EXPECT_NE(cuts.front().through.find("plane through the axis"), std::string::npos)
      << cuts.front().through;
  EXPECT_EQ(r.model.volumes().size(), 2u);
}

// Without the bore the halves of a meridian cut hold the axis, which no
// sweep round it takes: a core cylinder of half the smallest radius (20)
// is cut out first and swept along the axis, then the tube around it is
// halved along a meridian and swept round it.
TEST(DecomposeRevolved, ASolidFilletedShaftIsCoredThenHalved) {
  const Meshed m = mesh_shaft(0);
  const RunResult& r = m.run;
  EXPECT_GE(m.summary.min_sj, 0.5);  // measured 0.70
  ASSERT_EQ(r.decomposition.volumes.size(), 1u) << "not cut";
  const auto& cuts = r.decomposition.volumes.front().cuts;
  ASSERT_EQ(cuts.size(), 2u);
  EXPECT_NE(cuts[0].through.find("core cylinder r = 10"), std::string::npos) << cuts[0].through;
  EXPECT_NE(cuts[1].through.find("plane through the axis"), std::string::npos) << cuts[1].through;
  EXPECT_EQ(r.model.volumes().size(), 3u);
}

}  // namespace
}  // namespace cooperage::pipeline
