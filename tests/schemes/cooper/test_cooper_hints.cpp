// Sweep hints are binding (issue 15, deliverable 7): a journal's direction,
// source or target hint is honoured or the volume is refused naming the
// hint's journal line, never silently ignored. And the examples sweep along
// the axis their comments say, which the plans expose.
#include "framework/core/error.h"
#include "framework/geometry/occ/workbench.h"
#include "framework/io/journal_reader.h"
#include "framework/pipeline/build_geometry.h"
#include "framework/pipeline/mesher.h"
#include "plan_helpers.h"
#include "schemes/builtin_schemes.h"
#include "selector/select_schemes.h"
#include "support/real_cad.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <string>

namespace cooperage::cooper {
namespace {

namespace fs = std::filesystem;
using geom::Vec3;

// A journal written to a temporary file (its path is in the hints' places).
struct TempJournal {
  fs::path path;
  TempJournal(const std::string& name, const std::string& body) {
    path = fs::temp_directory_path() / ("cooperage_hints_" + name);
    std::ofstream(path) << body;
  }
  ~TempJournal() { fs::remove(path); }
};

const char* kBlindHole = R"(<cooperage version="1">
  <geometry>
    <brick name="block" origin="0 0 0" size="4 4 2"/>
    <cylinder name="hole" base="2 2 0.8" axis="0 0 1" radius="0.75" height="2"/>
    <cut name="part" inputs="block hole"/>
  </geometry>
  <mesh size="0.5">
    <volume id="1" direction="DIRECTION"/>
  </mesh>
</cooperage>
)";

std::string with_direction(const std::string& d) {
  std::string s = kBlindHole;
  s.replace(s.find("DIRECTION"), 9, d);
  return s;
}

// The cooper plan of volume 1 of a journal, with its hints.
std::shared_ptr<const VolumePlan> plan_of_journal(const fs::path& path, geom::Model& model,
                                                  std::unique_ptr<scheme::Registry>& registry) {
  const io::Job job = io::read_journal(path.string());
  model = pipeline::build_geometry(job);
  registry = std::make_unique<scheme::Registry>();
  register_builtin_schemes(*registry);
  return plan_test::scheme_plan(*registry, model, 1, job.mesh ? &*job.mesh : nullptr);
}

TEST(CooperHints, ADirectionHintIsHonoured) {
  for (const char* d : {"0 0 -1", "0 0 1"}) {
    const TempJournal j("honoured.xml", with_direction(d));
    geom::Model model;
    std::unique_ptr<scheme::Registry> registry;
    const auto p = plan_of_journal(j.path, model, registry);
    ASSERT_TRUE(p->ok) << d << ": " << p->why;
    const Vec3 want = d == std::string("0 0 1") ? Vec3(0, 0, 1) : Vec3(0, 0, -1);
    EXPECT_GT(sweep_direction(*p).dot(want), 0.999) << d << "\n" << describe_plan(*p);
  }
}

TEST(CooperHints, ADirectionHintThatCannotBeHonouredIsRefusedNamingItsLine) {
  // Along x the hole's floor would have to be a side: refused, naming the
  // journal line of the <volume> element (line 8), never swept along z.
  const TempJournal j("refused.xml", with_direction("1 0 0"));
  geom::Model model;
  std::unique_ptr<scheme::Registry> registry;
  const auto p = plan_of_journal(j.path, model, registry);
  EXPECT_FALSE(p->ok);
  EXPECT_NE(p->why.find("direction hint"), std::string::npos) << p->why;
  EXPECT_NE(p->why.find(j.path.string() + ":8"), std::string::npos) << p->why;
  // The run refuses too, with no mesh.
  const io::Job job = io::read_journal(j.path.string());
  try {
    pipeline::run_job(job, *registry, selector::mesh_options());
    FAIL() << "meshed against the hint";
  } catch (const MeshingError& e) {
    EXPECT_EQ(e.code(), ErrorCode::NotApplicable) << e.what();
  }
}

// Campaign seed 4 case 118 swept upwards by a hint: imprinting left a rib
// ending on no subcap and the run reported "map::at". Meshed or refused
// with the barrel named and the reason in words, never a library's text.
TEST(CooperHints, AnImprintingInconsistencyIsAMeshingErrorNamingTheBarrel) {
  const TempJournal j("rib.xml", R"(<cooperage version="1">
  <geometry>
    <brick name="block" origin="0 0 0" size="53.49 25.97 31.67"/>
    <brick name="f0" origin="10.24 6.2 31.67" size="14.72 2.66 12.06"/>
    <cylinder name="f1" base="16.39 10.99 -31.67" axis="0 0 1" radius="3.44" height="46.81"/>
    <cylinder name="f2" base="22.95 13.84 -31.67" axis="0 0 1" radius="3.07" height="95.01"/>
    <cylinder name="f3" base="20.13 4.28 22.04" axis="0 0 1" radius="5.3" height="41.3"/>
    <fuse name="body" inputs="block f0"/>
    <cut name="part" inputs="body f1 f2 f3"/>
  </geometry>
  <mesh size="4.41" decompose="off" finer_retries="0">
    <volume id="1" direction="0 0 1"/>
  </mesh>
</cooperage>
)");
  const io::Job job = io::read_journal(j.path.string());
  auto registry = std::make_unique<scheme::Registry>();
  register_builtin_schemes(*registry);
  try {
    pipeline::run_job(job, *registry, selector::mesh_options());
  } catch (const MeshingError& e) {
    const std::string what = e.what();
    EXPECT_EQ(e.code(), ErrorCode::MeshingFailed) << what;
    EXPECT_EQ(what.find("map::at"), std::string::npos) << what;
    EXPECT_NE(what.find("barrel "), std::string::npos) << what;
  }
}

TEST(CooperHints, SourceAndTargetHintsAreHonouredOrRefusedNamingTheirLine) {
  const std::string body = R"(<cooperage version="1">
  <geometry>
    <brick name="block" origin="0 0 0" size="2 3 4"/>
  </geometry>
  <mesh size="0.5">
    <volume id="1" scheme="cooper" sources="SOURCE" targets="TARGET"/>
  </mesh>
</cooperage>
)";
  // A brick: any pair of opposite faces. Name one face as the source.
  occ::Workbench wb;
  wb.brick("block", {0, 0, 0}, {2, 3, 4});
  const geom::Model brick = wb.build_model();
  int bottom = 0, top = 0, side = 0;
  for (const auto& s : brick.surfaces()) {
    const Vec3 c = 0.5 * (s.box.min + s.box.max);
    if (std::abs(c.z()) < 1e-9) bottom = s.id;
    if (std::abs(c.z() - 4) < 1e-9) top = s.id;
    if (std::abs(c.x()) < 1e-9) side = s.id;
  }
  auto journal = [&](int source, int target) {
    std::string s = body;
    s.replace(s.find("SOURCE"), 6, std::to_string(source));
    s.replace(s.find("TARGET"), 6, std::to_string(target));
    return s;
  };
  {
    const TempJournal j("st.xml", journal(top, bottom));
    geom::Model model;
    std::unique_ptr<scheme::Registry> registry;
    const auto p = plan_of_journal(j.path, model, registry);
    ASSERT_TRUE(p->ok) << p->why;
    EXPECT_EQ(p->source, top);
    EXPECT_EQ(p->target, bottom);
  }
  {
    // A source and a target that are not opposite: refused, the line named.
    const TempJournal j("bad.xml", journal(top, side));
    geom::Model model;
    std::unique_ptr<scheme::Registry> registry;
    const auto p = plan_of_journal(j.path, model, registry);
    EXPECT_FALSE(p->ok);
    EXPECT_NE(p->why.find(j.path.string() + ":6"), std::string::npos) << p->why;
  }
}

