// A volume its scheme accepted and then failed on is meshed again at half
// its size (framework/pipeline/finer_retry.h), and says so.
#include "framework/core/error.h"
#include "framework/pipeline/finer_retry.h"
#include "framework/pipeline/mesher.h"
#include "selector/select_schemes.h"

#include "journal_fixture.h"
#include "plans_like_map.h"
#include "support/mesh_checks.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace cooperage::pipeline {
namespace {

// A volume scheme that meshes as the volume map does, but fails (as cooper
// does on features closer than an element) while its mesh has fewer than
// `least` hexes: a coarse size fails, a fine enough one meshes.
class FailsWhenCoarse final : public testing::PlansLikeMap {
 public:
  FailsWhenCoarse(const scheme::VolumeScheme& map, std::size_t least)
      : PlansLikeMap(map), least_(least) {}
  std::string_view name() const override { return "fails_when_coarse"; }
  scheme::EntityMesh mesh(const scheme::VolumeView& view,
                          const scheme::Settings& settings) const override {
    scheme::EntityMesh m = map_.mesh(view, settings);
    if (m.hexes.size() < least_)
      throw MeshingError(
          ErrorCode::MeshingFailed, EntityRef::volume(view.volume_id),
          "hex 3 of layer 0 is inverted (" + std::to_string(m.hexes.size()) + " hexes)");
    return m;
  }

 private:
  std::size_t least_;
};

// Plans a straight sweep along the journal's direction hint, else along
// +z, as the volume map plans; what it meshes each way is the test's.
class PlansAStraightSweep : public testing::PlansLikeMap {
 public:
  using PlansLikeMap::PlansLikeMap;
  scheme::Applicability applicable(const scheme::VolumeView& view) const override {
    scheme::Applicability a = map_.applicable(view);
    if (!a.ok) return a;
    auto plan = std::make_shared<Along>();
    plan->d = {0.0, 0.0, downwards(view.settings(), view.volume_id) ? -1.0 : 1.0};
    a.plan = plan;
    return a;
  }

 protected:
  static bool downwards(const scheme::Settings& settings, int volume) {
    const io::VolumeSetting* v = settings.volume(volume);
    return v && v->direction && v->direction->z() < 0;
  }

 private:
  struct Along final : scheme::PlanData {
    std::array<double, 3> d{};
    std::optional<std::array<double, 3>> straight_sweep() const override { return d; }
  };
};

// Meshes (as the volume map does) only along -z and with at least `least`
// hexes: a sweep that fails one way at every size and meshes the other way.
class MeshesOnlyDownwards final : public PlansAStraightSweep {
 public:
  MeshesOnlyDownwards(const scheme::VolumeScheme& map, std::size_t least)
      : PlansAStraightSweep(map), least_(least) {}
  std::string_view name() const override { return "meshes_only_downwards"; }
  scheme::EntityMesh mesh(const scheme::VolumeView& view,
                          const scheme::Settings& settings) const override {
    scheme::EntityMesh m = map_.mesh(view, settings);
    if (!downwards(settings, view.volume_id) || m.hexes.size() < least_)
      throw MeshingError(ErrorCode::MeshingFailed, EntityRef::volume(view.volume_id),
                         "hex 3 of layer 0 is inverted");
    return m;
  }

