// Fuzz target: the STEP/BREP import path (framework/geometry/occ/import.cpp)
// on any bytes, as `cooperage info` reads a file: import, then build and
// validate the model. The CAD kernel runs in a child process; this process
// must only ever see a model or a MeshingError, however the kernel fails.
#include "framework/core/error.h"
#include "framework/geometry/occ/workbench.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <unistd.h>

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  // A hang in the kernel must end well inside libFuzzer's -timeout.
  ::setenv("COOPERAGE_CAD_TIMEOUT", "10", 0);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  const bool brep = bytes.find("CASCADE Topology") != std::string::npos;
  const std::string path =
      "/tmp/cooperage-fuzz-" + std::to_string(::getpid()) + (brep ? ".brep" : ".step");
  std::ofstream(path, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(size));
  try {
    (void)cooperage::occ::load_model(path);
  } catch (const cooperage::MeshingError& e) {
    if (e.code() == cooperage::ErrorCode::Internal) {
      std::fprintf(stderr, "internal error: %s\n", e.what());
      std::abort();
    }
  }
  std::remove(path.c_str());
  return 0;
}