// The axis each shipped example sweeps its cooper volumes along, as its
// comment says (the sign: from the caps the sweep leaves).
TEST(CooperHints, ExamplesSweepAlongTheAxisTheirCommentsSay) {
  const std::map<std::string, Vec3> axes = {
      {"bracket_prism.xml", {0, 0, 1}},
      {"blind_hole.xml", {0, 0, -1}},
      {"stepped_shaft.xml", {0, 0, -1}},
      {"flanged_hub.xml", {0, 0, -1}},
      {"countersunk_hole.xml", {0, 0, -1}},
      {"flush_step.xml", {0, 0, -1}},
      {"self_intersecting_subcap.xml", {0, 0, 1}},
      {"inclined_top.xml", {0, 0, 1}},
  };
  for (const auto& [file, axis] : axes) {
    SCOPED_TRACE(file);
    geom::Model model;
    std::unique_ptr<scheme::Registry> registry;
    const auto p =
        plan_of_journal(fs::path(COOPERAGE_SOURCE_DIR) / "examples" / file, model, registry);
    ASSERT_TRUE(p && p->ok) << (p ? p->why : "no plan");
    EXPECT_GT(sweep_direction(*p).dot(axis), 0.999) << describe_plan(*p);
  }
  // Along z, either way: the parts swept from both ends' caps.
  for (const char* file : {"fig1_part.xml", "round_over_square.xml"}) {
    SCOPED_TRACE(file);
    geom::Model model;
    std::unique_ptr<scheme::Registry> registry;
    const auto p =
        plan_of_journal(fs::path(COOPERAGE_SOURCE_DIR) / "examples" / file, model, registry);
    ASSERT_TRUE(p && p->ok) << (p ? p->why : "no plan");
    EXPECT_GT(std::abs(sweep_direction(*p).z()), 0.999) << describe_plan(*p);
  }
}

// A hint of several sources and targets that no sorting reaches (a pump
// cover: a dome and a flange, to be swept through their thickness from the
// outer skin 1, 2, 4 to the inner 5, 7, 8; every sorting stops at the
// concave blend before the hints are checked): the refusal still names the
// hint and its journal line (issue 15 item 7). Skipped without the shared
// real-CAD folder.
TEST(CooperHints, AHintNoSortingReachesIsNamedInTheRefusal) {
  const std::string cad = testing::real_cad("occt_Pump_TopCover.brep");
  if (!fs::exists(cad)) GTEST_SKIP() << cad << " is absent (the shared real-CAD folder is not here)";
  const TempJournal j("cover.xml", R"(<cooperage version="1">
  <geometry>
    <import name="cover" file=")" + cad + R"("/>
  </geometry>
  <mesh size="12" decompose="off">
    <volume id="1" sources="1 2 4" targets="5 7 8"/>
  </mesh>
</cooperage>
)");
  geom::Model model;
  std::unique_ptr<scheme::Registry> registry;
  const auto p = plan_of_journal(j.path, model, registry);
  EXPECT_FALSE(p->ok);
  EXPECT_NE(p->why.find("sweep hint (sources 1 2 4, targets 5 7 8)"), std::string::npos) << p->why;
  EXPECT_NE(p->why.find(j.path.string() + ":6"), std::string::npos) << p->why;
}

}  // namespace
}  // namespace cooperage::cooper