 private:
  std::size_t least_;
};

// Moves the interior node at (1, 1, 1) of a map mesh of the 4-unit cube
// at size 1 by (0.3, 0.3, 0.3): the hex it leans into keeps a corner of
// scaled Jacobian 0.182342 (its edges (0.7, -0.3, -0.3) and its two turns:
// determinant 0.1 over the lengths cubed, 0.67^1.5), every hex stays valid
// and the volume is the brick's.
void lean_the_node_at_1_1_1(scheme::EntityMesh& m) {
  for (geom::Vec3& x : m.coords) {
    if ((x - geom::Vec3(1, 1, 1)).norm() < 1e-9) x += geom::Vec3(0.3, 0.3, 0.3);
  }
  m.hex_scaled_jacobian.clear();  // the report computes them on the moved node
}

// Meshes as the volume map does, and leans the node at (1, 1, 1) while its
// mesh has fewer than `least` hexes.
class PoorWhenCoarse final : public testing::PlansLikeMap {
 public:
  PoorWhenCoarse(const scheme::VolumeScheme& map, std::size_t least)
      : PlansLikeMap(map), least_(least) {}
  std::string_view name() const override { return "poor_when_coarse"; }
  scheme::EntityMesh mesh(const scheme::VolumeView& view,
                          const scheme::Settings& settings) const override {
    scheme::EntityMesh m = map_.mesh(view, settings);
    if (m.hexes.size() < least_) lean_the_node_at_1_1_1(m);
    return m;
  }

 private:
  std::size_t least_;
};

// Meshes as the volume map does, and leans the node at (1, 1, 1) when it
// sweeps upwards (and downwards too when `poor_both_ways`): a valid mesh
// whose worst hex is 0.182342.
class PoorUpwards final : public PlansAStraightSweep {
 public:
  PoorUpwards(const scheme::VolumeScheme& map, bool poor_both_ways)
      : PlansAStraightSweep(map), both_(poor_both_ways) {}
  std::string_view name() const override { return "poor_upwards"; }
  scheme::EntityMesh mesh(const scheme::VolumeView& view,
                          const scheme::Settings& settings) const override {
    scheme::EntityMesh m = map_.mesh(view, settings);
    if (!downwards(settings, view.volume_id) || both_) lean_the_node_at_1_1_1(m);
    return m;
  }

