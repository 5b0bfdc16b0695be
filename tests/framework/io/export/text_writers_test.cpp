// Gmsh .msh, VTK .vtu and Abaqus .inp export, read back with Debian's
// python3 (meshio, the gmsh module, and a hand parser for *SURFACE faces)
// through readback.py; compared with values computed here from the MeshDB.
#include "framework/io/export/inp_writer.h"
#include "framework/io/export/msh_writer.h"
#include "framework/io/export/vtu_writer.h"

#include "export_fixtures.h"
#include "export_test_util.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <limits>
#include <map>

namespace cooperage::test {
namespace {

using Lines = std::vector<std::vector<std::string>>;

double num(const std::string& s) { return std::stod(s); }

/// Counts, checksums and volumes the read-back must reproduce.
void check_points_and_volumes(const TestMesh& t, const Lines& r) {
  ASSERT_FALSE(r.empty());
  EXPECT_EQ(value(r, "NODES"), std::vector<std::string>{std::to_string(t.db.node_count())});
  Vec3 sum = Vec3::Zero();
  double sumsq = 0;
  for (const auto& x : t.db.coords()) {
    sum += x;
    sumsq += x.squaredNorm();
  }
  const auto s = value(r, "SUM");
  ASSERT_EQ(s.size(), 3u);
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(num(s[a]), sum[a], 1e-9 * (1 + std::abs(sum[a])));
  EXPECT_NEAR(num(value(r, "SUMSQ").at(0)), sumsq, 1e-9 * (1 + sumsq));
  double vmin = std::numeric_limits<double>::max(), vsum = 0;
  for (const auto& [vid, v] : t.db.volumes()) {
    for (const auto& h : v.hexes) {
      const double vol = signed_volume(t.db.coords(), h.data(), hex_outward_faces());
      vmin = std::min(vmin, vol);
      vsum += vol;
    }
    for (const auto& w : v.wedges) {
      const double vol = signed_volume(t.db.coords(), w.data(), wedge_outward_faces());
      vmin = std::min(vmin, vol);
      vsum += vol;
    }
  }
  ASSERT_GT(vmin, 0) << "fixture must have positive elements";
  const double py_min = num(value(r, "VOLMIN").at(0));
  EXPECT_GT(py_min, 0) << "an element reads back inverted";
  EXPECT_NEAR(py_min, vmin, 1e-9);
  EXPECT_NEAR(num(value(r, "VOLSUM").at(0)), vsum, 1e-9);
}

std::map<std::string, int> cell_counts(const Lines& r) {
  std::map<std::string, int> c;
  for (const auto& l : with_key(r, "CELLS")) c[l.at(1)] = std::stoi(l.at(2));
  return c;
}

std::map<std::string, int> expected_counts(const TestMesh& t, bool volumes, bool surfaces) {
  std::map<std::string, int> c;
  auto add = [&c](const char* k, size_t n) {
    if (n) c[k] += static_cast<int>(n);
  };
  if (volumes) {
    add("hexahedron", t.db.hex_count());
    add("wedge", t.db.wedge_count());
  }
  if (surfaces) {
    add("quad", t.db.quad_count());
    add("triangle", t.db.tri_count());
  }
  return c;
}

/// Surface elements as (surface id, nodes) in writer order: surfaces
/// ascending, quads then triangles.
Lines expected_surf(const TestMesh& t) {
  Lines e;
  for (const auto& [sid, s] : t.db.surfaces()) {
    auto add = [&, sid = sid](const auto& el) {
      std::vector<std::string> l{"SURF", std::to_string(sid)};
      for (int v : el) l.push_back(std::to_string(v));
      e.push_back(l);
    };
    for (const auto& q : s.quads) add(q);
    for (const auto& q : s.tris) add(q);
  }
  return e;
}

/// SURF lines grouped by (entity tag, element kind), keeping the order
/// within each group (readers list an entity's element types in their own
/// order).
Lines sorted_by_tag(Lines l) {
  std::stable_sort(l.begin(), l.end(), [](const auto& a, const auto& b) {
    return std::make_pair(std::stoi(a[1]), a.size()) < std::make_pair(std::stoi(b[1]), b.size());
  });
  return l;
}

std::vector<TestMesh> volume_fixtures() {
  std::vector<TestMesh> f;
  f.push_back(one_block());
  f.push_back(two_blocks());
  f.push_back(two_wedges());
  f.push_back(mixed());
  return f;
}

// ASCII and binary (ExportOptions::binary) read back the same.
class MshEncoding : public ::testing::TestWithParam<bool> {};

TEST_P(MshEncoding, ReadsBackWithMeshioAndGmsh) {
  COOPERAGE_REQUIRE_MESHIO();
  const std::string dir = scratch_dir();
  io::ExportOptions options;
  options.binary = GetParam();
  int n = 0;
  for (const TestMesh& t : volume_fixtures()) {
    SCOPED_TRACE("fixture " + std::to_string(n));
    const std::string path = dir + "/m" + std::to_string(n++) + (GetParam() ? "b" : "a") + ".msh";
    io::write_msh(path, t.db, t.model, options);
    const Lines r = readback(path, "--gmsh");
    check_points_and_volumes(t, r);
    EXPECT_EQ(cell_counts(r), expected_counts(t, true, true));
    EXPECT_EQ(sorted_by_tag(with_key(r, "SURF")), sorted_by_tag(expected_surf(t)));
    // gmsh itself: nodes, physical groups (name, entity), element counts.
    EXPECT_EQ(value(r, "GMSH_NODES").at(0), std::to_string(t.db.node_count()));
    const Lines got_phys = with_key(r, "GMSH_PHYS");
    size_t n3 = 0, n2 = 0;
    for (const auto& l : got_phys) {
      ASSERT_GE(l.size(), 5u);
      EXPECT_EQ(l[2], l.back()) << "physical tag = entity tag";
      (l[1] == "3" ? n3 : n2)++;
    }
    EXPECT_EQ(n3, t.db.volumes().size());
    EXPECT_EQ(n2, t.db.surfaces().size());
    int gmsh_hex = 0, gmsh_prism = 0;
    for (const auto& l : with_key(r, "GMSH_ELEMS")) {
      if (l[1] == "3" && l[2] == "5") gmsh_hex += std::stoi(l[3]);
      if (l[1] == "3" && l[2] == "6") gmsh_prism += std::stoi(l[3]);
    }
    for (const auto& l : with_key(r, "GMSH_MINDET")) EXPECT_GT(num(l.at(2)), 0) << "type " << l[1];
    EXPECT_EQ(with_key(r, "GMSH_MINDET").size(),
              static_cast<size_t>((t.db.hex_count() > 0) + (t.db.wedge_count() > 0)));
    EXPECT_EQ(gmsh_hex, static_cast<int>(t.db.hex_count()));
    EXPECT_EQ(gmsh_prism, static_cast<int>(t.db.wedge_count()));
  }
}

INSTANTIATE_TEST_SUITE_P(MshWriter, MshEncoding, ::testing::Bool(),
                         [](const auto& p) { return p.param ? "binary" : "ascii"; });

TEST(MshWriter, BinaryHeaderAndSize) {
  const TestMesh t = two_blocks();
  io::ExportOptions options;
  options.binary = true;
  const std::string dir = scratch_dir();
  io::write_msh(dir + "/b.msh", t.db, t.model, options);
  io::write_msh(dir + "/a.msh", t.db, t.model);
  const std::string text = read_all(dir + "/b.msh");
  const std::string head = "$MeshFormat\n4.1 1 8\n";
  ASSERT_EQ(text.rfind(head, 0), 0u);
  int one = 0;
  std::memcpy(&one, text.data() + head.size(), sizeof one);
  EXPECT_EQ(one, 1) << "the byte-order check value";
  EXPECT_NE(text.find("\n$EndNodes\n"), std::string::npos);
  EXPECT_NE(text.find("\n$EndElements\n"), std::string::npos);
  EXPECT_NE(text.find("3 1 \"left\"\n"), std::string::npos) << "physical names stay text";
}

TEST(MshWriter, PhysicalNamesAndNodeEntities) {
  const TestMesh t = two_blocks();
  const std::string path = scratch_dir() + "/names.msh";
  io::write_msh(path, t.db, t.model);
  const std::string text = read_all(path);
  EXPECT_EQ(text.rfind("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n", 0), 0u);
  EXPECT_NE(text.find("3 1 \"left\"\n"), std::string::npos);
  EXPECT_NE(text.find("3 2 \"right\"\n"), std::string::npos);
  EXPECT_NE(text.find("2 1 \"surface_1\"\n"), std::string::npos);
  // The eight box corners are model vertices: their nodes sit in dim-0 blocks.
  EXPECT_NE(text.find("\n0 1 0 1\n"), std::string::npos);
  EXPECT_NE(text.find("\n0 8 0 1\n"), std::string::npos);
}

class VtuEncoding : public ::testing::TestWithParam<bool> {};

TEST_P(VtuEncoding, ReadsBackWithMeshio) {
  COOPERAGE_REQUIRE_MESHIO();
  const std::string dir = scratch_dir();
  io::ExportOptions options;
  options.binary = GetParam();
  int n = 0;
  for (const TestMesh& t : volume_fixtures()) {
    SCOPED_TRACE("fixture " + std::to_string(n));
    const std::string path = dir + "/v" + std::to_string(n++) + (GetParam() ? "b" : "a") + ".vtu";
    io::write_vtu(path, t.db, t.model, options);
    if (GetParam()) {
      const std::string text = read_all(path);
      EXPECT_NE(text.find("<AppendedData encoding=\"raw\">"), std::string::npos);
      EXPECT_EQ(text.find("format=\"ascii\""), std::string::npos);
    }
    const Lines r = readback(path);
    check_points_and_volumes(t, r);
    EXPECT_EQ(cell_counts(r), expected_counts(t, true, false));
    // Axis-aligned cubes and right prisms: scaled Jacobians are exact.
    const double sj_min = t.db.wedge_count() ? std::sqrt(0.5) * 2 / std::sqrt(3.0) : 1.0;
    EXPECT_NEAR(num(value(r, "SJMIN").at(0)), sj_min, 1e-12);
    const double sj_max = t.db.hex_count() ? 1.0 : sj_min;
    EXPECT_NEAR(num(value(r, "SJMAX").at(0)), sj_max, 1e-12);
    for (const auto& l : with_key(r, "BLOCK")) {
      const int id = std::stoi(l[2]);
      const auto& v = t.db.volume(id);
      EXPECT_EQ(std::stoi(l[3]),
                static_cast<int>(l[1] == "wedge" ? v.wedges.size() : v.hexes.size()));
    }
  }
}

INSTANTIATE_TEST_SUITE_P(VtuWriter, VtuEncoding, ::testing::Bool(),
                         [](const auto& p) { return p.param ? "binary" : "ascii"; });

TEST_P(VtuEncoding, SurfacesOnRequestAndForSurfaceMeshes) {
  COOPERAGE_REQUIRE_MESHIO();
  const std::string dir = scratch_dir() + (GetParam() ? "/b" : "/a");
  std::filesystem::create_directories(dir);
  const TestMesh t = mixed();
  io::ExportOptions opt;
  opt.include_surfaces = true;
  opt.binary = GetParam();
  io::write_vtu(dir + "/with_surfaces.vtu", t.db, t.model, opt);
  Lines r = readback(dir + "/with_surfaces.vtu");
  EXPECT_EQ(cell_counts(r), expected_counts(t, true, true));
  EXPECT_EQ(sorted_by_tag(with_key(r, "SURF")), sorted_by_tag(expected_surf(t)));
  check_points_and_volumes(t, r);

  const TestMesh s = surface_only();
  io::ExportOptions shell_options;
  shell_options.binary = GetParam();
  io::write_vtu(dir + "/shell.vtu", s.db, s.model, shell_options);
  r = readback(dir + "/shell.vtu");
  EXPECT_EQ(cell_counts(r), expected_counts(s, false, true));
  EXPECT_EQ(sorted_by_tag(with_key(r, "SURF")), sorted_by_tag(expected_surf(s)));
  EXPECT_NEAR(num(value(r, "SJMIN").at(0)), 1.0, 1e-12);
}

TEST(InpWriter, ReadsBackWithMeshioAndSurfacesMatch) {
  COOPERAGE_REQUIRE_MESHIO();
  const std::string dir = scratch_dir();
  int n = 0;
  for (const TestMesh& t : volume_fixtures()) {
    SCOPED_TRACE("fixture " + std::to_string(n));
    const std::string path = dir + "/a" + std::to_string(n++) + ".inp";
    io::write_inp(path, t.db, t.model);
    const Lines r = readback(path);
    check_points_and_volumes(t, r);
    EXPECT_EQ(cell_counts(r), expected_counts(t, true, false));
    // *SURFACE faces (via the Abaqus face labels) = the surface elements.
    std::map<std::string, std::multiset<std::vector<int>>> got, expect;
    for (const auto& l : with_key(r, "FACE")) {
      std::vector<int> f;
      for (size_t k = 2; k < l.size(); ++k) f.push_back(std::stoi(l[k]));
      got[l[1]].insert(f);
    }
    for (const auto& [sid, s] : t.db.surfaces()) {
      auto& e = expect["surface_" + std::to_string(sid)];
      auto add = [&e](const auto& el) {
        std::vector<int> f(el.begin(), el.end());
        std::sort(f.begin(), f.end());
        e.insert(f);
      };
      for (const auto& q : s.quads) add(q);
      for (const auto& q : s.tris) add(q);
    }
    EXPECT_EQ(got, expect);
    EXPECT_EQ(with_key(r, "NSET").size(), t.db.surfaces().size());
  }
}

TEST(InpWriter, KeywordsAndSurfaceOnlyShells) {
  const std::string dir = scratch_dir();
  const TestMesh t = mixed();
  io::write_inp(dir + "/mixed.inp", t.db, t.model);
  const std::string text = read_all(dir + "/mixed.inp");
  EXPECT_EQ(text.rfind("*HEADING\n", 0), 0u);
  EXPECT_NE(text.find("*ELEMENT, TYPE=C3D8, ELSET=mixed_C3D8\n1, "), std::string::npos);
  EXPECT_NE(text.find("*ELEMENT, TYPE=C3D6, ELSET=mixed_C3D6\n2, "), std::string::npos);
  EXPECT_NE(text.find("*ELSET, ELSET=mixed\nmixed_C3D8\nmixed_C3D6\n"), std::string::npos);
  EXPECT_NE(text.find("*SURFACE, TYPE=ELEMENT, NAME=surface_1\n"), std::string::npos);

  const TestMesh s = surface_only();
  io::write_inp(dir + "/shell.inp", s.db, s.model);
  const std::string shell = read_all(dir + "/shell.inp");
  EXPECT_NE(shell.find("*ELEMENT, TYPE=S4, ELSET=surface_1\n"), std::string::npos);
  EXPECT_EQ(shell.find("*SURFACE"), std::string::npos);
  if (have_meshio()) {
    const Lines r = readback(dir + "/shell.inp");
    EXPECT_EQ(cell_counts(r), expected_counts(s, false, true));
  }
}

}  // namespace
}  // namespace cooperage::test
