// Journal reader: valid journals read into the expected Job values.
#include "framework/io/journal_reader.h"

#include "framework/core/error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <variant>

namespace cooperage::io {
namespace {

namespace fs = std::filesystem;

const std::string kExamples = std::string(COOPERAGE_SOURCE_DIR) + "/examples";
const std::string kData = std::string(COOPERAGE_SOURCE_DIR) + "/tests/framework/io/data";

template <class T>
const T& op(const Job& job, size_t i) {
  EXPECT_LT(i, job.geometry.size());
  const T* p = std::get_if<T>(&job.geometry.at(i).op);
  EXPECT_NE(p, nullptr) << "step " << i << " has another type";
  if (!p) throw std::runtime_error("wrong op type");
  return *p;
}

TEST(JournalReader, EveryExampleParses) {
  int count = 0;
  for (const auto& entry : fs::directory_iterator(kExamples)) {
    if (entry.path().extension() != ".xml") continue;
    SCOPED_TRACE(entry.path().string());
    Job job;
    ASSERT_NO_THROW(job = read_journal(entry.path().string()));
    EXPECT_FALSE(job.geometry.empty());
    EXPECT_EQ(job.file, entry.path().string());
    EXPECT_EQ(fs::path(job.base_dir), fs::absolute(kExamples).lexically_normal());
    for (const auto& step : job.geometry) {
      EXPECT_EQ(step.where.file, job.file);
      EXPECT_GT(step.where.line, 0);
      EXPECT_FALSE(step.where.element.empty());
    }
    ++count;
  }
  EXPECT_GE(count, 4);
}

TEST(JournalReader, BrickExample) {
  const Job job = read_journal(kExamples + "/brick.xml");
  ASSERT_EQ(job.geometry.size(), 1u);
  const auto& brick = op<BrickOp>(job, 0);
  EXPECT_EQ(brick.size, Vec3(2, 3, 4));
  ASSERT_TRUE(job.mesh && job.mesh->size);
  EXPECT_DOUBLE_EQ(*job.mesh->size, 0.5);
  EXPECT_TRUE(job.imprint_merge);
}

TEST(JournalReader, CylinderBossExample) {
  const Job job = read_journal(kExamples + "/cylinder_boss.xml");
  ASSERT_EQ(job.geometry.size(), 3u);
  EXPECT_DOUBLE_EQ(op<CylinderOp>(job, 0).radius, 2);
  EXPECT_DOUBLE_EQ(op<CylinderOp>(job, 0).height, 3);
  EXPECT_DOUBLE_EQ(op<CylinderOp>(job, 1).radius, 1);
  EXPECT_DOUBLE_EQ(op<CylinderOp>(job, 1).height, 1.5);
  EXPECT_EQ(op<CylinderOp>(job, 1).base, Vec3(0, 0, 3));
  const auto& fuse = op<BooleanOp>(job, 2);
  EXPECT_EQ(fuse.kind, BooleanKind::Fuse);
  EXPECT_EQ(fuse.inputs, (std::vector<std::string>{"body", "boss"}));
  EXPECT_DOUBLE_EQ(*job.mesh->size, 0.25);
  ASSERT_EQ(job.exports.size(), 2u);
  EXPECT_EQ(job.exports[0].file, "cylinder_boss.exo");
  EXPECT_EQ(job.exports[1].file, "cylinder_boss.vtu");
}

TEST(JournalReader, PlateThreeHolesExample) {
  const Job job = read_journal(kExamples + "/plate_three_holes.xml");
  EXPECT_EQ(op<BrickOp>(job, 0).size, Vec3(10, 6, 1));
  const auto& cut = op<BooleanOp>(job, job.geometry.size() - 1);
  EXPECT_EQ(cut.kind, BooleanKind::Cut);
  EXPECT_EQ(cut.inputs.size(), 4u);
  EXPECT_EQ(cut.inputs[0], "plate");
}

TEST(JournalReader, TwoBricksExample) {
  const Job job = read_journal(kExamples + "/two_bricks.xml");
  ASSERT_EQ(job.geometry.size(), 2u);
  EXPECT_TRUE(job.imprint_merge);
  // touching on x = 1
  EXPECT_DOUBLE_EQ(op<BrickOp>(job, 0).origin.x() + op<BrickOp>(job, 0).size.x(),
                   op<BrickOp>(job, 1).origin.x());
}

TEST(JournalReader, CompleteJournalRoundTrips) {
  const std::string path = kData + "/complete.xml";
  const Job job = read_journal(path);
  EXPECT_EQ(job.file, path);
  EXPECT_FALSE(job.imprint_merge);
  ASSERT_EQ(job.geometry.size(), 15u);

  const auto& imp = op<ImportOp>(job, 0);
  EXPECT_EQ(imp.name, "bracket");
  EXPECT_EQ(imp.file, "parts/bracket.STEP");  // as written; resolved by the executor
  EXPECT_FALSE(imp.heal);
  EXPECT_EQ(job.geometry[0].where.element, "import");
  EXPECT_EQ(job.geometry[0].where.line, 8);
  EXPECT_EQ(job.geometry[0].where.file, path);

  const auto& box = op<BrickOp>(job, 1);
  EXPECT_EQ(box.name, "box");
  EXPECT_EQ(box.origin, Vec3(-1, -2, -3));
  EXPECT_EQ(box.size, Vec3(2, 4, 6));

  const auto& pin = op<CylinderOp>(job, 2);
  EXPECT_EQ(pin.base, Vec3(0, 0, -3));
  EXPECT_EQ(pin.axis, Vec3(0, 0, 2));  // as written, not normalised
  EXPECT_DOUBLE_EQ(pin.radius, 0.5);
  EXPECT_DOUBLE_EQ(pin.height, 6);

  const auto& tip = op<ConeOp>(job, 3);
  EXPECT_EQ(tip.base, Vec3(1, 1, 1));
  EXPECT_EQ(tip.axis, Vec3(1, 0, 0));
  EXPECT_DOUBLE_EQ(tip.radius1, 2);
  EXPECT_DOUBLE_EQ(tip.radius2, 0.5);
  EXPECT_DOUBLE_EQ(tip.height, 3);

  const auto& ball = op<SphereOp>(job, 4);
  EXPECT_EQ(ball.center, Vec3(5, 0, 0));
  EXPECT_DOUBLE_EQ(ball.radius, 1.5);

  const auto& slab = op<PrismOp>(job, 5);
  EXPECT_EQ(slab.direction, Vec3(0, 0, 0.25));
  ASSERT_EQ(slab.profile.size(), 4u);
  EXPECT_EQ(slab.profile[2], Vec3(4, 3, 0));
  ASSERT_EQ(slab.holes.size(), 2u);
  EXPECT_EQ(slab.holes[0].size(), 3u);
  EXPECT_EQ(slab.holes[1][1], Vec3(3.5, 1, 0));

  const auto& ring = op<RevolveOp>(job, 6);
  EXPECT_EQ(ring.axis, Vec3(0, 0, 1));
  EXPECT_DOUBLE_EQ(ring.angle, 90);
  EXPECT_EQ(ring.profile.size(), 4u);

  const auto& holed = op<BooleanOp>(job, 7);
  EXPECT_EQ(holed.kind, BooleanKind::Cut);
  EXPECT_EQ(holed.name, "holed");
  EXPECT_EQ(holed.inputs, (std::vector<std::string>{"box", "pin"}));
  EXPECT_EQ(op<BooleanOp>(job, 8).kind, BooleanKind::Fuse);
  EXPECT_EQ(op<BooleanOp>(job, 8).inputs.size(), 3u);
  EXPECT_EQ(op<BooleanOp>(job, 9).kind, BooleanKind::Common);

  EXPECT_EQ(op<TranslateOp>(job, 10).shape, "joined");
  EXPECT_EQ(op<TranslateOp>(job, 10).by, Vec3(10, 0, 0));
  const auto& rot = op<RotateOp>(job, 11);
  EXPECT_EQ(rot.origin, Vec3(1, 2, 3));
  EXPECT_EQ(rot.axis, Vec3(0, 1, 0));
  EXPECT_DOUBLE_EQ(rot.angle, -45);
  EXPECT_DOUBLE_EQ(op<ScaleOp>(job, 12).factor, 0.001);
  const auto& cut = op<WebcutOp>(job, 13);
  EXPECT_EQ(cut.origin, Vec3(10, 0, 0));
  EXPECT_EQ(cut.normal, Vec3(1, 0, 0));
  EXPECT_EQ(job.geometry[13].where.element, "webcut");
  const auto& spire = op<LoftOp>(job, 14);
  EXPECT_EQ(spire.name, "spire");
  EXPECT_FALSE(spire.ruled);
  ASSERT_EQ(spire.sections.size(), 3u);
  EXPECT_EQ(spire.sections[0].size(), 4u);
  EXPECT_EQ(spire.sections[1].size(), 3u);  // smooth lofts may change the count
  EXPECT_EQ(spire.sections[1][1], Vec3(20.75, 0.25, 1));
  EXPECT_EQ(spire.sections[2], (Polygon{Vec3(20.5, 0.5, 2)}));  // the apex
  EXPECT_EQ(job.geometry[14].where.element, "loft");

  ASSERT_TRUE(job.mesh.has_value());
  const MeshSettings& m = *job.mesh;
  EXPECT_DOUBLE_EQ(*m.size, 0.5);
  EXPECT_EQ(m.threads, 4);
  EXPECT_EQ(m.where.element, "mesh");
  ASSERT_EQ(m.curves.size(), 3u);
  EXPECT_EQ(m.curves[0].id, 1);
  EXPECT_EQ(m.curves[0].sizing.intervals, 8);
  EXPECT_FALSE(m.curves[0].sizing.size);
  EXPECT_EQ(m.curves[0].sizing.firmness, Firmness::Hard);
  EXPECT_EQ(m.curves[0].bias, BiasKind::None);
  EXPECT_DOUBLE_EQ(*m.curves[1].sizing.size, 0.1);
  EXPECT_EQ(m.curves[1].sizing.firmness, Firmness::Default);
  EXPECT_EQ(m.curves[1].bias, BiasKind::Geometric);
  EXPECT_DOUBLE_EQ(*m.curves[1].bias_ratio, 1.2);
  EXPECT_TRUE(m.curves[1].reverse_bias);
  EXPECT_EQ(m.curves[2].bias, BiasKind::Dual);
  EXPECT_DOUBLE_EQ(*m.curves[2].bias_first_size, 0.01);
  EXPECT_FALSE(m.curves[2].bias_ratio);
  EXPECT_FALSE(m.curves[2].reverse_bias);
  EXPECT_EQ(m.curves[2].where.element, "curve");
  EXPECT_GT(m.curves[2].where.line, m.curves[1].where.line);

  ASSERT_EQ(m.surfaces.size(), 2u);
  EXPECT_EQ(m.surfaces[0].id, 4);
  EXPECT_DOUBLE_EQ(*m.surfaces[0].sizing.size, 0.3);
  EXPECT_EQ(m.surfaces[0].scheme, "submap");
  EXPECT_EQ(m.surfaces[1].scheme, "pave");
  EXPECT_FALSE(m.surfaces[1].sizing.size);

  ASSERT_EQ(m.volumes.size(), 2u);
  const VolumeSetting& v = m.volumes[0];
  EXPECT_EQ(v.id, 1);
  EXPECT_DOUBLE_EQ(*v.sizing.size, 0.4);
  EXPECT_EQ(v.scheme, "cooper");
  EXPECT_EQ(v.elements, ElementKind::Mixed);
  EXPECT_EQ(v.sources, (std::vector<int>{3, 4}));
  EXPECT_EQ(v.targets, (std::vector<int>{5}));
  ASSERT_TRUE(v.direction);
  EXPECT_EQ(*v.direction, Vec3(0, 0, -1));
  EXPECT_EQ(m.volumes[1].scheme, "map");
  EXPECT_FALSE(m.volumes[1].elements);  // the mesh's kind
  EXPECT_FALSE(m.volumes[1].direction);

  ASSERT_EQ(m.vertex_types.size(), 2u);
  EXPECT_EQ(m.vertex_types[0].surface, 4);
  EXPECT_EQ(m.vertex_types[0].vertex, 7);
  EXPECT_EQ(m.vertex_types[0].type, VertexType::Corner);
  EXPECT_EQ(m.vertex_types[1].type, VertexType::Reversal);

  ASSERT_EQ(job.quality.size(), 3u);
  EXPECT_EQ(job.quality[0].metric, "scaled_jacobian");
  EXPECT_DOUBLE_EQ(*job.quality[0].min, 0.2);
  EXPECT_FALSE(job.quality[0].max);
  EXPECT_EQ(job.quality[0].action, QualityCheck::Action::Fail);
  EXPECT_EQ(job.quality[1].metric, "skew");
  EXPECT_DOUBLE_EQ(*job.quality[1].max, 0.8);
  EXPECT_EQ(job.quality[1].action, QualityCheck::Action::Warn);
  EXPECT_DOUBLE_EQ(*job.quality[2].min, 1);
  EXPECT_DOUBLE_EQ(*job.quality[2].max, 4);

  ASSERT_EQ(job.exports.size(), 4u);
  EXPECT_EQ(job.exports[0].file, "out/result.exo");
  EXPECT_EQ(job.exports[3].file, "/tmp/result.inp");
  EXPECT_EQ(job.exports[0].where.element, "export");
  ASSERT_EQ(job.reports.size(), 1u);
  EXPECT_EQ(job.reports[0].file, "out/result.html");
  EXPECT_EQ(job.reports[0].where.element, "report");
  EXPECT_FALSE(job.exports[0].binary);
  EXPECT_FALSE(job.exports[1].binary);           // default ascii
  EXPECT_TRUE(job.exports[2].binary);            // encoding="binary"
  EXPECT_EQ(job.exports[2].file, "result.VTU");  // extensions in any case
}

// <mesh elements> is every volume's kind; a <volume elements> overrides it,
// "hex" too, and a volume that does not say takes the mesh's.
TEST(JournalReader, MeshElementsAndAVolumesOwn) {
  const Job job = parse_journal(R"(<cooperage version="1">
  <geometry><brick name="b" origin="0 0 0" size="1 1 1"/></geometry>
  <mesh size="0.5" elements="wedge">
    <volume id="1" elements="hex"/>
    <volume id="2" size="0.2"/>
  </mesh>
</cooperage>)",
                                "mem.xml", "/base");
  ASSERT_TRUE(job.mesh);
  EXPECT_EQ(job.mesh->elements, ElementKind::Wedge);
  ASSERT_EQ(job.mesh->volumes.size(), 2u);
  EXPECT_EQ(job.mesh->volumes[0].elements, ElementKind::Hex);
  EXPECT_FALSE(job.mesh->volumes[1].elements);
  EXPECT_THROW(parse_journal(R"(<cooperage version="1">
  <geometry><brick name="b" origin="0 0 0" size="1 1 1"/></geometry>
  <mesh size="0.5" elements="tet"/>
</cooperage>)",
                             "mem.xml", "/base"),
               MeshingError);
}

