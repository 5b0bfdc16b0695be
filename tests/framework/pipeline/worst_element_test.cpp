// The note on a volume's worst element (framework/pipeline/worst_element.h):
// a blade whose face has an 8-degree corner is bounded there at any size,
// and the note says so; a hex made poor in the middle of a cube is not
// bounded by any corner, and the note says where it is; a good mesh gets
// no note. Values are checked against the hexes' own scaled Jacobians.
#include "framework/pipeline/worst_element.h"

#include "support/mesh_checks.h"

#include "framework/geometry/occ/workbench.h"
#include "framework/pipeline/mesher.h"
#include "pipeline_helpers.h"
#include "schemes/builtin_schemes.h"
#include "selector/select_schemes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace cooperage::pipeline {
namespace {

using geom::Vec3;

using testing::builtin_registry;
using testing::sized;

double worst_hex(const mesh::MeshDB& db, int volume) {
  double worst = 1.0;
  for (const mesh::Hex& h : db.volume(volume).hexes)
    worst = std::min(worst, testing::hex_scaled_jacobian(testing::hex_points(db, h)));
  return worst;
}

std::string number3(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f", v);
  return buf;
}

// A prism 1 thick on the profile (0,0) (L,0) (L,2) (2/tan 8deg, 2): its
// faces at z = 0 and 1 have a corner of 8 degrees at x = y = 0, and every
// hex there has a face with that corner: sin 8 = 0.139 at most.
TEST(WorstElement, AnEightDegreeCornerIsNamedAsTheBound) {
  const double tip = 2.0 / std::tan(8.0 * M_PI / 180.0);
  occ::Workbench wb;
  wb.prism("blade", {{0, 0, 0}, {tip + 4, 0, 0}, {tip + 4, 2, 0}, {tip, 2, 0}}, {}, {0, 0, 1});
  const geom::Model model = wb.build_model();
  const MeshResult r = mesh_model(model, sized(0.5), builtin_registry(), selector::mesh_options());
  const double worst = worst_hex(r.mesh, 1);
  ASSERT_GT(worst, 0.0);
  ASSERT_LT(worst, std::sin(8.0 * M_PI / 180.0) + 0.01);
  const std::string note = worst_element_note(model, r.mesh, 1);
  EXPECT_NE(note.find("scaled Jacobian of " + number3(worst)), std::string::npos) << note;
  EXPECT_NE(note.find("has a corner of 8.0 degrees"), std::string::npos) << note;
  EXPECT_NE(note.find("(0.139)"), std::string::npos) << note;
  // The run carries it as the volume's warning.
  bool warned = false;
  for (const auto& w : r.warnings) warned = warned || w.message == note;
  EXPECT_TRUE(warned);
}

// A 2 x 2 x 2 grid of hexes in the unit cube with its centre node moved
// 0.155 along each axis: the hex towards (1, 1, 1) nearly folds at it (at
// 1/6 it would), and no model corner is at that node.
TEST(WorstElement, APoorHexAwayFromCornersSaysWhereItIs) {
  occ::Workbench wb;
  wb.brick("cube", {0, 0, 0}, {1, 1, 1});
  const geom::Model model = wb.build_model();
  mesh::MeshDB db;
  int node[3][3][3];
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      for (int k = 0; k < 3; ++k) {
        Vec3 x(0.5 * i, 0.5 * j, 0.5 * k);
        const bool centre = i == 1 && j == 1 && k == 1;
        if (centre) x += Vec3(0.155, 0.155, 0.155);
        node[i][j][k] = db.add_node(x, {static_cast<std::int8_t>(centre ? 3 : 2), 1});
      }
    }
  }
  auto& hexes = db.mutable_volume(1).hexes;
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 2; ++j) {
      for (int k = 0; k < 2; ++k) {
        hexes.push_back({node[i][j][k], node[i + 1][j][k], node[i + 1][j + 1][k], node[i][j + 1][k],
                         node[i][j][k + 1], node[i + 1][j][k + 1], node[i + 1][j + 1][k + 1],
                         node[i][j + 1][k + 1]});
      }
    }
  }
  const double worst = worst_hex(db, 1);
  ASSERT_GT(worst, 0.0);
  ASSERT_LT(worst, 0.2);
  const std::string note = worst_element_note(model, db, 1);
  EXPECT_EQ(note.rfind("its worst hex has a scaled Jacobian of " + number3(worst), 0), 0u) << note;
  EXPECT_NE(note.find("no corner or edge of the part there bounds it"), std::string::npos) << note;
  // Below a bar under its worst value there is nothing to say.
  EXPECT_EQ(worst_element_note(model, db, 1, worst - 1e-9), "");
}

