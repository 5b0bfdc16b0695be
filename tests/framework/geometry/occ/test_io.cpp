// Import and export: STEP/BREP round trips, stable ids, kept units, silence,
// and bad files that must fail with a clear error instead of crashing.
#include "occ_test_util.h"

#include <fstream>
#include <sstream>
#include <thread>

namespace cooperage::occ::test {
namespace {

void write_text(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

std::string write_brick_step(const TempDir& dir, const std::string& name = "brick.step") {
  Workbench wb;
  wb.brick("b", Vec3(0, 0, 0), Vec3(2, 3, 4));
  const std::string path = dir.file(name);
  wb.write(path);
  return path;
}

TEST(OccIo, StepRoundTripKeepsUnitAndVolume) {
  TempDir dir;
  const std::string path = write_brick_step(dir);
  const Model m = load_model(path);
  ASSERT_EQ(m.volumes().size(), 1u);
  EXPECT_NEAR(m.volume(1).volume, 24.0, 1e-9);
  EXPECT_DOUBLE_EQ(m.unit_in_metres(), 1e-3);
  EXPECT_EQ(m.volume(1).name, "brick");
  EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
}

TEST(OccIo, StepInMetresIsNotConvertedToMillimetres) {
  TempDir dir;
  std::string text = read_text(write_brick_step(dir));
  const std::string mm = "SI_UNIT(.MILLI.,.METRE.)";
  const auto at = text.find(mm);
  ASSERT_NE(at, std::string::npos) << "the writer's length unit entity changed";
  text.replace(at, mm.size(), "SI_UNIT($,.METRE.)");
  const std::string path = dir.file("metres.step");
  write_text(path, text);
  const Model m = load_model(path);
  EXPECT_NEAR(m.volume(1).volume, 24.0, 1e-9);  // not 24e9, not 24e-9
  EXPECT_DOUBLE_EQ(m.unit_in_metres(), 1.0);
}

TEST(OccIo, IdsAreStableOverTwoLoads) {
  TempDir dir;
  Workbench wb;
  wb.brick("plate", Vec3(0, 0, 0), Vec3(10, 4, 1));
  for (int i = 0; i < 3; ++i)
    wb.cylinder("hole" + std::to_string(i), Vec3(2 + 3 * i, 2, -1), Vec3(0, 0, 1), 0.5, 3);
  wb.cut("part", {"plate", "hole0", "hole1", "hole2"});
  wb.brick("lid", Vec3(0, 0, 1), Vec3(3, 4, 1));
  const std::string path = dir.file("parts.stp");
  wb.write(path);
  const Model a = load_model(path);
  const Model b = load_model(path);
  ASSERT_EQ(a.volumes().size(), 2u);
  ASSERT_EQ(a.vertices().size(), b.vertices().size());
  ASSERT_EQ(a.curves().size(), b.curves().size());
  ASSERT_EQ(a.surfaces().size(), b.surfaces().size());
  EXPECT_EQ(count_shared_surfaces(a), 1);
  for (size_t i = 0; i < a.vertices().size(); ++i)
    EXPECT_EQ(a.vertices()[i].point, b.vertices()[i].point) << "vertex " << i + 1;
  for (size_t i = 0; i < a.curves().size(); ++i) {
    EXPECT_EQ(a.curves()[i].length, b.curves()[i].length) << "curve " << i + 1;
    EXPECT_EQ(a.curves()[i].start_vertex, b.curves()[i].start_vertex);
  }
  for (size_t i = 0; i < a.surfaces().size(); ++i) {
    EXPECT_EQ(a.surfaces()[i].area, b.surfaces()[i].area) << "surface " << i + 1;
    EXPECT_EQ(a.surfaces()[i].volumes, b.surfaces()[i].volumes);
  }
  EXPECT_EQ(geom::euler_characteristic(a), 2 * 2 - 2 * 3);
}

// The import child measures every face (area, centroid, tight box) and solid
// (volume) and the parent takes its numbers instead of measuring again; a
// thread of its own starts with nothing remembered and measures from
// scratch. Faces of different sizes and two solids: a mix-up of the order
// would give a face another's numbers.
TEST(OccIo, MeasuresSentByTheImportChildAreThoseMeasuredAgain) {
  TempDir dir;
  Workbench made;
  made.brick("plate", Vec3(0, 0, 0), Vec3(10, 4, 1));
  for (int i = 0; i < 3; ++i)
    made.cylinder("hole" + std::to_string(i), Vec3(2 + 3 * i, 2, -1), Vec3(0, 0, 1), 0.3 + 0.2 * i,
                  3);
  made.cut("part", {"plate", "hole0", "hole1", "hole2"});
  made.sphere("dome", Vec3(1, 1, 1), 0.8);
  made.fuse("body", {"part", "dome"});
  made.brick("lid", Vec3(5, 0, 1), Vec3(3, 4, 1.5));
  const std::string path = dir.file("parts.stp");
  made.write(path);

  Workbench wb;
  wb.import_file("p", path);
  const Model sent = wb.build_model();
  Model measured;
  std::thread([&] { measured = wb.build_model(); }).join();
  ASSERT_EQ(sent.volumes().size(), 2u);
  ASSERT_EQ(sent.surfaces().size(), measured.surfaces().size());
  for (size_t i = 0; i < sent.surfaces().size(); ++i) {
    const geom::Surface& a = sent.surfaces()[i];
    const geom::Surface& b = measured.surfaces()[i];
    EXPECT_EQ(a.area, b.area) << "surface " << i + 1;
    EXPECT_EQ(a.centroid, b.centroid) << "surface " << i + 1;
    EXPECT_EQ(a.box.min, b.box.min) << "surface " << i + 1;
    EXPECT_EQ(a.box.max, b.box.max) << "surface " << i + 1;
  }
  for (size_t i = 0; i < sent.volumes().size(); ++i)
    EXPECT_EQ(sent.volumes()[i].volume, measured.volumes()[i].volume) << "volume " << i + 1;
  EXPECT_NE(sent.volumes()[0].volume, sent.volumes()[1].volume);
}

TEST(OccIo, BrepRoundTrip) {
  TempDir dir;
  Workbench wb;
  wb.cylinder("c", Vec3(0, 0, 0), Vec3(1, 1, 0), 1.0, 3.0);
  const Model before = wb.build_model();
  const std::string path = dir.file("c.brep");
  wb.write(path);
  Workbench again;
  again.import_file("c", path, /*heal=*/false);
  const Model after = again.build_model();
  EXPECT_EQ(after.surfaces().size(), before.surfaces().size());
  EXPECT_TRUE(near_rel(after.volume(1).volume, before.volume(1).volume, 1e-12));
}

// Files written from assemblies nest placements, each of a shape's chain
// composed on every query; the import moves them into the geometry. A brick
// placed through a chain of twelve (rotations about z and moves along it,
// which commute, so the order of the chain cannot matter) must come out
// where the whole chain puts it.
TEST(OccIo, NestedPlacementsOfABrepPlaceItsGeometry) {
  TempDir dir;
  Workbench wb;
  wb.brick("b", Vec3(1, 2, 0), Vec3(2, 3, 4));
  const Model made = wb.build_model();
  const std::string plain = dir.file("plain.brep");
  wb.write(plain);
  std::string text = read_text(plain);
  const std::string none = "Locations 0";
  const auto at = text.find(none);
  ASSERT_NE(at, std::string::npos) << "the writer's location table changed";
  std::ostringstream table;
  table.precision(17);
  table << "Locations 13\n";
  double turn = 0.0, rise = 0.0;
  for (int k = 0; k < 12; ++k) {
    const double a = k % 2 ? 0.1 * (k + 1) : 0.0;
    const double dz = k % 2 ? 0.0 : 0.5 * (k + 1);
    turn += a;
    rise += dz;
    table << "1\n"
          << std::cos(a) << " " << -std::sin(a) << " 0 0\n"
          << std::sin(a) << " " << std::cos(a) << " 0 0\n"
          << "0 0 1 " << dz << "\n";
  }
  table << "2 ";
  for (int k = 1; k <= 12; ++k) table << " " << k << " 1";
  table << " 0";
  text.replace(at, none.size(), table.str());
  // The root's reference, the file's last line: the brick under the chain.
  const auto root = text.rfind("+1 0");
  ASSERT_NE(root, std::string::npos);
  text.replace(root, 4, "+1 13");
  const std::string placed = dir.file("placed.brep");
  write_text(placed, text);

  Workbench again;
  again.import_file("b", placed, /*heal=*/false);
  const Model m = again.build_model();
  ASSERT_EQ(m.vertices().size(), made.vertices().size());
  EXPECT_TRUE(near_rel(m.volume(1).volume, 24.0, 1e-12));
  const Eigen::Matrix3d turned = Eigen::AngleAxisd(turn, Vec3::UnitZ()).toRotationMatrix();
  for (const geom::Vertex& v : made.vertices()) {
    const Vec3 want = turned * v.point + Vec3(0, 0, rise);
    double nearest = 1e300;
    for (const geom::Vertex& w : m.vertices()) nearest = std::min(nearest, (w.point - want).norm());
    EXPECT_LT(nearest, 1e-9) << "vertex " << v.id << " of the brick is not where the chain puts it";
  }
}

TEST(OccIo, IgesRoundTrip) {
  TempDir dir;
  Workbench wb;
  wb.brick("b", Vec3(0, 0, 0), Vec3(2, 3, 4));
  wb.cylinder("c", Vec3(5, 0, 0), Vec3(0, 0, 1), 1.0, 2.0);
  const std::string path = dir.file("parts.igs");
  wb.write(path);
  testing::internal::CaptureStdout();
  const Model m = load_model(path);
  EXPECT_EQ(testing::internal::GetCapturedStdout(), "");
  ASSERT_EQ(m.volumes().size(), 2u);
  EXPECT_NEAR(m.volume(1).volume, 24.0, 1e-7);
  EXPECT_TRUE(near_rel(m.volume(2).volume, 3.14159265358979323846 * 2.0, 1e-6));
  EXPECT_DOUBLE_EQ(m.unit_in_metres(), 1e-3);
  EXPECT_EQ(m.volume(1).name, "parts.1");
  EXPECT_EQ(geom::euler_characteristic(m), 4);
}

TEST(OccIo, StepImportPrintsNothing) {
  TempDir dir;
  const std::string path = write_brick_step(dir);
  testing::internal::CaptureStdout();
  Workbench wb;
  wb.import_file("b", path);
  const Model m = wb.build_model();
  const std::string out = testing::internal::GetCapturedStdout();
  EXPECT_EQ(out, "");
  EXPECT_EQ(m.volumes().size(), 1u);
}

TEST(OccIo, MissingFile) {
  const std::string path = "/nonexistent/dir/part.step";
  const std::string msg = expect_error(ErrorCode::FileNotFound, [&] { load_model(path); });
  EXPECT_NE(msg.find(path), std::string::npos) << msg;
}

TEST(OccIo, TruncatedStep) {
  TempDir dir;
  const std::string text = read_text(write_brick_step(dir));
  const std::string path = dir.file("half.step");
  write_text(path, text.substr(0, text.size() / 2));
  testing::internal::CaptureStdout();
  const std::string msg = expect_error(ErrorCode::ParseError, [&] { load_model(path); });
  EXPECT_EQ(testing::internal::GetCapturedStdout(), "");
  EXPECT_NE(msg.find(path), std::string::npos) << msg;
  EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
}

TEST(OccIo, GarbageAndEmptyFiles) {
  TempDir dir;
  const std::string garbage = dir.file("garbage.step");
  write_text(garbage, "this is not ISO-10303-21\n\x01\x02\x03 ;;; ENDSEC;\n");
  testing::internal::CaptureStdout();
  std::string msg = expect_error(ErrorCode::ParseError, [&] { load_model(garbage); });
  EXPECT_EQ(testing::internal::GetCapturedStdout(), "");
  EXPECT_NE(msg.find(garbage), std::string::npos) << msg;
  const std::string empty = dir.file("empty.stp");
  write_text(empty, "");
  expect_error(ErrorCode::ParseError, [&] { load_model(empty); });
  const std::string iges = dir.file("garbage.igs");
  write_text(iges, "garbage\n");
  expect_error(ErrorCode::ParseError, [&] { load_model(iges); });
  const std::string brep = dir.file("garbage.brep");
  write_text(brep, "garbage\n");
  testing::internal::CaptureStdout();
  expect_error(ErrorCode::ParseError, [&] { load_model(brep); });
  EXPECT_EQ(testing::internal::GetCapturedStdout(), "");
}

TEST(OccIo, UnknownExtension) {
  TempDir dir;
  const std::string path = dir.file("part.xyz");
  write_text(path, "solid\n");
  const std::string msg = expect_error(ErrorCode::InvalidInput, [&] { load_model(path); });
  EXPECT_NE(msg.find(".xyz"), std::string::npos) << msg;
  Workbench wb;
  wb.brick("b", Vec3(0, 0, 0), Vec3(1, 1, 1));
  expect_error(ErrorCode::InvalidInput, [&] { wb.write(dir.file("out.obj")); });
  EXPECT_FALSE(std::filesystem::exists(dir.file("out.obj")));
  expect_error(ErrorCode::InvalidInput, [&] { wb.write(dir.file("out.step"), {"ghost"}); });
}

}  // namespace
}  // namespace cooperage::occ::test
