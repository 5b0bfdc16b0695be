// .obj .off .stl .ply export through OpenMesh, read back by meshio
// (surface_readback.py): node and face counts, every point a mesh node,
// every face a surface element (STL: half of one), the faces facing out.
#include "framework/core/error.h"
#include "framework/io/export/write_mesh.h"

#include "export_fixtures.h"
#include "export_test_util.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <ostream>
#include <set>

namespace cooperage::test {
namespace {

using Lines = std::vector<std::vector<std::string>>;

struct Case {
  const char* ext;
  bool binary;
};
std::ostream& operator<<(std::ostream& os, const Case& c) {
  return os << c.ext << (c.binary ? " binary" : " ascii");
}

class SurfaceFormat : public ::testing::TestWithParam<Case> {};

/// The MeshDB node at `x` (coordinates in single precision), or -1.
int node_at(const mesh::MeshDB& db, const Vec3& x) {
  for (size_t i = 0; i < db.node_count(); ++i)
    if ((db.node(static_cast<int>(i)) - x).norm() < 1e-6) return static_cast<int>(i);
  return -1;
}

/// Checks the read-back against the surface elements of `surfaces` in `t`:
/// counts, points, faces (as node sets; a triangle must be half of a quad
/// for STL), and the enclosed volume.
void check(const TestMesh& t, const std::vector<int>& surfaces, const std::string& path,
           bool triangles, double volume) {
  const Lines r = readback(path, "", "surface_readback.py");
  ASSERT_FALSE(r.empty());
  // meshio reads every file but an .off with quads (meshio 5.0 reads
  // triangles only from .off; the script parses those itself).
  bool quads_in_file = !triangles;
  if (quads_in_file) {
    quads_in_file = false;
    for (int sid : surfaces) quads_in_file = quads_in_file || !t.db.surface(sid).quads.empty();
  }
  const bool off_quads = path.size() > 4 && path.substr(path.size() - 4) == ".off" && quads_in_file;
  EXPECT_EQ(value(r, "READER"), std::vector<std::string>{off_quads ? "off-parser" : "meshio"});
  std::set<std::set<int>> quads, tris;
  std::set<int> nodes;
  for (int sid : surfaces) {
    for (const auto& q : t.db.surface(sid).quads) {
      quads.insert(std::set<int>(q.begin(), q.end()));
      nodes.insert(q.begin(), q.end());
    }
    for (const auto& f : t.db.surface(sid).tris) {
      tris.insert(std::set<int>(f.begin(), f.end()));
      nodes.insert(f.begin(), f.end());
    }
  }
  EXPECT_EQ(value(r, "NODES"), std::vector<std::string>{std::to_string(nodes.size())});
  std::vector<int> point_node;
  for (const auto& l : with_key(r, "P")) {
    const int n = node_at(t.db, Vec3(std::stod(l[1]), std::stod(l[2]), std::stod(l[3])));
    EXPECT_TRUE(nodes.count(n)) << "point " << l[1] << " " << l[2] << " " << l[3];
    point_node.push_back(n);
  }
  ASSERT_EQ(point_node.size(), nodes.size());
  size_t n_faces = 0;
  for (const auto& l : with_key(r, "F")) {
    std::set<int> face;
    for (size_t k = 1; k < l.size(); ++k) face.insert(point_node.at(std::stoul(l[k])));
    ++n_faces;
    if (face.size() == 4) {
      EXPECT_TRUE(quads.count(face)) << "a quad that is no surface element";
    } else if (tris.count(face) == 0) {
      EXPECT_TRUE(triangles) << "a triangle that is no surface element";
      bool half = false;
      for (const auto& q : quads)
        half = half || std::includes(q.begin(), q.end(), face.begin(), face.end());
      EXPECT_TRUE(half) << "a triangle that is not half of a surface quad";
    }
  }
  EXPECT_EQ(n_faces, triangles ? 2 * quads.size() + tris.size() : quads.size() + tris.size());
  EXPECT_NEAR(std::stod(value(r, "VOLUME").at(0)), volume, 1e-5);
}

TEST_P(SurfaceFormat, ASurfaceMeshReadsBackWithMeshio) {
  COOPERAGE_REQUIRE_MESHIO();
  const TestMesh t = surface_only();  // the unit cube's skin, 24 quads
  io::ExportOptions o;
  o.binary = GetParam().binary;
  const std::string path = scratch_dir() + "/skin." + GetParam().ext;
  io::write_mesh(path, t.db, t.model, o);
  std::vector<int> all;
  for (const auto& [sid, s] : t.db.surfaces()) all.push_back(sid);
  check(t, all, path, std::string(GetParam().ext) == "stl", 1.0);
}

TEST_P(SurfaceFormat, AVolumeMeshWritesItsBoundaryFacingOut) {
  COOPERAGE_REQUIRE_MESHIO();
  const TestMesh t = two_blocks();  // two boxes sharing x = 1: the shared surface is left out
  io::ExportOptions o;
  o.binary = GetParam().binary;
  const std::string path = scratch_dir() + "/boundary." + GetParam().ext;
  io::write_mesh(path, t.db, t.model, o);
  std::vector<int> outer;
  for (const auto& s : t.model.surfaces())
    if (s.volumes.size() == 1) outer.push_back(s.id);
  ASSERT_EQ(outer.size(), 10u);
  check(t, outer, path, std::string(GetParam().ext) == "stl", 2.0);
}

INSTANTIATE_TEST_SUITE_P(Formats, SurfaceFormat,
                         ::testing::Values(Case{"obj", false}, Case{"off", false},
                                           Case{"stl", false}, Case{"ply", false},
                                           Case{"stl", true}, Case{"ply", true}),
                         [](const auto& p) {
                           return std::string(p.param.ext) +
                                  (p.param.binary ? "_binary" : "_ascii");
                         });

TEST(SurfaceWriter, WedgesAndTrianglesToo) {
  COOPERAGE_REQUIRE_MESHIO();
  const TestMesh t = mixed();  // a hex and two wedges: the skin has triangles
  const std::string path = scratch_dir() + "/mixed.ply";
  io::write_mesh(path, t.db, t.model);
  std::vector<int> all;
  for (const auto& s : t.model.surfaces()) all.push_back(s.id);
  check(t, all, path, false, 2.0);
}

TEST(SurfaceWriter, AnOffOfTrianglesReadsBackWithMeshio) {
  COOPERAGE_REQUIRE_MESHIO();
  TestMesh t = surface_only();
  for (const auto& s : t.model.surfaces()) {  // each quad into two triangles
    auto& m = t.db.mutable_surface(s.id);
    for (const auto& q : m.quads) {
      m.tris.push_back({q[0], q[1], q[2]});
      m.tris.push_back({q[0], q[2], q[3]});
    }
    m.quads.clear();
  }
  const std::string path = scratch_dir() + "/tris.off";
  io::write_mesh(path, t.db, t.model);
  std::vector<int> all;
  for (const auto& s : t.model.surfaces()) all.push_back(s.id);
  check(t, all, path, false, 1.0);
}

TEST(SurfaceWriter, AVolumeMeshWithoutSurfaceElementsIsRefusedAndNoFileIsLeft) {
  TestMesh t = one_block();
  for (const auto& s : t.model.surfaces()) t.db.mutable_surface(s.id) = {};
  const std::string dir = scratch_dir();
  try {
    io::write_mesh(dir + "/a.obj", t.db, t.model);
    ADD_FAILURE() << "no error";
  } catch (const MeshingError& e) {
    EXPECT_EQ(e.code(), ErrorCode::InvalidInput);
    EXPECT_NE(std::string(e.what()).find("no boundary surface elements"), std::string::npos)
        << e.what();
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

}  // namespace
}  // namespace cooperage::test
