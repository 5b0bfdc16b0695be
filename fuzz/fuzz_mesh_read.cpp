// Fuzz target: the mesh file readers (framework/io/read) on any bytes. The
// format is guessed from the content as a user's extension would name it:
// netCDF/HDF5 bytes go through the netCDF header check in this process (the
// libexodus read itself runs in a child process, see exodus_reader.cpp, and
// is covered by scripts/fuzz_campaign.py); Gmsh and VTK text through their
// readers, from a temporary file.
#include "framework/core/error.h"
#include "framework/io/read/netcdf_header.h"
#include "framework/io/read/read_mesh_file.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <unistd.h>

namespace {

std::string temp_file(const char* extension) {
  return "/tmp/cooperage-fuzz-" + std::to_string(::getpid()) + extension;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  try {
    if (bytes.rfind("CDF", 0) == 0 || bytes.rfind("\x89HDF", 0) == 0) {
      (void)cooperage::io::detail::check_netcdf_bytes("fuzz.exo", bytes, size);
      return 0;
    }
    const bool vtu = bytes.find("<VTKFile") != std::string::npos;
    const std::string path = temp_file(vtu ? ".vtu" : ".msh");
    std::ofstream(path, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(size));
    try {
      const cooperage::io::MeshFile f = cooperage::io::read_mesh_file(path);
      // What a reader returns is usable: every index names a node.
      for (const auto& b : f.blocks)
        for (int n : b.connectivity)
          if (n < 0 || static_cast<std::size_t>(n) >= f.coords.size()) std::abort();
    } catch (...) {
      std::remove(path.c_str());
      throw;
    }
    std::remove(path.c_str());
  } catch (const cooperage::MeshingError& e) {
    if (std::strlen(e.what()) > 1000) std::abort();
  }
  return 0;
}
