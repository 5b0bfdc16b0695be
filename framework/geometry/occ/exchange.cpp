#include "framework/geometry/occ/exchange.h"

#include "framework/core/error.h"

#include <dlfcn.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <vector>

namespace cooperage::occ::exchange {
namespace {

constexpr int kAbi = 1;

// RTLD_DEEPBIND: the module's toolkits look up symbols among themselves
// before the process's 45 libraries. Without it every reference between two
// STEP toolkits walked all of those first, and loading them at the first
// STEP file cost ~55 ms against ~34 ms when they were linked in (a STEP
// run 21 ms slower than before; with it, as fast). Sanitizer runtimes
// refuse the flag, so sanitized builds do without.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
constexpr int kDeepBind = 0;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || \
    __has_feature(memory_sanitizer)
constexpr int kDeepBind = 0;
#else
constexpr int kDeepBind = RTLD_DEEPBIND;
#endif
#else
constexpr int kDeepBind = RTLD_DEEPBIND;
#endif
constexpr const char* kModule = "libcooperage_occ_exchange.so";

using AbiFn = int (*)();
using ReadFn = int (*)(int, const char*, TopoDS_Shape*, Unit*, char*, size_t);
using WriteFn = int (*)(int, const char*, const TopoDS_Shape*, const char*);

struct Api {
  ReadFn read = nullptr;
  WriteFn write = nullptr;
};

// Where the module may be, in order: $COOPERAGE_EXCHANGE_MODULE; beside the
// binary holding this code (the installed or built libcooperage_framework,
// or a test that links the objects); the build tree; the loader's own
// search (rpath, LD_LIBRARY_PATH).
std::vector<std::string> candidates() {
  std::vector<std::string> out;
  if (const char* env = std::getenv("COOPERAGE_EXCHANGE_MODULE"); env && *env) out.push_back(env);
  static const int anchor = 0;  // any object of this binary
  Dl_info info{};
  if (dladdr(&anchor, &info) != 0 && info.dli_fname != nullptr) {
    out.push_back((std::filesystem::path(info.dli_fname).parent_path() / kModule).string());
  }
#ifdef COOPERAGE_EXCHANGE_BUILD_PATH
  out.push_back(COOPERAGE_EXCHANGE_BUILD_PATH);
#endif
  out.push_back(kModule);
  std::vector<std::string> unique;
  for (const std::string& c : out)
    if (std::find(unique.begin(), unique.end(), c) == unique.end()) unique.push_back(c);
  return unique;
}

const Api& api() {
  static Api loaded;
  static std::once_flag once;
  static std::string failure;
  std::call_once(once, [] {
    std::string tried;
    for (const std::string& path : candidates()) {
      if (path.find('/') != std::string::npos && !std::filesystem::exists(path)) {
        tried += (tried.empty() ? "" : ", ") + path + " (absent)";
        continue;
      }
      void* handle = dlopen(path.c_str(), RTLD_LAZY | RTLD_LOCAL | kDeepBind);
      if (handle == nullptr) {
        const char* why = dlerror();
        tried += (tried.empty() ? "" : ", ") + path + " (" + (why ? why : "not loaded") + ")";
        continue;
      }
      auto abi = reinterpret_cast<AbiFn>(dlsym(handle, "cooperage_exchange_abi"));
      auto read = reinterpret_cast<ReadFn>(dlsym(handle, "cooperage_exchange_read"));
      auto write = reinterpret_cast<WriteFn>(dlsym(handle, "cooperage_exchange_write"));
      if (abi == nullptr || read == nullptr || write == nullptr || abi() != kAbi) {
        tried += (tried.empty() ? "" : ", ") + path + " (not this version's module)";
        continue;
      }
      loaded = {read, write};
      return;
    }
    failure = "the STEP/IGES module " + std::string(kModule) +
              " could not be loaded; looked in: " + tried +
              " (set COOPERAGE_EXCHANGE_MODULE to its path)";
  });
  if (loaded.read == nullptr) throw MeshingError(ErrorCode::Internal, failure);
  return loaded;
}

}  // namespace

void load() { api(); }

TopoDS_Shape read(Format format, const std::string& path, Unit& unit) {
  TopoDS_Shape shape;
  char error[256] = {0};
  if (api().read(static_cast<int>(format), path.c_str(), &shape, &unit, error, sizeof error) != 0)
    throw MeshingError(ErrorCode::ParseError, path + ": " + error);
  return shape;
}

bool write(Format format, const std::string& path, const TopoDS_Shape& shape,
           const std::string& unit_name) {
  return api().write(static_cast<int>(format), path.c_str(), &shape, unit_name.c_str()) == 0;
}

}  // namespace cooperage::occ::exchange
