// Error cases of io::read_mesh_file: every error names the file and says
// what is wrong.
#include "framework/core/error.h"
#include "framework/io/export/export_test_util.h"
#include "framework/io/export/write_mesh.h"
#include "read_test_util.h"

#include <gtest/gtest.h>

#include <cstdint>

#include <fstream>

namespace cooperage::test {
namespace {

using quality::ElementType;

/// Runs read_mesh_file(path), expecting MeshingError(code) whose message
/// contains `path` and `text`.
void expect_error(const std::string& path, ErrorCode code, const std::string& text) {
  try {
    io::read_mesh_file(path);
    ADD_FAILURE() << "no error for " << path;
  } catch (const MeshingError& e) {
    EXPECT_EQ(e.code(), code) << e.what();
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
  }
}

void write_file(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

TEST(ReadErrors, MissingFile) {
  const std::string dir = scratch_dir();
  for (const char* ext : {".exo", ".msh", ".vtu"}) {
    expect_error(dir + "/nothing" + ext, ErrorCode::FileNotFound, "no such file");
  }
}

TEST(ReadErrors, UnknownExtensionListsAllowedOnes) {
  const std::string path = scratch_dir() + "/mesh.stl";
  write_file(path, "solid x\nendsolid x\n");
  expect_error(path, ErrorCode::InvalidInput, ".exo .e .g .msh .vtu");
}

TEST(ReadErrors, TruncatedMshNamesTheLine) {
  const TestMesh t = one_block();
  const std::string dir = scratch_dir();
  io::write_mesh(dir + "/full.msh", t.db, t.model);
  const std::string text = read_all(dir + "/full.msh");
  const size_t cut = text.find("$Elements") + 40;  // inside the first element block
  write_file(dir + "/cut.msh", text.substr(0, cut));
  expect_error(dir + "/cut.msh", ErrorCode::ParseError, "line ");
}

TEST(ReadErrors, MshWithoutEndElements) {
  const TestMesh t = one_block();
  const std::string dir = scratch_dir();
  io::write_mesh(dir + "/full.msh", t.db, t.model);
  const std::string text = read_all(dir + "/full.msh");
  write_file(dir + "/cut.msh", text.substr(0, text.find("$EndElements")));
  expect_error(dir + "/cut.msh", ErrorCode::ParseError, "$EndElements");
}

TEST(ReadErrors, MshBadNumberNamesTheLine) {
  const std::string path = scratch_dir() + "/bad.msh";
  write_file(path,
             "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 1 1 1\n3 1 0 1\n1\n0 zero 0\n"
             "$EndNodes\n");
  expect_error(path, ErrorCode::ParseError, "line 8");
}

TEST(ReadErrors, BinaryMshOfTheOtherByteOrder) {
  const std::string path = scratch_dir() + "/bin.msh";
  static const char kText[] = "$MeshFormat\n4.1 1 8\n\x00\x00\x00\x01\n$EndMeshFormat\n";
  write_file(path, std::string(kText, sizeof kText - 1));
  expect_error(path, ErrorCode::NotSupported, "other byte order");
}

TEST(ReadErrors, BinaryMshCountBeyondTheFile) {
  const std::string path = scratch_dir() + "/count.msh";
  static const char kHead[] = "$MeshFormat\n4.1 1 8\n\x01\x00\x00\x00\n$EndMeshFormat\n$Nodes\n";
  std::string text(kHead, sizeof kHead - 1);
  const uint64_t huge = uint64_t{1} << 40;
  text.append(reinterpret_cast<const char*>(&huge), 8);
  text += std::string(24, '\0');
  write_file(path, text);
  expect_error(path, ErrorCode::ParseError, "more than the file holds");
}

TEST(ReadErrors, NotAnExodusFile) {
  const std::string path = scratch_dir() + "/text.exo";
  write_file(path, "this is not netCDF\n");
  expect_error(path, ErrorCode::ParseError, "Exodus");
}

const char* kVtuHead =
    "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" "
    "byte_order=\"LittleEndian\"";

TEST(ReadErrors, CompressedVtu) {
  const std::string path = scratch_dir() + "/z.vtu";
  write_file(path, std::string(kVtuHead) +
                       " compressor=\"vtkZLibDataCompressor\">\n<UnstructuredGrid>\n"
                       "</UnstructuredGrid>\n</VTKFile>\n");
  expect_error(path, ErrorCode::NotSupported, "not supported");
}

TEST(ReadErrors, AppendedVtuOffsetPastTheData) {
  const std::string path = scratch_dir() + "/a.vtu";
  write_file(path, std::string(kVtuHead) +
                       ">\n<UnstructuredGrid>\n<Piece NumberOfPoints=\"1\" NumberOfCells=\"0\">\n"
                       "<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" "
                       "format=\"appended\" offset=\"0\"/></Points>\n</Piece>\n"
                       "</UnstructuredGrid>\n<AppendedData encoding=\"raw\">_xxxx</AppendedData>\n"
                       "</VTKFile>\n");
  expect_error(path, ErrorCode::ParseError, "does not fit");
}

TEST(ReadErrors, Base64AppendedVtu) {
  const std::string path = scratch_dir() + "/b.vtu";
  write_file(path, std::string(kVtuHead) +
                       ">\n<UnstructuredGrid>\n</UnstructuredGrid>\n"
                       "<AppendedData encoding=\"base64\">_AAAA</AppendedData>\n</VTKFile>\n");
  expect_error(path, ErrorCode::NotSupported, "not raw");
}

TEST(ReadErrors, MalformedVtuXml) {
  const std::string path = scratch_dir() + "/x.vtu";
  write_file(path, std::string(kVtuHead) + ">\n<UnstructuredGrid>\n<Piece>\n</VTKFile>\n");
  expect_error(path, ErrorCode::ParseError, "line");
}

TEST(ReadErrors, VtuConnectivityOutOfRange) {
  const std::string path = scratch_dir() + "/r.vtu";
  write_file(path, std::string(kVtuHead) +
                       ">\n<UnstructuredGrid>\n<Piece NumberOfPoints=\"3\" NumberOfCells=\"1\">\n"
                       "<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" "
                       "format=\"ascii\">0 0 0 1 0 0 0 1 0</DataArray></Points>\n<Cells>\n"
                       "<DataArray type=\"Int32\" Name=\"connectivity\">0 1 7</DataArray>\n"
                       "<DataArray type=\"Int32\" Name=\"offsets\">3</DataArray>\n"
                       "<DataArray type=\"UInt8\" Name=\"types\">5</DataArray>\n</Cells>\n"
                       "</Piece>\n</UnstructuredGrid>\n</VTKFile>\n");
  expect_error(path, ErrorCode::ParseError, "point 7");
}

}  // namespace
}  // namespace cooperage::test

namespace cooperage::test {
namespace {

// libFuzzer (scripts/fuzz.sh mesh_read, 2026-12-02): a .vtu whose XML
// declaration came after other text gave an error of
// over 1,000 characters, because tinyxml2 quotes the offending text whole.
TEST(ReadErrors, VtuXmlErrorIsClipped) {
  const std::string path = scratch_dir() + "/long.vtu";
  std::string lines;
  for (int i = 0; i < 200; ++i) lines += "  0.5 0.25 1\n";
  // A declaration after other text: tinyxml2 quotes all of it (1,032 characters before the fix).
  write_file(path, "text\n<?xml vers 1\n" + lines + "?>\n<VTKFile/>\n");
  try {
    io::read_mesh_file(path);
    ADD_FAILURE() << "no error";
  } catch (const MeshingError& e) {
    EXPECT_EQ(e.code(), ErrorCode::ParseError) << e.what();
    EXPECT_NE(std::string(e.what()).find("XML error"), std::string::npos) << e.what();
    EXPECT_LT(std::string(e.what()).size(), 300u) << e.what();
  }
}

// libFuzzer (CI's fuzz run, 2026-12-02): file text quoted in an error came
// whole -- a 9 KB "type" attribute of a DataArray, a long token where a .msh
// number belongs. Both are clipped now.
TEST(ReadErrors, FileTextQuotedInAnErrorIsClipped) {
  const std::string dir = scratch_dir();
  const std::string junk(5000, 'x');
  write_file(dir + "/type.vtu",
             "<VTKFile type=\"UnstructuredGrid\"><UnstructuredGrid><Piece NumberOfPoints=\"1\" "
             "NumberOfCells=\"0\"><Points><DataArray type=\"" +
                 junk +
                 "\" NumberOfComponents=\"3\">0 0 0</DataArray></Points></Piece>"
                 "</UnstructuredGrid></VTKFile>\n");
  write_file(dir + "/token.msh", "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n" + junk + "\n");
  write_file(dir + "/version.msh", "$MeshFormat\n" + junk + " 0 8\n$EndMeshFormat\n");
  for (const char* name : {"/type.vtu", "/token.msh", "/version.msh"}) {
    try {
      io::read_mesh_file(dir + name);
      ADD_FAILURE() << "no error for " << name;
    } catch (const MeshingError& e) {
      EXPECT_NE(std::string(e.what()).find("xxxx"), std::string::npos) << e.what();
      EXPECT_LT(std::string(e.what()).size(), dir.size() + 200) << e.what();
    }
  }
}

}  // namespace
}  // namespace cooperage::test