TEST(JournalReader, DefaultsWhenAttributesAreOmitted) {
  const Job job = parse_journal(R"(<cooperage version="1">
  <geometry>
    <cylinder name="c" radius="1" height="2"/>
    <cone name="k" radius1="1" height="2"/>
    <sphere name="s" radius="1"/>
    <revolve name="r" axis="0 0 1"><profile points="1 0 0, 2 0 0, 2 0 1"/></revolve>
    <import name="i" file="a.brep"/>
    <torus name="t" major_radius="3" minor_radius="1"/>
  </geometry>
</cooperage>)",
                                "mem.xml", "/base");
  EXPECT_EQ(job.file, "mem.xml");
  EXPECT_EQ(job.base_dir, "/base");
  EXPECT_TRUE(job.imprint_merge);
  EXPECT_FALSE(job.mesh);
  EXPECT_TRUE(job.quality.empty());
  EXPECT_TRUE(job.exports.empty());
  EXPECT_TRUE(job.reports.empty());
  EXPECT_EQ(op<CylinderOp>(job, 0).base, Vec3::Zero());
  EXPECT_EQ(op<CylinderOp>(job, 0).axis, Vec3::UnitZ());
  EXPECT_DOUBLE_EQ(op<ConeOp>(job, 1).radius2, 0);
  EXPECT_EQ(op<SphereOp>(job, 2).center, Vec3::Zero());
  EXPECT_DOUBLE_EQ(op<RevolveOp>(job, 3).angle, 360);
  EXPECT_EQ(op<RevolveOp>(job, 3).origin, Vec3::Zero());
  EXPECT_TRUE(op<ImportOp>(job, 4).heal);
  EXPECT_EQ(op<TorusOp>(job, 5).center, Vec3::Zero());
  EXPECT_EQ(op<TorusOp>(job, 5).axis, Vec3::UnitZ());
  EXPECT_DOUBLE_EQ(op<TorusOp>(job, 5).major_radius, 3);
  EXPECT_DOUBLE_EQ(op<TorusOp>(job, 5).minor_radius, 1);
  EXPECT_EQ(job.geometry[2].where.line, 5);
}