 private:
  bool both_;
};

class FinerRetries : public testing::JournalFixture {
 protected:
  void use_scheme(std::size_t least) {
    registry_.add(std::make_unique<FailsWhenCoarse>(*registry_.volume_scheme("map"), least));
  }
  void use_poor_scheme(std::size_t least) {
    registry_.add(std::make_unique<PoorWhenCoarse>(*registry_.volume_scheme("map"), least));
  }
  void use_poor_upwards_scheme(bool poor_both_ways = false) {
    registry_.add(std::make_unique<PoorUpwards>(*registry_.volume_scheme("map"), poor_both_ways));
  }
  void use_downwards_scheme(std::size_t least = 0) {
    registry_.add(std::make_unique<MeshesOnlyDownwards>(*registry_.volume_scheme("map"), least));
  }
  bool written(const char* file) const { return std::filesystem::exists(dir_ / file); }
  static double hex_volume(const mesh::MeshDB& db) {
    double v = 0;
    for (const auto& [id, vol] : db.volumes())
      for (const mesh::Hex& h : vol.hexes)
        v += cooperage::testing::hex_volume(cooperage::testing::hex_points(db, h));
    return v;
  }
};

// A 4-unit cube at size 1 has 64 hexes: too few for the scheme; at 0.5 it
// has 512.
TEST_F(FinerRetries, AVolumeThatFailsIsMeshedAtHalfItsSizeWithAWarning) {
  use_scheme(100);
  const RunResult r =
      run_job(journal(R"(  <geometry><brick name="b" origin="0 0 0" size="4 4 4"/></geometry>
  <mesh size="1"><volume id="1" scheme="fails_when_coarse"/></mesh>
  <export file="out.vtu"/>
)"),
              registry_, selector::mesh_options());
  EXPECT_FALSE(r.failed());
  EXPECT_EQ(r.mesh.mesh.hex_count(), 512u);
  EXPECT_NEAR(hex_volume(r.mesh.mesh), 64.0, 1e-9);
  ASSERT_FALSE(r.mesh.warnings.empty());
  const Warning& w = r.mesh.warnings.front();
  EXPECT_EQ(w.entity.dim, 3);
  EXPECT_EQ(w.entity.id, 1);
  EXPECT_EQ(w.message.rfind("meshed at size 0.5, half the size asked for (1), at which it failed: "
                            "hex 3 of layer 0 is inverted (64 hexes)",
                            0),
            0u)
      << w.message;
  EXPECT_TRUE(written("out.vtu"));
  ASSERT_FALSE(r.mesh.stages.empty());
  EXPECT_EQ(r.mesh.stages.front().stage, "failed attempts");
}

TEST_F(FinerRetries, NoRetryWhenTheJournalSaysNone) {
  use_scheme(100);
  try {
    run_job(journal(R"(  <geometry><brick name="b" origin="0 0 0" size="4 4 4"/></geometry>
  <mesh size="1" finer_retries="0"><volume id="1" scheme="fails_when_coarse"/></mesh>
  <export file="out.vtu"/>
)"),
            registry_, selector::mesh_options());
    ADD_FAILURE() << "no error";
  } catch (const MeshingError& e) {
    EXPECT_NE(std::string(e.what()).find("(64 hexes)"), std::string::npos) << e.what();
    EXPECT_EQ(e.hint().find("failed too"), std::string::npos) << e.hint();
  }
  EXPECT_FALSE(written("out.vtu"));
}

// 1 -> 0.5 -> 0.25 gives 64, 512, 4096 hexes: two halvings are not enough
// for 5000, and the error says what was tried.
TEST_F(FinerRetries, TheErrorSaysWhichSizesWereTried) {
  use_scheme(5000);
  try {
    run_job(journal(R"(  <geometry><brick name="b" origin="0 0 0" size="4 4 4"/></geometry>
  <mesh size="1"><volume id="1" scheme="fails_when_coarse"/></mesh>
  <export file="out.vtu"/>
)"),
            registry_, selector::mesh_options());
    ADD_FAILURE() << "no error";
  } catch (const MeshingError& e) {
    EXPECT_NE(std::string(e.what()).find("(4096 hexes)"), std::string::npos) << e.what();
    EXPECT_EQ(e.hint().rfind("meshing it again at a quarter the size (0.25) failed too; ", 0), 0u)
        << e.hint();
  }
  EXPECT_FALSE(written("out.vtu"));
}

// Only the volume that failed gets the smaller size; its own size, not the
// global one, is halved.
TEST_F(FinerRetries, OnlyTheFailedVolumeIsRefined) {
  use_scheme(100);
  const RunResult r = run_job(journal(R"(  <geometry>
    <brick name="a" origin="0 0 0" size="4 4 4"/>
    <brick name="b" origin="10 0 0" size="2 2 2"/>
  </geometry>
  <mesh size="0.5"><volume id="1" size="1" scheme="fails_when_coarse"/></mesh>
)"),
                              registry_, selector::mesh_options());
  EXPECT_FALSE(r.failed());
  EXPECT_EQ(r.mesh.mesh.volume(1).hexes.size(), 512u);
  EXPECT_EQ(r.mesh.mesh.volume(2).hexes.size(), 64u);
  EXPECT_NEAR(hex_volume(r.mesh.mesh), 64.0 + 8.0, 1e-9);
}

// A straight sweep that fails at its size and at half and a quarter of it
// is swept the other way at the size asked for, and says so.
TEST_F(FinerRetries, AStraightSweepFailingAtEverySizeIsSweptTheOtherWay) {
  use_downwards_scheme();
  const RunResult r =
      run_job(journal(R"(  <geometry><brick name="b" origin="0 0 0" size="4 4 4"/></geometry>
  <mesh size="1"><volume id="1" scheme="meshes_only_downwards"/></mesh>
  <export file="out.vtu"/>
)"),
              registry_, selector::mesh_options());
  EXPECT_FALSE(r.failed());
  EXPECT_EQ(r.mesh.mesh.hex_count(), 64u);  // the size asked for
  EXPECT_NEAR(hex_volume(r.mesh.mesh), 64.0, 1e-9);
  ASSERT_FALSE(r.mesh.warnings.empty());
  EXPECT_EQ(r.mesh.warnings.front().text(),
            "volume 1: meshed sweeping it the other way, along (0, 0, -1), at the size asked for "
            "(1); along (0, 0, 1) it failed at the size asked for and at smaller ones: hex 3 of "
            "layer 0 is inverted");
  EXPECT_TRUE(written("out.vtu"));
  ASSERT_FALSE(r.mesh.stages.empty());
  EXPECT_EQ(r.mesh.stages.front().stage, "failed attempts");
}

// Swept the other way, it is halved again as before.
TEST_F(FinerRetries, TheOtherWayIsTriedAtSmallerSizesToo) {
  use_downwards_scheme(100);
  const RunResult r =
      run_job(journal(R"(  <geometry><brick name="b" origin="0 0 0" size="4 4 4"/></geometry>
  <mesh size="1"><volume id="1" scheme="meshes_only_downwards"/></mesh>
)"),
              registry_, selector::mesh_options());
  EXPECT_FALSE(r.failed());
  EXPECT_EQ(r.mesh.mesh.hex_count(), 512u);
  EXPECT_NEAR(hex_volume(r.mesh.mesh), 64.0, 1e-9);
  ASSERT_FALSE(r.mesh.warnings.empty());
  EXPECT_EQ(r.mesh.warnings.front().text(),
            "volume 1: meshed sweeping it the other way, along (0, 0, -1), at size 0.5, half the "
            "size asked for (1); along (0, 0, 1) it failed at the size asked for and at smaller "
            "ones: hex 3 of layer 0 is inverted");
}

// A direction the journal gives is binding: no turning, and the error says
// what was tried.
TEST_F(FinerRetries, AHintedSweepIsNotTurned) {
  use_downwards_scheme();
  try {
    run_job(journal(R"(  <geometry><brick name="b" origin="0 0 0" size="4 4 4"/></geometry>
  <mesh size="1"><volume id="1" scheme="meshes_only_downwards" direction="0 0 1"/></mesh>
  <export file="out.vtu"/>
)"),
            registry_, selector::mesh_options());
    ADD_FAILURE() << "no error";
  } catch (const MeshingError& e) {
    EXPECT_EQ(e.hint().rfind("meshing it again at a quarter the size (0.25) failed too; ", 0), 0u)
        << e.hint();
    EXPECT_EQ(e.hint().find("other way"), std::string::npos) << e.hint();
  }
  EXPECT_FALSE(written("out.vtu"));
}

TEST(FinerRetryAttribute, IsCheckedInTheJournal) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("cooperage-finer-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto file = dir / "job.xml";
  for (const char* value : {"5", "-1", "two"}) {
    std::ofstream(file) << "<cooperage version=\"1\">\n  <geometry><brick name=\"b\" origin=\"0 0 "
                           "0\" size=\"1 1 1\"/></geometry>\n  <mesh size=\"1\" finer_retries=\""
                        << value << "\"/>\n</cooperage>\n";
    try {
      io::read_journal(file.string());
      ADD_FAILURE() << value;
    } catch (const MeshingError& e) {
      EXPECT_NE(std::string(e.what()).find("job.xml:3"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("finer_retries"), std::string::npos) << e.what();
    }
  }
  std::filesystem::remove_all(dir);
}

// ---- the settings and the texts, without a run ------------------------------

Verdict refused(int volume, bool finer_may_help) {
  Verdict v{EntityRef::volume(volume),
            Verdict::State::Refused,
            ErrorCode::MeshingFailed,
            "quad 3 is folded",
            "a hint",
            finer_may_help};
  return v;
}

TEST(HalveFailedVolumes, HalvesOnlyWhatASmallerSizeMayMesh) {
  io::MeshSettings s;
  s.size = 2;
  io::VolumeSetting own;
  own.id = 3;
  own.sizing.size = 0.5;
  s.volumes.push_back(own);
  std::map<int, FinerRetry> retries;
  Verdict meshed{EntityRef::volume(4), Verdict::State::Meshed, ErrorCode::NotApplicable, "", ""};
  const std::vector<int> halved = halve_failed_volumes(
      {refused(1, true), refused(2, false), refused(3, true), meshed}, s, retries);
  EXPECT_EQ(halved, (std::vector<int>{1, 3}));
  EXPECT_EQ(*s.size, 2.0) << "the global size stays";
  ASSERT_EQ(s.volumes.size(), 2u);
  EXPECT_EQ(s.volumes[0].id, 3);
  EXPECT_EQ(*s.volumes[0].sizing.size, 0.25);
  EXPECT_EQ(s.volumes[1].id, 1);
  EXPECT_EQ(*s.volumes[1].sizing.size, 1.0);
  EXPECT_EQ(retries.at(1).asked, 2.0);
  EXPECT_EQ(retries.at(3).asked, 0.5);
  EXPECT_EQ(retries.at(3).first_reason, "quad 3 is folded");
  // Again: a quarter of the size asked for; the first reason stays.
  Verdict again = refused(3, true);
  again.reason = "hex 9 is inverted";
  EXPECT_EQ(halve_failed_volumes({again}, s, retries), (std::vector<int>{3}));
  EXPECT_EQ(retries.at(3).size, 0.125);
  EXPECT_EQ(retries.at(3).first_reason, "quad 3 is folded");
}

TEST(HalveFailedVolumes, AVolumeSizedByIntervalsAloneIsLeftAsItIs) {
  io::MeshSettings s;  // no size anywhere
  std::map<int, FinerRetry> retries;
  EXPECT_TRUE(halve_failed_volumes({refused(1, true)}, s, retries).empty());
  EXPECT_TRUE(s.volumes.empty());
}

TEST(ReportFinerRetries, WarnsForWhatMeshedAndExtendsTheHintOfWhatDidNot) {
  MeshResult r;
  r.verdicts = {{EntityRef::volume(1), Verdict::State::Meshed, ErrorCode::NotApplicable, "", ""},
                refused(2, true)};
  r.warnings = {{EntityRef::surface(5), "pave fell back"}};
  std::map<int, FinerRetry> retries;
  retries[1] = {3.0, 0.75, "quad 3 is folded", std::nullopt, false};
  retries[2] = {1.0, 0.5, "hex 9 is inverted", std::nullopt, false};
  report_finer_retries(retries, r);
  ASSERT_EQ(r.warnings.size(), 2u);
  EXPECT_EQ(r.warnings[0].text(),
            "volume 1: meshed at size 0.75, a quarter the size asked for (3), at which it "
            "failed: quad 3 is folded");
  EXPECT_EQ(r.warnings[1].message, "pave fell back");
  EXPECT_EQ(r.verdicts[1].hint, "meshing it again at half the size (0.5) failed too; a hint");
}

// A scheme that gave no hint (submap's lattice that does not fit its face)
// leaves what was tried, with no "; " dangling after it.
TEST(ReportFinerRetries, WhatWasTriedStandsAloneWithoutAHint) {
  MeshResult r;
  r.verdicts = {refused(1, true), refused(2, true)};
  r.verdicts[0].hint.clear();
  r.verdicts[1].hint.clear();
  std::map<int, FinerRetry> retries;
  retries[1] = {1.0, 0.25, "quad 3 is folded", std::nullopt, false};
  retries[2] = {1.0, 1.0, "quad 3 is folded", geom::Vec3(0, 0, -1), true};
  report_finer_retries(retries, r);
  EXPECT_EQ(r.verdicts[0].hint, "meshing it again at a quarter the size (0.25) failed too");
  EXPECT_EQ(r.verdicts[1].hint,
            "meshing it again at smaller sizes, and sweeping it the other way, along (0, 0, 1), "
            "failed too");
}

// A volume that meshes worse than a failing quality check allows is meshed
// again at half its size (the run would otherwise write nothing), and says
// so; a warning check, no retries, or a retry that is no better leave the
// first mesh.
constexpr const char* kPoorCube =
    R"(  <geometry><brick name="b" origin="0 0 0" size="4 4 4"/></geometry>
  <mesh size="1"%s><volume id="1" scheme="poor_when_coarse"/></mesh>
  <quality metric="scaled_jacobian" min="0.5" action="%s"/>
  <export file="out.vtu"/>
)";

std::string poor_cube(const char* mesh_attributes, const char* action) {
  char text[1024];
  std::snprintf(text, sizeof text, kPoorCube, mesh_attributes, action);
  return text;
}

TEST_F(FinerRetries, AVolumeBelowAFailingQualityCheckIsMeshedAtHalfItsSize) {
  use_poor_scheme(100);
  const RunResult r = run_job(journal(poor_cube("", "fail")), registry_, selector::mesh_options());
  EXPECT_FALSE(r.failed());
  EXPECT_EQ(r.mesh.mesh.hex_count(), 512u);
  EXPECT_NEAR(hex_volume(r.mesh.mesh), 64.0, 1e-9);
  EXPECT_NEAR(r.quality.blocks.at(0).find("scaled_jacobian")->min, 1.0, 1e-12);
  ASSERT_FALSE(r.mesh.warnings.empty());
  EXPECT_EQ(r.mesh.warnings.front().text(),
            "volume 1: meshed at size 0.5, half the size asked for (1), where its worst element's "
            "scaled Jacobian was 0.182342, below the minimum 0.5 of a failing <quality> check");
  EXPECT_TRUE(written("out.vtu"));
}

TEST_F(FinerRetries, AWarningCheckOrNoRetriesKeepThePoorMesh) {
  use_poor_scheme(100);
  const RunResult warned =
      run_job(journal(poor_cube("", "warn")), registry_, selector::mesh_options());
  EXPECT_FALSE(warned.failed());
  EXPECT_EQ(warned.mesh.mesh.hex_count(), 64u);
  EXPECT_NEAR(warned.quality.blocks.at(0).find("scaled_jacobian")->min, 0.182342, 1e-6);
  // Only the note on the worst element (below 0.2), no retry.
  ASSERT_EQ(warned.mesh.warnings.size(), 1u);
  EXPECT_EQ(
      warned.mesh.warnings.front().message.rfind("its worst hex has a scaled Jacobian of 0.182", 0),
      0u)
      << warned.mesh.warnings.front().text();
  std::filesystem::remove(dir_ / "out.vtu");
  const RunResult none = run_job(journal(poor_cube(" finer_retries=\"0\"", "fail")), registry_,
                                 selector::mesh_options());
  EXPECT_TRUE(none.failed());
  EXPECT_EQ(none.mesh.mesh.hex_count(), 64u);
  EXPECT_FALSE(written("out.vtu"));
}

// At 0.5 the move inverts a hex (0.3 is more than the half-size hex's
// diagonal allows) and the volume is refused; a quarter of the size is
// tried from there and meshes as the map does.
TEST_F(FinerRetries, ARefusedRetryIsHalvedAgain) {
  use_poor_scheme(1000);
  const RunResult r = run_job(journal(poor_cube("", "fail")), registry_, selector::mesh_options());
  EXPECT_FALSE(r.failed());
  EXPECT_EQ(r.mesh.mesh.hex_count(), 4096u);
  EXPECT_NEAR(hex_volume(r.mesh.mesh), 64.0, 1e-9);
  ASSERT_FALSE(r.mesh.warnings.empty());
  EXPECT_EQ(r.mesh.warnings.front().text().rfind(
                "volume 1: meshed at size 0.25, a quarter the size asked for (1), where", 0),
            0u)
      << r.mesh.warnings.front().text();
  EXPECT_TRUE(written("out.vtu"));
}

TEST_F(FinerRetries, ARetryNoBetterKeepsTheFirstMeshAndTheCheckFails) {
  use_poor_scheme(1000000);  // at 0.5 the same move inverts a hex: the retry is worse
  const RunResult r = run_job(journal(poor_cube("", "fail")), registry_, selector::mesh_options());
  EXPECT_TRUE(r.failed());
  EXPECT_EQ(r.mesh.mesh.hex_count(), 64u);
  // No retry was kept: the only warning is the note on the worst element.
  ASSERT_EQ(r.mesh.warnings.size(), 1u);
  EXPECT_EQ(r.mesh.warnings.front().message.rfind("its worst hex has a scaled Jacobian of", 0), 0u);
  EXPECT_FALSE(written("out.vtu"));
}

// A straight sweep that meshes below kTurnPoorSweepsBelow at the size asked
// for is swept the other way there too; the better mesh is kept and the
// warning says so.
TEST_F(FinerRetries, APoorStraightSweepIsSweptTheOtherWayWhenThatIsBetter) {
  use_poor_upwards_scheme();
  const char* body = R"(  <geometry><brick name="b" origin="0 0 0" size="4 4 4"/></geometry>
  <mesh size="1"%s><volume id="1" scheme="poor_upwards"%s/></mesh>
  <export file="out.vtu"/>
)";
  char text[512];
  std::snprintf(text, sizeof text, body, "", "");
  const RunResult r = run_job(journal(text), registry_, selector::mesh_options());
  EXPECT_FALSE(r.failed());
  EXPECT_EQ(r.mesh.mesh.hex_count(), 64u);  // the size asked for
  EXPECT_NEAR(r.quality.blocks.at(0).find("scaled_jacobian")->min, 1.0, 1e-12);
  ASSERT_EQ(r.mesh.warnings.size(), 1u);
  EXPECT_EQ(r.mesh.warnings.front().text(),
            "volume 1: meshed sweeping it the other way, along (0, 0, -1), at the size asked for "
            "(1): its worst element's scaled Jacobian is 1.000, where along (0, 0, 1) it was "
            "0.182");
  EXPECT_TRUE(written("out.vtu"));
  ASSERT_FALSE(r.mesh.stages.empty());
  EXPECT_EQ(r.mesh.stages.front().stage, "failed attempts");

