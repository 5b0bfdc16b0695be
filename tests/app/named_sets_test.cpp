// A solver's view of `cooperage run` / `cooperage mesh` output: the named
// blocks, side sets and node sets of examples/named_sets.xml read back from
// the written .exo, .msh and .inp by independent readers (netCDF4, meshio,
// the gmsh module), surface formats from `--dim 2` and 3D runs read back by
// meshio, and the journal errors for groups that name no entity.
#include "run_command.h"
#include "temp_dir.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace cooperage {
namespace {

namespace fs = std::filesystem;
using testing::run_command;

using testing::kCli;
using testing::kSource;
const std::string kPython = COOPERAGE_DEBIAN_PYTHON;

bool python_has(const std::string& modules) {
  return std::system((kPython + " -c 'import " + modules + "' > /dev/null 2>&1").c_str()) == 0;
}

/// Output lines of a read-back script of tests/framework/io/export.
std::vector<std::string> readback(const std::string& script, const std::string& file) {
  const auto r = run_command(kPython + " " + kSource + "/tests/framework/io/export/" + script +
                             " '" + file + "'");
  EXPECT_EQ(r.exit_code, 0) << file << "\n" << r.out << r.err;
  std::vector<std::string> lines;
  std::istringstream in(r.out);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

bool has(const std::vector<std::string>& lines, const std::string& line) {
  return std::find(lines.begin(), lines.end(), line) != lines.end();
}

std::string joined(const std::vector<std::string>& lines) {
  std::string s;
  for (const auto& l : lines) s += l + "\n";
  return s;
}

class NamedSets : public testing::TempDirTest {};

TEST_F(NamedSets, TheExamplesGroupsReachEveryFormatWithTheirNames) {
  if (!python_has("meshio, gmsh, netCDF4"))
    GTEST_SKIP() << kPython
                 << " lacks meshio, gmsh or netCDF4 (python3-meshio python3-gmsh "
                    "python3-netcdf4)";
  fs::copy_file(kSource + "/examples/named_sets.xml", path("named_sets.xml"));
  const auto r = run_command(kCli + " run -q " + path("named_sets.xml"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // left brick 1x1x1, right 2x1x1 at size 0.25: 64 and 128 hexes; each
  // named surface is 4x4 faces; the clamped end 5x5 nodes.
  const auto exo = readback("groups_readback.py", path("named_sets.exo"));
  for (const char* line :
       {"EXO_BLOCK 1 steel HEX8 64", "EXO_BLOCK 2 rubber HEX8 128", "EXO_SIDESET 10 fixed_end 16",
        "EXO_SIDESET 11 load_end 16", "EXO_SIDESET 12 interface 16", "EXO_NODESET 20 clamp 25"})
    EXPECT_TRUE(has(exo, line)) << line << "\n" << joined(exo);
  const auto msh = readback("groups_readback.py", path("named_sets.msh"));
  for (const char* line :
       {"MESHIO_PHYS 3 1 steel", "MESHIO_PHYS 2 11 load_end", "GMSH_PHYS 3 1 steel 64",
        "GMSH_PHYS 3 2 rubber 128", "GMSH_PHYS 2 10 fixed_end 16", "GMSH_PHYS 2 12 interface 16"})
    EXPECT_TRUE(has(msh, line)) << line << "\n" << joined(msh);
  const auto inp = readback("groups_readback.py", path("named_sets.inp"));
  for (const char* line : {"INP_ELSET steel 64", "INP_ELSET rubber 128", "INP_NSET clamp 25",
                           "INP_SURFACE fixed_end 16", "INP_SURFACE load_end 16"})
    EXPECT_TRUE(has(inp, line)) << line << "\n" << joined(inp);
  // The .ply is the bar's skin: 2*16 end faces + 4*48 sides, facing out.
  const auto ply = readback("surface_readback.py", path("named_sets.ply"));
  EXPECT_TRUE(has(ply, "READER meshio")) << joined(ply);
  EXPECT_TRUE(has(ply, "CELLS quad 224")) << joined(ply);
  EXPECT_TRUE(has(ply, "VOLUME 3")) << joined(ply);
  // `cooperage quality` still reads the .msh (only grouped elements in it).
  const auto q = run_command(kCli + " quality " + path("named_sets.msh"));
  EXPECT_EQ(q.exit_code, 0) << q.err;
}

TEST_F(NamedSets, AnUnknownIdNamesTheJournalLineAndWritesNothing) {
  std::ofstream(path("bad.xml")) << R"(<cooperage version="1">
  <geometry><brick name="b" origin="0 0 0" size="1 1 1"/></geometry>
  <mesh size="0.5"/>
  <sideset id="1" name="top" surfaces="6"/>
  <block id="1" name="steel" volumes="1 2"/>
  <export file="bad.exo"/>
</cooperage>
)";
  const auto r = run_command(kCli + " run -q " + path("bad.xml"));
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("bad.xml:5: <block>: the model has no volume 2"), std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(path("bad.exo")));
}

TEST_F(NamedSets, AJournalWithGroupsIsNotDecomposedBehindItsBack) {
  // Groups name the model's ids; cutting a volume would renumber them.
  std::ifstream in(kSource + "/examples/fig3a_auto.xml");
  std::stringstream text;
  text << in.rdbuf();
  std::string xml = text.str();
  const std::string mesh = "<mesh size=\"0.25\" decompose=\"auto\"/>";
  ASSERT_NE(xml.find(mesh), std::string::npos);
  xml.replace(xml.find(mesh), mesh.size(), mesh + "\n  <block id=\"1\" volumes=\"1\"/>");
  std::ofstream(path("fig3a.xml")) << xml;
  const auto r = run_command(kCli + " run -q " + path("fig3a.xml"));
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("automatic decomposition would renumber the entities that <block> at"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(path("fig3a_auto.exo")));
}

class SurfaceOutput : public testing::TempDirTest {};

TEST_F(SurfaceOutput, MeshDim2OfThePartReadsBackWithMeshioInEverySurfaceFormat) {
  if (!python_has("meshio")) GTEST_SKIP() << kPython << " lacks meshio (python3-meshio)";
  // The same run to .msh gives the reference (read by meshio too): each
  // surface file has every one of its faces (STL: two per quad).
  const std::string part = kSource + "/examples/part.step";
  const std::string mesh = kCli + " mesh " + part + " --size 2 --dim 2 -q -o ";
  const auto r = run_command(mesh + path("part.msh"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto ref =
      run_command(kPython + " -c \"import meshio; m = meshio.read('" + path("part.msh") +
                  "'); c = {b.type: 0 for b in m.cells}\n"
                  "for b in m.cells: c[b.type] += len(b.data)\n"
                  "print(c.get('quad', 0), c.get('triangle', 0))\"");
  ASSERT_EQ(ref.exit_code, 0) << ref.err;
  std::istringstream words(ref.out);
  size_t quads = 0, tris = 0;
  words >> quads >> tris;
  ASSERT_GT(quads, 0u);
  for (const std::string ext : {"obj", "off", "stl", "ply"}) {
    const auto made = run_command(mesh + path("part." + ext));
    ASSERT_EQ(made.exit_code, 0) << ext << "\n" << made.err;
    const auto got = readback("surface_readback.py", path("part." + ext));
    // meshio 5.0 reads triangles only from .off; the script parses quads.
    EXPECT_TRUE(has(got, ext == "off" ? "READER off-parser" : "READER meshio")) << joined(got);
    size_t q = 0, t = 0;
    for (const auto& l : got) {
      if (l.rfind("CELLS quad ", 0) == 0) q += std::stoul(l.substr(11));
      if (l.rfind("CELLS triangle ", 0) == 0) t += std::stoul(l.substr(15));
    }
    EXPECT_EQ(q, ext == "stl" ? 0 : quads) << ext;
    EXPECT_EQ(t, ext == "stl" ? 2 * quads + tris : tris) << ext;
  }
}

}  // namespace
}  // namespace cooperage
