// Workbench::loft: solids through planar sections (twisted prism, frustum,
// pyramid, tetrahedron), checked against closed-form volumes and topology
// counts, and the validation of bad sections.
#include "occ_test_util.h"

#include "framework/io/journal_reader.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

namespace cooperage::occ::test {
namespace {

constexpr double kPi = 3.14159265358979323846;

/// Square of side `side` centred on the z axis at height z, turned by deg
/// degrees about z (counter-clockwise seen from +z).
std::vector<Vec3> square(double side, double z, double deg = 0) {
  const double a = deg * kPi / 180, h = 0.5 * side;
  std::vector<Vec3> pts;
  for (const auto& [x, y] : {std::pair{-h, -h}, {h, -h}, {h, h}, {-h, h}})
    pts.emplace_back(x * std::cos(a) - y * std::sin(a), x * std::sin(a) + y * std::cos(a), z);
  return pts;
}

void expect_counts(const Model& m, size_t v, size_t c, size_t s) {
  EXPECT_EQ(m.vertices().size(), v);
  EXPECT_EQ(m.curves().size(), c);
  EXPECT_EQ(m.surfaces().size(), s);
  ASSERT_EQ(m.volumes().size(), 1u);
  EXPECT_EQ(geom::euler_characteristic(m), 2);
  for (const auto& surface : m.surfaces()) EXPECT_EQ(surface.volumes, std::vector<int>{1});
}

TEST(OccLoft, TwistedSquarePrism) {
  Workbench wb;
  std::vector<std::vector<Vec3>> sections;
  for (int k = 0; k < 4; ++k) sections.push_back(square(1.0, k, 15.0 * k));
  wb.loft("twist", sections);
  Model m;
  ASSERT_NO_THROW(m = wb.build_model());  // build_model runs Model::validate()
  expect_counts(m, 16, 28, 14);
  EXPECT_EQ(m.volume(1).name, "twist");
  // Close to base area x height, a little less: the ruled faces pull in.
  const double v = m.volume(1).volume;
  EXPECT_GT(v, 0.95 * 3.0);
  EXPECT_LT(v, 3.0);
  // Exactly: a section at fraction t between two squares turned by θ is the
  // square scaled by |1 - t + t e^{iθ}|, so each layer holds
  // 1 - (1 - cos θ) / 3 of the prism's volume.
  const double exact = 3.0 * (1.0 - (1.0 - std::cos(15.0 * kPi / 180)) / 3.0);
  EXPECT_TRUE(near_rel(v, exact, 1e-6)) << v << " vs " << exact;
  RecordProperty("twisted_prism_volume", std::to_string(v));
  std::cout << "[ loft     ] twisted prism volume " << std::setprecision(10) << v << " (exact "
            << exact << ")\n";
  EXPECT_NEAR(m.volume(1).box.min.z(), 0.0, 1e-7);
  EXPECT_NEAR(m.volume(1).box.max.z(), 3.0, 1e-7);
}

// The shipped example: its <loft> builds the same twisted block.
TEST(OccLoft, TwistedBlockExample) {
  const io::Job job =
      io::read_journal(std::string(COOPERAGE_SOURCE_DIR) + "/examples/twisted_block.xml");
  ASSERT_EQ(job.geometry.size(), 1u);
  const auto* op = std::get_if<io::LoftOp>(&job.geometry[0].op);
  ASSERT_NE(op, nullptr);
  Workbench wb;
  wb.loft(op->name, op->sections, op->ruled);
  const Model m = wb.build_model();
  expect_counts(m, 8, 12, 6);
  // One ruled layer of height 3 turned by 45 degrees: each cross-section is a
  // scaled square, V = h A (1 - (1 - cos t) / 3).
  const double exact = 3.0 * (1.0 - (1.0 - std::cos(45.0 * kPi / 180)) / 3.0);
  EXPECT_TRUE(near_rel(m.volume(1).volume, exact, 1e-5)) << m.volume(1).volume;  // 6 digits
}

TEST(OccLoft, FrustumOfASquarePyramid) {
  Workbench wb;
  wb.loft("frustum", {square(2.0, 0.0), square(1.0, 3.0)});
  const Model m = wb.build_model();
  expect_counts(m, 8, 12, 6);
  const double a1 = 4.0, a2 = 1.0, h = 3.0;
  EXPECT_TRUE(near_rel(m.volume(1).volume, h / 3 * (a1 + a2 + std::sqrt(a1 * a2)), 1e-9))
      << m.volume(1).volume;
}

TEST(OccLoft, Tetrahedron) {
  Workbench wb;
  const Vec3 a(0, 0, 0), b(2, 0, 0), c(0, 3, 0), d(0.5, 0.5, 4);
  wb.loft("tet", {{a, b, c}, {d}});
  const Model m = wb.build_model();
  expect_counts(m, 4, 6, 4);
  const double det = (b - a).dot((c - a).cross(d - a));
  EXPECT_TRUE(near_rel(m.volume(1).volume, std::abs(det) / 6, 1e-9)) << m.volume(1).volume;
  for (const auto& s : m.surfaces()) EXPECT_EQ(s.geometry->type(), geom::SurfaceType::Plane);
  for (const auto& v : m.vertices()) EXPECT_EQ(v.curves.size(), 3u);
}

TEST(OccLoft, SquarePyramidApexLastOrFirst) {
  for (const bool apex_first : {false, true}) {
    SCOPED_TRACE(apex_first ? "apex first" : "apex last");
    Workbench wb;
    std::vector<std::vector<Vec3>> sections = {square(2.0, 0.0), {Vec3(0, 0, 3)}};
    if (apex_first) std::swap(sections[0], sections[1]);
    wb.loft("pyramid", sections);
    const Model m = wb.build_model();
    expect_counts(m, 5, 8, 5);
    EXPECT_TRUE(near_rel(m.volume(1).volume, 4.0 * 3.0 / 3, 1e-9)) << m.volume(1).volume;
    // Outward normals: the base faces -z.
    int base = 0;
    for (const auto& s : m.surfaces())
      if (std::abs(s.area - 4.0) < 1e-9) base = s.id;
    ASSERT_NE(base, 0);
    EXPECT_LT(m.outward_normal(base, 1, uv_centre(m.surface(base))).z(), -0.99);
  }
}

TEST(OccLoft, ClockwiseSectionsGiveTheSameSolid) {
  Workbench wb;
  auto bottom = square(2.0, 0.0), top = square(1.0, 3.0);
  std::reverse(bottom.begin(), bottom.end());
  std::reverse(top.begin(), top.end());
  wb.loft("frustum", {bottom, top});
  const Model m = wb.build_model();
  EXPECT_TRUE(near_rel(m.volume(1).volume, 7.0, 1e-9)) << m.volume(1).volume;
}

TEST(OccLoft, SmoothLoftBetweenDifferentCounts) {
  Workbench wb;
  std::vector<Vec3> octagon;
  for (int k = 0; k < 8; ++k)
    octagon.emplace_back(0.6 * std::cos(kPi * (k + 0.5) / 4), 0.6 * std::sin(kPi * (k + 0.5) / 4),
                         2);
  wb.loft("blend", {square(1.0, 0.0), octagon}, /*ruled=*/false);
  Model m;
  ASSERT_NO_THROW(m = wb.build_model());
  ASSERT_EQ(m.volumes().size(), 1u);
  EXPECT_EQ(geom::euler_characteristic(m), 2);
  const double oct_area = 0.5 * 8 * 0.36 * std::sin(kPi / 4);
  EXPECT_GT(m.volume(1).volume, 2.0 * std::min(1.0, oct_area) * 0.9);
  EXPECT_LT(m.volume(1).volume, 2.0 * std::max(1.0, oct_area) * 1.1);
}

TEST(OccLoft, BadSections) {
  const auto fails = [](const std::vector<std::vector<Vec3>>& sections, const std::string& part,
                        bool ruled = true) {
    Workbench wb;
    const std::string msg =
        expect_error(ErrorCode::InvalidInput, [&] { wb.loft("L", sections, ruled); });
    EXPECT_NE(msg.find("shape 'L'"), std::string::npos) << msg;
    EXPECT_NE(msg.find(part), std::string::npos) << msg;
    EXPECT_FALSE(wb.has("L"));
  };
  fails({square(1, 0)}, "at least 2 sections");
  fails({}, "at least 2 sections");
  auto warped = square(1, 1);
  warped[2].z() += 0.1;
  fails({square(1, 0), warped}, "section 2 is not planar");
  fails({square(1, 0), {Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(0.5, 1, 1)}}, "same number of points");
  fails({square(1, 0), {Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(0.5, 1, 1)}}, "compatible wires");
  fails({square(1, 0), {Vec3(0, 0, 1)}, square(1, 2)}, "section 2 is a single point");
  fails({square(1, 0), {Vec3(0, 0, 1), Vec3(1, 0, 1)}}, "section 2 has 2 points");
  fails({{Vec3(0, 0, -1)}, {Vec3(0, 0, 1)}}, "at least one polygon section");
  auto dup = square(1, 1);
  dup.insert(dup.begin() + 1, dup[0]);
  fails({square(1, 0), dup}, "coincident consecutive points", false);
  fails({square(1, 0), {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0)}}, "degenerate");
  fails({square(1, 0), square(2, 0)}, "lie in one plane");
  fails({square(1, 0), {Vec3(5, 5, 0)}}, "lie in one plane");
  auto reversed = square(1, 1);
  std::reverse(reversed.begin(), reversed.end());
  fails({square(1, 0), reversed}, "winds the opposite way");
  fails({square(1, 0), {Vec3(0, 0, NAN)}}, "non-finite");

  Workbench wb;
  wb.brick("L", Vec3::Zero(), Vec3::Ones());
  expect_error(ErrorCode::InvalidInput, [&] { wb.loft("L", {square(1, 0), square(1, 1)}); });
}

}  // namespace
}  // namespace cooperage::occ::test