  // Not with a direction the journal gives, nor without retries.
  for (auto [mesh_attribute, volume_attribute] :
       {std::pair{"", " direction=\"0 0 1\""}, std::pair{" finer_retries=\"0\"", ""}}) {
    std::snprintf(text, sizeof text, body, mesh_attribute, volume_attribute);
    const RunResult kept = run_job(journal(text), registry_, selector::mesh_options());
    EXPECT_FALSE(kept.failed());
    EXPECT_NEAR(kept.quality.blocks.at(0).find("scaled_jacobian")->min, 0.182342, 1e-6);
    ASSERT_EQ(kept.mesh.warnings.size(), 1u);
    EXPECT_EQ(kept.mesh.warnings.front().message.rfind("its worst hex has a scaled Jacobian", 0),
              0u)
        << kept.mesh.warnings.front().text();
  }
}

// The other way no better: the mesh as planned stays, with its note.
TEST_F(FinerRetries, APoorSweepNoBetterTheOtherWayIsKeptAsPlanned) {
  use_poor_upwards_scheme(true);
  const RunResult r =
      run_job(journal(R"(  <geometry><brick name="b" origin="0 0 0" size="4 4 4"/></geometry>
  <mesh size="1"><volume id="1" scheme="poor_upwards"/></mesh>
  <export file="out.vtu"/>
)"),
              registry_, selector::mesh_options());
  EXPECT_FALSE(r.failed());
  EXPECT_EQ(r.mesh.mesh.hex_count(), 64u);
  EXPECT_NEAR(r.quality.blocks.at(0).find("scaled_jacobian")->min, 0.182342, 1e-6);
  ASSERT_EQ(r.mesh.warnings.size(), 1u);
  EXPECT_EQ(r.mesh.warnings.front().message.rfind("its worst hex has a scaled Jacobian", 0), 0u)
      << r.mesh.warnings.front().text();
  EXPECT_TRUE(written("out.vtu"));
}

}  // namespace
}  // namespace cooperage::pipeline
