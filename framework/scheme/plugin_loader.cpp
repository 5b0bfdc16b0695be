#include "framework/scheme/plugin_loader.h"

#include "framework/core/error.h"
#include "framework/scheme/plugin.h"

#include <dlfcn.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <sstream>

namespace cooperage::scheme {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(const std::string& library, const std::string& what,
                       const std::string& reason) {
  throw MeshingError(
      ErrorCode::InvalidInput,
      "plug-in " + library + (what.empty() ? "" : " (" + what + ")") + ": " + reason);
}

}  // namespace

void load_plugin(Registry& registry, const std::string& path, const std::string& what) {
  std::error_code ec;
  if (!fs::exists(path, ec)) fail(path, what, "no such file");
  if (fs::is_directory(path, ec)) fail(path, what, "is a directory, not a library");
  const std::string library = fs::canonical(path, ec).string();
  if (ec) fail(path, what, "cannot resolve the path (" + ec.message() + ")");
  if (registry.has_library(library)) return;
  // RTLD_NOW: an unresolved symbol is an error here, not a crash while meshing.
  void* handle = dlopen(library.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    const char* reason = dlerror();
    fail(library, what, std::string("cannot be loaded: ") + (reason ? reason : "unknown reason"));
  }
  // The handle is never closed: the registry's schemes run the library's code.
  auto abi = reinterpret_cast<PluginAbiFunction>(dlsym(handle, kPluginAbiSymbol));
  if (!abi) {
    fail(library, what,
         std::string("is not a Cooperage plug-in: it has no ") + kPluginAbiSymbol +
             "() function (define it with COOPERAGE_PLUGIN_ABI from framework/scheme/plugin.h)");
  }
  const int version = abi();
  if (version != kPluginAbiVersion) {
    fail(library, what,
         "was built for plug-in ABI version " + std::to_string(version) +
             ", but this cooperage "
             "loads version " +
             std::to_string(kPluginAbiVersion) + "; rebuild the plug-in against this Cooperage");
  }
  auto register_schemes =
      reinterpret_cast<PluginRegisterFunction>(dlsym(handle, kPluginRegisterSymbol));
  if (!register_schemes) {
    fail(library, what,
         std::string("has no ") + kPluginRegisterSymbol +
             "(cooperage::scheme::Registry&) function (declare it extern \"C\")");
  }
  const Registry::OriginScope origin(registry, library);
  try {
    register_schemes(registry);
  } catch (const MeshingError& e) {
    fail(library, what, e.message());
  } catch (const std::exception& e) {
    fail(library, what, std::string("registration failed: ") + e.what());
  }
}

std::vector<std::string> plugin_path_libraries(const std::string& value) {
  std::vector<std::string> out;
  std::stringstream entries(value);
  std::string entry;
  while (std::getline(entries, entry, ':')) {
    if (entry.empty()) continue;
    std::error_code ec;
    if (!fs::exists(entry, ec)) {
      throw MeshingError(ErrorCode::InvalidInput,
                         std::string(kPluginPathVariable) + ": \"" + entry + "\" does not exist");
    }
    if (!fs::is_directory(entry, ec)) {
      out.push_back(entry);
      continue;
    }
    std::vector<std::string> found;
    for (const fs::directory_entry& f : fs::directory_iterator(entry, ec)) {
      if (f.path().extension() == ".so" && !f.is_directory()) found.push_back(f.path().string());
    }
    std::sort(found.begin(), found.end());
    out.insert(out.end(), found.begin(), found.end());
  }
  return out;
}

void load_plugin_path(Registry& registry) {
  const char* value = std::getenv(kPluginPathVariable);
  if (!value) return;
  for (const std::string& library : plugin_path_libraries(value)) {
    load_plugin(registry, library, kPluginPathVariable);
  }
}

}  // namespace cooperage::scheme
