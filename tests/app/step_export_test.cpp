// Issue 15, "Done when": the must-mesh parts (built from journal primitives,
// tests/schemes/cooper/must_mesh_parts.h) mesh through `cooperage mesh` and
// `cooperage run` on STEP exports of the same parts. Each part is written
// to STEP by the Workbench in a scratch directory, meshed by the command
// line, and its .exo read back and checked independently of the mesher:
// hexes only, every hex face in at most two hexes and the faces in one
// closed (every boundary edge in exactly two boundary faces), no two nodes
// at one place, a minimum scaled Jacobian of at least 0.3 and the hexes'
// exact volume within 0.5 % of the solid's (OCCT's volume of the part).
// Coarse sizes keep it fast (the must-mesh tests cover the finer ones).
#include "run_command.h"
#include "support/mesh_checks.h"
#include "temp_dir.h"

#include "framework/geometry/occ/workbench.h"
#include "framework/io/read/read_mesh_file.h"
#include "schemes/cooper/must_mesh_parts.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <utility>

namespace cooperage {
namespace {

struct Checked {
  size_t hexes = 0;
  double volume = 0;
  double min_sj = 1;
};

// The mesh file's hexes as a MeshDB (one volume per block), checked.
Checked check_mesh_file(const std::string& path, const std::string& name) {
  const io::MeshFile f = io::read_mesh_file(path);
  mesh::MeshDB db;
  for (const auto& x : f.coords) db.add_node(x, {3, 0});
  int id = 0;
  for (const io::MeshBlock& b : f.blocks) {
    EXPECT_EQ(b.type, quality::ElementType::Hex) << name << ": block " << b.name << " is not hexes";
    if (b.type != quality::ElementType::Hex) continue;
    auto& v = db.mutable_volume(++id);
    for (size_t e = 0; e < b.size(); ++e) {
      mesh::Hex h;
      for (int k = 0; k < 8; ++k)
        h[static_cast<size_t>(k)] = b.connectivity[8 * e + static_cast<size_t>(k)];
      v.hexes.push_back(h);
    }
  }
  EXPECT_TRUE(f.skipped.empty()) << name << ": cells other than hexes";
  Checked c;
  for (const auto& [vid, v] : db.volumes()) {
    for (const auto& h : v.hexes) {
      const auto p = testing::hex_points(db, h);
      c.volume += testing::hex_volume(p);
      c.min_sj = std::min(c.min_sj, testing::hex_scaled_jacobian(p));
      ++c.hexes;
    }
  }
  // Conformal and closed: faces in one or two hexes; the edges of the
  // faces in one hex each in exactly two of them.
  static const int side[6][4] = {{0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6},
                                 {0, 4, 7, 3}, {0, 3, 2, 1}, {4, 5, 6, 7}};
  std::map<testing::FaceKey, std::pair<int, std::array<int, 4>>> faces;
  for (const auto& [vid, v] : db.volumes()) {
    for (const auto& h : v.hexes) {
      for (const auto& s : side) {
        const std::array<int, 4> q = {h[s[0]], h[s[1]], h[s[2]], h[s[3]]};
        auto& entry = faces[testing::face_key(q)];
        ++entry.first;
        entry.second = q;
      }
    }
  }
  std::map<std::pair<int, int>, int> edges;
  int overused = 0;
  for (const auto& [key, entry] : faces) {
    if (entry.first > 2) ++overused;
    if (entry.first != 1) continue;
    for (int k = 0; k < 4; ++k) {
      const int a = entry.second[static_cast<size_t>(k)],
                b = entry.second[static_cast<size_t>((k + 1) % 4)];
      ++edges[{std::min(a, b), std::max(a, b)}];
    }
  }
  EXPECT_EQ(overused, 0) << name << ": faces in more than two hexes";
  int open = 0;
  for (const auto& [e, n] : edges) open += n != 2;
  EXPECT_EQ(open, 0) << name << ": boundary edges not in exactly two boundary faces";
  EXPECT_EQ(testing::duplicate_node_pairs(db, 1e-9), 0) << name;
  return c;
}

class StepExport : public testing::TempDirTest {};

// A size per part: 0.4 where that keeps the minimum scaled Jacobian above
// 0.3; the Fig. 1 part and the elbow at 0.3; the round/square overlaps of
// k = 1 at their must-mesh size 0.25 (at 0.3 and 0.4 their worst hex falls
// to 0.27-0.29 and 0.19: the lens between the two footprints is thin).
TEST_F(StepExport, MustMeshPartsMeshFromTheirStepFiles) {
  const std::map<std::string, double> size_of = {{"fig1_part", 0.3},
                                                 {"elbow_with_boss", 0.3},
                                                 {"round_over_square_1.0", 0.25},
                                                 {"square_over_round_1.0", 0.25}};
  for (const auto& [name, build] : cooper::parts::all()) {
    SCOPED_TRACE(name);
    occ::Workbench wb;
    build(wb);
    const std::string step = path(name + ".step");
    wb.write(step);
    double solid = 0;
    const geom::Model model = wb.build_model();
    for (const auto& v : model.volumes()) solid += v.volume;
    const auto it = size_of.find(name);
    const double size = it == size_of.end() ? 0.4 : it->second;
    const std::string out = path(name + ".exo");
    const auto r = testing::run_command(std::string(COOPERAGE_CLI) + " mesh " + step + " --size " +
                                        std::to_string(size) + " -o " + out + " --quiet");
    ASSERT_EQ(r.exit_code, 0) << name << ":\n" << r.err;
    const Checked c = check_mesh_file(out, name);
    EXPECT_GE(c.min_sj, 0.3) << name;
    EXPECT_NEAR(c.volume, solid, 0.005 * solid) << name;
    std::printf(
        "[step export] %s at size %g: %zu hexes, min scaled Jacobian %.3f, volume %+.3f %%\n",
        name.c_str(), size, c.hexes, c.min_sj, 100 * (c.volume - solid) / solid);
  }
}

// `cooperage run` on a journal importing the STEP file of a part with
// blind holes from both ends and of the flanged hub.
TEST_F(StepExport, RunImportsTheStepFileOfAPart) {
  for (const auto& [name, build] : cooper::parts::all()) {
    if (name != "blind_holes_both_ends" && name != "flanged_hub") continue;
    SCOPED_TRACE(name);
    occ::Workbench wb;
    build(wb);
    wb.write(path(name + ".step"));
    double solid = 0;
    const geom::Model model = wb.build_model();
    for (const auto& v : model.volumes()) solid += v.volume;
    {
      std::ofstream j(path(name + ".xml"));
      j << "<cooperage version=\"1\">\n  <geometry>\n    <import name=\"part\" file=\"" << name
        << ".step\"/>\n"
        << "  </geometry>\n  <mesh size=\"0.3\"/>\n  <export file=\"" << name
        << ".exo\"/>\n</cooperage>\n";
    }
    const auto r = testing::run_command(std::string(COOPERAGE_CLI) + " run " + path(name + ".xml") +
                                        " --quiet");
    ASSERT_EQ(r.exit_code, 0) << name << ":\n" << r.err;
    const Checked c = check_mesh_file(path(name + ".exo"), name);
    EXPECT_GE(c.min_sj, 0.3) << name;
    EXPECT_NEAR(c.volume, solid, 0.005 * solid) << name;
    std::printf("[step export] run %s: %zu hexes, min scaled Jacobian %.3f\n", name.c_str(),
                c.hexes, c.min_sj);
  }
}

}  // namespace
}  // namespace cooperage