TEST(JournalReader, LoftSectionsInOrder) {
  const Job job = parse_journal(R"(<cooperage version="1"><geometry>
    <loft name="tet">
      <section points="0.5 0.5 4"/>
      <section points="0 0 0, 2 0 0, 0 3 0"/>
    </loft>
    <loft name="twist" ruled="true">
      <section points="-0.5 -0.5 0, 0.5 -0.5 0, 0.5 0.5 0, -0.5 0.5 0"/>
      <section points="-0.353553 -0.612372 1, 0.612372 -0.353553 1, 0.353553 0.612372 1, -0.612372 0.353553 1"/>
    </loft>
  </geometry></cooperage>)",
                                "l.xml", ".");
  ASSERT_EQ(job.geometry.size(), 2u);
  const auto& tet = op<LoftOp>(job, 0);
  EXPECT_EQ(tet.name, "tet");
  EXPECT_TRUE(tet.ruled);  // the default
  ASSERT_EQ(tet.sections.size(), 2u);
  EXPECT_EQ(tet.sections[0], (Polygon{Vec3(0.5, 0.5, 4)}));
  EXPECT_EQ(tet.sections[1], (Polygon{Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0, 3, 0)}));
  const auto& twist = op<LoftOp>(job, 1);
  EXPECT_TRUE(twist.ruled);
  ASSERT_EQ(twist.sections.size(), 2u);
  EXPECT_EQ(twist.sections[1][1], Vec3(0.612372, -0.353553, 1));
  EXPECT_EQ(job.geometry[1].where.line, 6);
}

