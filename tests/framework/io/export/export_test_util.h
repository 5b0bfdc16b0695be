// Scratch directories and the Python read-back driver for the exporter tests.
#pragma once

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace cooperage::test {

/// A fresh directory under the gtest temp dir, removed at program exit.
inline std::string scratch_dir() {
  struct Registry {
    std::vector<std::string> dirs;
    ~Registry() {
      std::error_code ec;
      for (const auto& d : dirs) std::filesystem::remove_all(d, ec);
    }
  };
  static Registry registry;
  std::string tmpl = ::testing::TempDir() + "cooperage_export_XXXXXX";
  std::vector<char> buf(tmpl.begin(), tmpl.end());
  buf.push_back('\0');
  const char* d = mkdtemp(buf.data());
  if (!d) return std::string();
  registry.dirs.emplace_back(d);
  return registry.dirs.back();
}

inline bool file_exists(const std::string& p) { return std::ifstream(p).good(); }

inline std::string read_all(const std::string& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

/// True when Debian's python has meshio and gmsh.
inline bool have_meshio() {
  const std::string cmd =
      std::string(COOPERAGE_DEBIAN_PYTHON) + " -c 'import meshio, numpy' > /dev/null 2>&1";
  return std::system(cmd.c_str()) == 0;
}

/// Runs `script` (readback.py, or groups_readback.py) of this folder on
/// `file`; returns its output lines split in words. Fails the test (and
/// returns empty) when the script fails.
inline std::vector<std::vector<std::string>> readback(const std::string& file,
                                                      const std::string& extra = "",
                                                      const std::string& script = "readback.py") {
  const std::string out = file + ".readback.txt";
  const std::string cmd = std::string(COOPERAGE_DEBIAN_PYTHON) + " " + COOPERAGE_SOURCE_DIR +
                          "/tests/framework/io/export/" + script + " '" + file + "' " + extra +
                          " > '" + out + "' 2>&1";
  const int rc = std::system(cmd.c_str());
  std::vector<std::vector<std::string>> lines;
  std::istringstream in(read_all(out));
  for (std::string line; std::getline(in, line);) {
    std::istringstream ls(line);
    std::vector<std::string> words;
    for (std::string w; ls >> w;) words.push_back(w);
    if (!words.empty()) lines.push_back(words);
  }
  EXPECT_EQ(rc, 0) << cmd << "\n" << read_all(out);
  return lines;
}

/// Lines whose first word is `key`.
inline std::vector<std::vector<std::string>> with_key(
    const std::vector<std::vector<std::string>>& lines, const std::string& key) {
  std::vector<std::vector<std::string>> r;
  for (const auto& l : lines) {
    if (l[0] == key) r.push_back(l);
  }
  return r;
}

/// The words after `key` on its first line (empty when missing).
inline std::vector<std::string> value(const std::vector<std::vector<std::string>>& lines,
                                      const std::string& key) {
  for (const auto& l : lines) {
    if (l[0] == key) return std::vector<std::string>(l.begin() + 1, l.end());
  }
  ADD_FAILURE() << "read-back has no " << key;
  return {};
}

/// True when Debian's python also has netCDF4 (meshio's Exodus reader needs it).
inline bool have_netcdf4() {
  const std::string cmd =
      std::string(COOPERAGE_DEBIAN_PYTHON) + " -c 'import netCDF4' > /dev/null 2>&1";
  return std::system(cmd.c_str()) == 0;
}

#define COOPERAGE_REQUIRE_MESHIO()                             \
  do {                                                         \
    if (!::cooperage::test::have_meshio())                     \
      GTEST_SKIP() << COOPERAGE_DEBIAN_PYTHON                  \
                   << " lacks meshio/numpy: python read-back " \
                      "skipped (apt install python3-meshio)";  \
  } while (0)

}  // namespace cooperage::test
