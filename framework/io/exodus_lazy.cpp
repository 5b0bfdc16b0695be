#include "framework/io/exodus_lazy.h"

#include "framework/core/error.h"

#include <dlfcn.h>

#include <string>

namespace cooperage::io::exodus_lazy {
namespace {

// The library's run-time name, then the file CMake found (for a library
// outside the loader's search path).
const char* const kCandidates[] = {"libexoIIv2c.so.5", COOPERAGE_EXODUS_LIBRARY_FILE};

Api load() {
  void* lib = nullptr;
  std::string why;
  for (const char* name : kCandidates) {
    lib = dlopen(name, RTLD_NOW | RTLD_LOCAL);
    if (lib) break;
    const char* e = dlerror();
    why += std::string(why.empty() ? "" : "; ") + (e ? e : name);
  }
  if (!lib) {
    throw MeshingError(ErrorCode::Internal,
                       "cannot load the Exodus II library (Debian package libexodusii5): " + why);
  }
  Api api;
#define COOPERAGE_EXODUS_RESOLVE(f)                                                    \
  api.f = reinterpret_cast<decltype(api.f)>(dlsym(lib, #f));                           \
  if (!api.f) {                                                                        \
    throw MeshingError(ErrorCode::Internal,                                            \
                       std::string("the Exodus II library has no function " #f ": ") + \
                           (dlerror() ? "not exported" : "null"));                     \
  }
  COOPERAGE_EXODUS_FUNCTIONS(COOPERAGE_EXODUS_RESOLVE)
#undef COOPERAGE_EXODUS_RESOLVE
  return api;  // the library stays loaded for the life of the process
}

}  // namespace

const Api& api() {
  static const Api loaded = load();
  return loaded;
}

}  // namespace cooperage::io::exodus_lazy