TEST(JournalReader, TwistedBlockExample) {
  const Job job = read_journal(kExamples + "/twisted_block.xml");
  ASSERT_EQ(job.geometry.size(), 1u);
  const auto& loft = op<LoftOp>(job, 0);
  EXPECT_EQ(loft.name, "twisted");
  EXPECT_TRUE(loft.ruled);
  ASSERT_EQ(loft.sections.size(), 2u);
  for (size_t k = 0; k < 2; ++k) {
    ASSERT_EQ(loft.sections[k].size(), 4u);
    for (const auto& p : loft.sections[k]) {
      EXPECT_DOUBLE_EQ(p.z(), 3.0 * static_cast<double>(k));
      EXPECT_NEAR(std::hypot(p.x(), p.y()), std::sqrt(0.5), 1e-6);
    }
  }
  EXPECT_DOUBLE_EQ(*job.mesh->size, 0.1);
  ASSERT_EQ(job.mesh->volumes.size(), 1u);
  EXPECT_EQ(job.mesh->volumes[0].scheme, "cooper");
  ASSERT_EQ(job.exports.size(), 1u);
  EXPECT_EQ(job.exports[0].file, "twisted_block.vtu");
}

TEST(JournalReader, NumbersInAllNotations) {
  const Job job = parse_journal(R"(<cooperage version="1"><geometry>
    <brick name="b" origin="+1 -0 .5" size="1e-3  2.  3E+1"/></geometry>
    <mesh size=" 0.25 " threads="0"/></cooperage>)",
                                "n.xml", ".");
  EXPECT_EQ(op<BrickOp>(job, 0).origin, Vec3(1, 0, 0.5));
  EXPECT_EQ(op<BrickOp>(job, 0).size, Vec3(1e-3, 2, 30));
  EXPECT_DOUBLE_EQ(*job.mesh->size, 0.25);
  EXPECT_EQ(job.mesh->threads, 0);
}

TEST(JournalReader, WebcutPiecesKeepTheirNameAndCanBeTransformed) {
  const Job job = parse_journal(R"(<cooperage version="1"><geometry>
    <brick name="b" size="1 1 1"/>
    <webcut shape="b" origin="0.5 0 0" normal="1 0 0"/>
    <translate shape="b" by="1 0 0"/>
  </geometry></cooperage>)",
                                "w.xml", ".");
  EXPECT_EQ(job.geometry.size(), 3u);
}

}  // namespace
}  // namespace cooperage::io
