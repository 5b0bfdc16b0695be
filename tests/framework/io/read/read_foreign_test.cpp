// Files from other producers: meshio (.vtu base64 binary, .msh 4.1 ASCII)
// and Gmsh itself (a transfinite, recombined box, 4.1 and 2.2 ASCII).
// Counts must match what Python reports and every hex / wedge must have a
// positive volume (so VTK wedges were converted to Exodus order).
#include "framework/io/export/export_test_util.h"
#include "read_test_util.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

namespace cooperage::test {
namespace {

using quality::ElementType;

/// Runs `script` with Debian's python; returns its "key value" output lines.
/// Returns false (and the caller skips) when the script cannot import its modules.
bool run_python(const std::string& dir, const std::string& script,
                std::map<std::string, size_t>& counts) {
  const std::string py = dir + "/make.py", out = dir + "/make.txt";
  std::ofstream(py) << script;
  const std::string cmd =
      std::string(COOPERAGE_DEBIAN_PYTHON) + " '" + py + "' > '" + out + "' 2> '" + out + ".err'";
  if (std::system(cmd.c_str()) != 0) {
    ADD_FAILURE() << "python failed: " << read_all(out + ".err");
    return false;
  }
  std::istringstream in(read_all(out));
  std::string key;
  size_t n = 0;
  while (in >> key >> n) counts[key] = n;
  return true;
}

bool have_module(const char* module) {
  const std::string cmd =
      std::string(COOPERAGE_DEBIAN_PYTHON) + " -c 'import " + module + "' > /dev/null 2>&1";
  return std::system(cmd.c_str()) == 0;
}

// A unit hex, a wedge next to it (meshio's wedge order is Gmsh's / Exodus's),
// a tetra on top and a line: the last two must be skipped.
const char* kMeshioScript = R"(
import sys, meshio, numpy as np
d = sys.argv[0].rsplit('/', 1)[0]
pts = np.array([[0,0,0],[1,0,0],[1,1,0],[0,1,0],[0,0,1],[1,0,1],[1,1,1],[0,1,1],
                [2,0,0],[2,0,1],[0.5,0.5,2]], dtype=float)
cells = [("hexahedron", np.array([[0,1,2,3,4,5,6,7]])),
         ("wedge", np.array([[1,8,2,5,9,6]])),
         ("tetra", np.array([[4,5,6,10]])),
         ("line", np.array([[0,1]]))]
# Gmsh 4.1 needs an entity per node and per cell block (meshio's gmsh:* data).
m = meshio.Mesh(pts, cells, field_data={"solid": np.array([7, 3]), "edge": np.array([8, 1])},
                point_data={"gmsh:dim_tags": np.array([[3, 1]] * len(pts))},
                cell_data={"gmsh:physical": [np.array([7])] * 3 + [np.array([8])],
                           "gmsh:geometrical": [np.array([t]) for t in (1, 2, 3, 1)]})
meshio.write(d + "/m32.vtu", m, binary=True, compression=None)
meshio.write(d + "/m64.vtu", m, binary=True, compression=None, header_type="UInt64")
meshio.write(d + "/mascii.vtu", m, binary=False)
meshio.write(d + "/m.msh", m, file_format="gmsh", binary=False)
meshio.write(d + "/m22.msh", m, file_format="gmsh22", binary=False)
print("points", len(pts))
print("hex", 1)
print("wedge", 1)
)";

TEST(ReadForeign, MeshioFiles) {
  if (!have_module("meshio")) GTEST_SKIP() << "Debian python3-meshio not installed";
  const std::string dir = scratch_dir();
  std::map<std::string, size_t> counts;
  ASSERT_TRUE(run_python(dir, kMeshioScript, counts));
  ASSERT_EQ(counts["hex"], 1u);
  for (const char* name : {"m32.vtu", "m64.vtu", "mascii.vtu", "m.msh", "m22.msh"}) {
    SCOPED_TRACE(name);
    const std::string path = dir + "/" + name;
    const io::MeshFile f = io::read_mesh_file(path);
    EXPECT_EQ(f.coords.size(), counts["points"]);
    EXPECT_EQ(count_of(f, ElementType::Hex), counts["hex"]);
    EXPECT_EQ(count_of(f, ElementType::Wedge), counts["wedge"]);
    EXPECT_GT(min_volume(f), 0.0);
    EXPECT_NEAR(min_volume(f), 0.5, 1e-12);  // the wedge; the hex is 1
    EXPECT_EQ(f.skipped.at("tetra"), 1u);
    EXPECT_EQ(f.skipped.at("line"), 1u);
    if (std::string(name).find(".msh") != std::string::npos) {
      for (const auto& b : f.blocks) {
        if (b.type == ElementType::Hex) {
          EXPECT_EQ(b.name, "solid");  // physical name
        }
      }
    }
  }
  // The binary vtus really are uncompressed base64 binary, with both header types.
  for (const char* name : {"m32.vtu", "m64.vtu"}) {
    const std::string text = read_all(dir + "/" + name);
    EXPECT_NE(text.find("format=\"binary\""), std::string::npos) << name;
    EXPECT_EQ(text.find("compressor"), std::string::npos) << name;
  }
  EXPECT_NE(read_all(dir + "/m64.vtu").find("header_type=\"UInt64\""), std::string::npos);
}

// A 1 x 2 x 3 box, transfinite with 3 nodes per curve and recombined: 8 hexes.
const char* kGmshScript = R"(
import sys, gmsh
d = sys.argv[0].rsplit('/', 1)[0]
gmsh.initialize()
gmsh.option.setNumber("General.Terminal", 0)
gmsh.model.add("box")
gmsh.model.occ.addBox(0, 0, 0, 1, 2, 3)
gmsh.model.occ.synchronize()
for dim, tag in gmsh.model.getEntities(1):
    gmsh.model.mesh.setTransfiniteCurve(tag, 3)
for dim, tag in gmsh.model.getEntities(2):
    gmsh.model.mesh.setTransfiniteSurface(tag)
    gmsh.model.mesh.setRecombine(2, tag)
gmsh.model.mesh.setTransfiniteVolume(1)
p = gmsh.model.addPhysicalGroup(3, [1])
gmsh.model.setPhysicalName(3, p, "the box")
gmsh.model.mesh.generate(3)
gmsh.option.setNumber("Mesh.MshFileVersion", 4.1)
gmsh.write(d + "/box41.msh")
gmsh.option.setNumber("Mesh.Binary", 1)
gmsh.write(d + "/box41b.msh")
gmsh.option.setNumber("Mesh.Binary", 0)
gmsh.option.setNumber("Mesh.MshFileVersion", 2.2)
gmsh.write(d + "/box22.msh")
types, tags, nodes = gmsh.model.mesh.getElements(3)
n = sum(len(t) for ty, t in zip(types, tags) if ty == 5)
print("hex", n)
print("nodes", len(gmsh.model.mesh.getNodes()[0]))
gmsh.finalize()
)";

TEST(ReadForeign, GmshTransfiniteBox) {
  if (!have_module("gmsh")) GTEST_SKIP() << "Debian python3-gmsh not installed";
  const std::string dir = scratch_dir();
  std::map<std::string, size_t> counts;
  ASSERT_TRUE(run_python(dir, kGmshScript, counts));
  ASSERT_EQ(counts["hex"], 8u);
  for (const char* name : {"box41.msh", "box41b.msh", "box22.msh"}) {
    SCOPED_TRACE(name);
    const io::MeshFile f = io::read_mesh_file(dir + "/" + name);
    EXPECT_EQ(count_of(f, ElementType::Hex), counts["hex"]);
    ASSERT_EQ(f.blocks.size(), 1u);
    EXPECT_EQ(f.blocks[0].name, "the box");
    EXPECT_GT(min_volume(f), 0.0);
    double total = 0;
    for (size_t e = 0; e < f.blocks[0].size(); ++e) {
      total +=
          signed_volume(f.coords, f.blocks[0].connectivity.data() + 8 * e, hex_outward_faces());
    }
    EXPECT_NEAR(total, 6.0, 1e-9);
  }
}

}  // namespace
}  // namespace cooperage::test