// One hex in the middle of the blade's 8-degree edge (the z-line through
// the origin), away from its vertices: no face corner is at it, the edge
// between the two side faces bounds it.
TEST(WorstElement, AnEightDegreeEdgeIsNamedAsTheBound) {
  const double angle = 8.0 * M_PI / 180.0;
  const double tip = 2.0 / std::tan(angle);
  occ::Workbench wb;
  wb.prism("blade", {{0, 0, 0}, {tip + 4, 0, 0}, {tip + 4, 2, 0}, {tip, 2, 0}}, {}, {0, 0, 1});
  const geom::Model model = wb.build_model();
  int edge = 0;
  for (const auto& c : model.curves()) {
    const Vec3 a = model.vertex(c.start_vertex).point, b = model.vertex(c.end_vertex).point;
    if (a.head<2>().norm() < 1e-9 && b.head<2>().norm() < 1e-9) edge = c.id;
  }
  ASSERT_GT(edge, 0);
  mesh::MeshDB db;
  const Vec3 along(1, 0, 0), slant(std::cos(angle), std::sin(angle), 0);
  std::vector<int> n;
  for (const double z : {0.25, 0.75}) {
    n.push_back(db.add_node({0, 0, z}, {1, edge}));
    n.push_back(db.add_node(0.5 * along + Vec3(0, 0, z), {2, 1}));
    n.push_back(db.add_node(0.5 * (along + slant) + Vec3(0, 0, z), {3, 1}));
    n.push_back(db.add_node(0.5 * slant + Vec3(0, 0, z), {2, 2}));
  }
  db.mutable_volume(1).hexes.push_back({n[0], n[1], n[2], n[3], n[4], n[5], n[6], n[7]});
  const double worst = worst_hex(db, 1);
  ASSERT_GT(worst, 0.0);
  const std::string note = worst_element_note(model, db, 1, 1.0);
  EXPECT_NE(note.find("along curve " + std::to_string(edge)), std::string::npos) << note;
  EXPECT_NE(note.find("meet at 8.0 degrees"), std::string::npos) << note;
  EXPECT_EQ(note.find("has a corner"), std::string::npos) << note;
}

// A column of sheared hexes (a sweep repeats a cap's worst shape layer
// after layer); `shears` gives each one's top face shift in x over its
// height of 1, so its scaled Jacobian is 1 / sqrt(1 + shear^2). The first
// `count` hexes only.
mesh::MeshDB sheared_column(const std::vector<double>& shears, size_t count) {
  mesh::MeshDB db;
  std::vector<int> below;
  double x = 0;
  for (size_t level = 0; level <= shears.size(); ++level) {
    std::vector<int> ring;
    for (const Vec3& c : {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)})
      ring.push_back(db.add_node(c + Vec3(x, 0, static_cast<double>(level)), {3, 1}));
    if (level > 0 && level <= count) {
      db.mutable_volume(1).hexes.push_back(
          {below[0], below[1], below[2], below[3], ring[0], ring[1], ring[2], ring[3]});
    }
    if (level < shears.size()) x += shears[level];
    below = ring;
  }
  return db;
}

// Hexes within 1e-6 of the worst are as bad: the note names the first of
// them, whichever rounding made smallest (a moved part named another), and
// a hex worse by more is named wherever it is.
TEST(WorstElement, OfHexesAsBadTheFirstIsNamed) {
  occ::Workbench wb;
  wb.brick("column", {0, 0, 0}, {40, 1, 4});
  const geom::Model model = wb.build_model();
  const double shear = 10.0;  // 0.0995
  // The first hex better by 1e-8, which rounding can do too.
  const double first = std::sqrt(1.0 / std::pow(1.0 / std::sqrt(1 + shear * shear) + 1e-8, 2) - 1);
  const mesh::MeshDB column = sheared_column({first, shear, shear, shear}, 4);
  ASSERT_LT(worst_hex(column, 1),
            testing::hex_scaled_jacobian(testing::hex_points(column, column.volume(1).hexes[0])));
  const std::string note = worst_element_note(model, column, 1);
  EXPECT_EQ(note, worst_element_note(model, sheared_column({first, shear, shear, shear}, 1), 1));
  // The last hex worse by 1e-3 is the one named.
  const double worse = std::sqrt(1.0 / std::pow(1.0 / std::sqrt(1 + shear * shear) - 1e-3, 2) - 1);
  const mesh::MeshDB last_worse = sheared_column({first, shear, shear, worse}, 4);
  const std::string named = worst_element_note(model, last_worse, 1);
  EXPECT_NE(named, note);
  EXPECT_NE(named.find("at ("), std::string::npos) << named;
  EXPECT_NE(named.find(", 3.5)"), std::string::npos) << named;  // the centre of the fourth
}

TEST(WorstElement, AGoodMeshHasNoNote) {
  occ::Workbench wb;
  wb.brick("b", {0, 0, 0}, {2, 3, 4});
  const geom::Model model = wb.build_model();
  const MeshResult r = mesh_model(model, sized(0.5), builtin_registry(), selector::mesh_options());
  EXPECT_EQ(worst_element_note(model, r.mesh, 1), "");
  EXPECT_TRUE(r.warnings.empty());
}

}  // namespace
}  // namespace cooperage::pipeline
