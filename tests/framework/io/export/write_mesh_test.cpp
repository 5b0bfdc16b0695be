// write_mesh dispatch, atomic writes and error handling; the local scaled
// Jacobian.
#include "framework/io/export/write_mesh.h"

#include "framework/core/error.h"
#include "framework/io/export/export_common.h"

#include "export_fixtures.h"
#include "export_test_util.h"

#include <gtest/gtest.h>

#include <dirent.h>

namespace cooperage::test {
namespace {

const char* kExtensions[] = {"exo", "e", "g", "msh", "vtu", "inp"};

std::vector<std::string> list_dir(const std::string& dir) {
  std::vector<std::string> names;
  if (DIR* d = opendir(dir.c_str())) {
    while (dirent* e = readdir(d)) {
      const std::string n = e->d_name;
      if (n != "." && n != "..") names.push_back(n);
    }
    closedir(d);
  }
  std::sort(names.begin(), names.end());
  return names;
}

TEST(WriteMesh, DispatchesOnExtension) {
  const TestMesh t = two_blocks();
  const std::string dir = scratch_dir();
  for (const char* ext : kExtensions) {
    const std::string path = dir + "/mesh." + ext;
    io::write_mesh(path, t.db, t.model);
    EXPECT_TRUE(file_exists(path)) << path;
  }
  io::write_mesh(dir + "/UPPER.VTU", t.db, t.model);
  EXPECT_NE(read_all(dir + "/mesh.msh").find("$MeshFormat"), std::string::npos);
  EXPECT_NE(read_all(dir + "/mesh.vtu").find("<VTKFile"), std::string::npos);
  EXPECT_NE(read_all(dir + "/UPPER.VTU").find("<VTKFile"), std::string::npos);
  EXPECT_EQ(read_all(dir + "/mesh.inp").rfind("*HEADING", 0), 0u);
  EXPECT_EQ(read_all(dir + "/mesh.exo").substr(0, 3), "CDF");  // netCDF classic
  EXPECT_EQ(list_dir(dir).size(), 7u) << "no temporary files left behind";
}

TEST(WriteMesh, UnknownExtensionListsAllowedOnes) {
  const TestMesh t = one_block();
  const std::string dir = scratch_dir();
  for (const std::string name : {"/mesh.step", "/mesh", "/dir.d/mesh"}) {
    try {
      io::write_mesh(dir + name, t.db, t.model);
      ADD_FAILURE() << "no error for " << name;
    } catch (const MeshingError& e) {
      EXPECT_EQ(e.code(), ErrorCode::InvalidInput);
      const std::string m = e.what();
      for (const char* ext :
           {".exo", ".e", ".g", ".msh", ".vtu", ".inp", ".obj", ".off", ".stl", ".ply"})
        EXPECT_NE(m.find(ext), std::string::npos) << m;
    }
  }
  EXPECT_TRUE(list_dir(dir).empty());
}

TEST(WriteMesh, MissingDirectoryThrowsAndWritesNothing) {
  const TestMesh t = one_block();
  const std::string dir = scratch_dir();
  for (const char* ext : kExtensions) {
    const std::string path = dir + "/no/such/dir/mesh." + ext;
    EXPECT_THROW(io::write_mesh(path, t.db, t.model), MeshingError) << ext;
    EXPECT_FALSE(file_exists(path));
  }
  EXPECT_TRUE(list_dir(dir).empty());
}

TEST(WriteMesh, InvalidMeshNeverClobbersAGoodFile) {
  const TestMesh good = one_block();
  TestMesh bad = one_block();
  bad.db.mutable_volume(1).hexes[3][5] = static_cast<int>(bad.db.node_count());  // out of range
  const std::string dir = scratch_dir();
  for (const char* ext : kExtensions) {
    const std::string path = dir + "/mesh." + ext;
    io::write_mesh(path, good.db, good.model);
    const std::string before = read_all(path);
    ASSERT_FALSE(before.empty());
    try {
      io::write_mesh(path, bad.db, bad.model);
      ADD_FAILURE() << "no error for ." << ext;
    } catch (const MeshingError& e) {
      EXPECT_EQ(e.code(), ErrorCode::InvalidInput) << e.what();
      EXPECT_EQ(e.entity().dim, 3);
      EXPECT_EQ(e.entity().id, 1);
      EXPECT_NE(std::string(e.what()).find("hex 3"), std::string::npos) << e.what();
    }
    EXPECT_EQ(read_all(path), before) << ext;
  }
  EXPECT_EQ(list_dir(dir).size(), 6u) << "no temporary files left behind";
}

TEST(WriteMesh, OtherInvalidInput) {
  const std::string dir = scratch_dir();
  TestMesh t = one_block();
  t.db.mutable_surface(99).quads.push_back({0, 1, 2, 3});  // not in the model
  EXPECT_THROW(io::write_mesh(dir + "/a.vtu", t.db, t.model), MeshingError);
  TestMesh empty;
  empty.db.add_node(Vec3::Zero(), {});
  EXPECT_THROW(io::write_mesh(dir + "/b.msh", empty.db, empty.model), MeshingError);
  // A surface quad that is no face of its volume's hexes (non-conformal).
  TestMesh nc = one_block();
  auto& q = nc.db.mutable_surface(1).quads[0];
  std::swap(q[0], q[2]);
  q[0] = q[1];
  q[1] = static_cast<int>(nc.db.node_count()) - 1;
  for (const char* ext : {"exo", "inp"}) {
    try {
      io::write_mesh(dir + "/c." + ext, nc.db, nc.model);
      ADD_FAILURE() << "no error for ." << ext;
    } catch (const MeshingError& e) {
      EXPECT_EQ(e.entity().dim, 2) << e.what();
    }
  }
  EXPECT_TRUE(list_dir(dir).empty());
}

TEST(ScaledJacobian, VerdictValues) {
  using io::detail::scaled_jacobian;
  std::vector<Vec3> x{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                      {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  const mesh::Hex cube{0, 1, 2, 3, 4, 5, 6, 7};
  EXPECT_NEAR(scaled_jacobian(cube, x), 1.0, 1e-15);
  const mesh::Hex inverted{4, 5, 6, 7, 0, 1, 2, 3};
  EXPECT_NEAR(scaled_jacobian(inverted, x), -1.0, 1e-15);
  std::vector<Vec3> sheared = x;
  for (int k = 4; k < 8; ++k) sheared[k].x() += 1.0;  // 45 degree shear
  EXPECT_NEAR(scaled_jacobian(cube, sheared), std::sqrt(0.5), 1e-12);
  // Equilateral prism: 1 (Verdict scales wedges by 2/sqrt(3)).
  std::vector<Vec3> w{{0, 0, 0}, {1, 0, 0}, {0.5, std::sqrt(3.0) / 2, 0},
                      {0, 0, 1}, {1, 0, 1}, {0.5, std::sqrt(3.0) / 2, 1}};
  EXPECT_NEAR(scaled_jacobian(mesh::Wedge{0, 1, 2, 3, 4, 5}, w), 1.0, 1e-12);
  EXPECT_LT(scaled_jacobian(mesh::Wedge{0, 2, 1, 3, 5, 4}, w), 0.0);
  EXPECT_NEAR(scaled_jacobian(mesh::Quad{0, 1, 2, 3}, x), 1.0, 1e-15);
  EXPECT_NEAR(scaled_jacobian(mesh::Tri{0, 1, 3}, x),
              std::min(1.0, 2 / std::sqrt(3.0) * std::sqrt(0.5)), 1e-12);
}

}  // namespace
}  // namespace cooperage::test
