#include "framework/core/lazy_module.h"

#include "framework/core/error.h"

#include <dlfcn.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

namespace cooperage {
namespace {

// RTLD_DEEPBIND: a module's toolkits look up symbols among themselves
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

std::vector<std::string> candidates(const char* file) {
  namespace fs = std::filesystem;
  std::vector<std::string> out;
  if (const char* dir = std::getenv("COOPERAGE_MODULE_DIR"); dir && *dir)
    out.push_back((fs::path(dir) / file).string());
  static const int anchor = 0;  // any object of the binary holding this code
  Dl_info info{};
  if (dladdr(&anchor, &info) != 0 && info.dli_fname != nullptr)
    out.push_back((fs::path(info.dli_fname).parent_path() / file).string());
#ifdef COOPERAGE_MODULE_BUILD_DIR
  out.push_back((fs::path(COOPERAGE_MODULE_BUILD_DIR) / file).string());
#endif
  out.push_back(file);
  std::vector<std::string> unique;
  for (const std::string& c : out)
    if (std::find(unique.begin(), unique.end(), c) == unique.end()) unique.push_back(c);
  return unique;
}

}  // namespace

void* open_module(const char* file, const char* abi_symbol, int abi) {
  std::string tried;
  for (const std::string& path : candidates(file)) {
    const auto note = [&](const std::string& why) {
      tried += (tried.empty() ? "" : ", ") + path + " (" + why + ")";
    };
    if (path.find('/') != std::string::npos && !std::filesystem::exists(path)) {
      note("absent");
      continue;
    }
    void* handle = dlopen(path.c_str(), RTLD_LAZY | RTLD_LOCAL | kDeepBind);
    if (handle == nullptr) {
      const char* why = dlerror();
      note(why ? why : "not loaded");
      continue;
    }
    using AbiFn = int (*)();
    const auto version = reinterpret_cast<AbiFn>(dlsym(handle, abi_symbol));
    if (version == nullptr || version() != abi) {
      note("not this version's module");
      continue;
    }
    return handle;
  }
  throw MeshingError(ErrorCode::Internal, std::string("the module ") + file +
                                              " could not be loaded; looked in: " + tried +
                                              " (set COOPERAGE_MODULE_DIR to its directory)");
}

}  // namespace cooperage
