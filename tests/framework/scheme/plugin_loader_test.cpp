// Loading plug-ins: the example plug-in registers its scheme with its
// library as origin; every broken library is refused with a message naming
// it and the reason, and a refused library registers nothing.
#include "framework/scheme/plugin_loader.h"

#include "framework/core/error.h"
#include "framework/scheme/plugin.h"
#include "schemes/builtin_schemes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace cooperage::scheme {
namespace {

namespace fs = std::filesystem;

const std::string kTriPrimitive = COOPERAGE_PLUGIN_TRIPRIMITIVE;

// The message of the MeshingError `load` throws ("" when it does not throw).
template <class Load>
std::string error_of(Load load) {
  try {
    load();
  } catch (const MeshingError& e) {
    EXPECT_EQ(e.code(), ErrorCode::InvalidInput);
    return e.message();
  }
  return {};
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(PluginLoader, TheExamplePluginAddsItsSchemeWithTheLibraryAsOrigin) {
  Registry r;
  register_builtin_schemes(r);
  load_plugin(r, kTriPrimitive);
  const SurfaceScheme* s = r.surface_scheme("triprimitive");
  ASSERT_NE(s, nullptr);
  EXPECT_EQ(r.origin(2, "triprimitive"), fs::canonical(kTriPrimitive).string());
  EXPECT_EQ(r.origin(2, "pave"), Registry::kBuiltIn);
  EXPECT_TRUE(serves(s->serves(), Role::QuadCap));
  // After the built-ins, so they keep winning ties.
  EXPECT_EQ(r.names(2).back(), "triprimitive");
  // A second load of the same library (another path to it, too) is a no-op.
  load_plugin(r, kTriPrimitive);
  load_plugin(
      r,
      (fs::path(kTriPrimitive).parent_path() / "." / fs::path(kTriPrimitive).filename()).string());
  EXPECT_EQ(r.surface_schemes().size(), r.names(2).size());
  const std::vector<std::string> names = r.names(2);
  EXPECT_EQ(std::count(names.begin(), names.end(), "triprimitive"), 1);
}

TEST(PluginLoader, AMissingFileIsNamed) {
  Registry r;
  const std::string m = error_of([&] { load_plugin(r, "/no/such/libplugin.so", "--plugin"); });
  EXPECT_EQ(m, "plug-in /no/such/libplugin.so (--plugin): no such file");
}

TEST(PluginLoader, AFileThatIsNoLibraryGivesTheLoadersReason) {
  const fs::path text = fs::temp_directory_path() / "cooperage-not-a-library.so";
  std::ofstream(text) << "not a shared library\n";
  Registry r;
  const std::string m = error_of([&] { load_plugin(r, text.string()); });
  fs::remove(text);
  EXPECT_TRUE(contains(m, "cooperage-not-a-library.so: cannot be loaded: ")) << m;
}

TEST(PluginLoader, ALibraryWithoutTheAbiSymbolIsNoPlugin) {
  Registry r;
  const std::string m = error_of([&] { load_plugin(r, COOPERAGE_PLUGIN_NO_ABI); });
  EXPECT_TRUE(contains(m, fs::canonical(COOPERAGE_PLUGIN_NO_ABI).string())) << m;
  EXPECT_TRUE(contains(m, "is not a Cooperage plug-in: it has no cooperage_plugin_abi()")) << m;
}

TEST(PluginLoader, AnotherAbiVersionIsRefusedBeforeRegistration) {
  Registry r;
  // Its cooperage_register aborts: reaching it would end this test program.
  const std::string m = error_of([&] { load_plugin(r, COOPERAGE_PLUGIN_WRONG_ABI, "job.xml:3"); });
  EXPECT_TRUE(contains(m,
                       "(job.xml:3): was built for plug-in ABI version 999, but this "
                       "cooperage loads version " +
                           std::to_string(kPluginAbiVersion)))
      << m;
  EXPECT_TRUE(r.names(2).empty());
}

TEST(PluginLoader, ALibraryWithoutTheRegistrationFunctionIsRefused) {
  Registry r;
  const std::string m = error_of([&] { load_plugin(r, COOPERAGE_PLUGIN_NO_REGISTER); });
  EXPECT_TRUE(contains(m, "has no cooperage_register(cooperage::scheme::Registry&) function")) << m;
}

TEST(PluginLoader, ADuplicateSchemeNameNamesTheLibraryAndTheBuiltIn) {
  Registry r;
  register_builtin_schemes(r);
  const std::string lib = fs::canonical(COOPERAGE_PLUGIN_DUPLICATE).string();
  const std::string m = error_of([&] { load_plugin(r, COOPERAGE_PLUGIN_DUPLICATE); });
  EXPECT_EQ(m, "plug-in " + lib + ": surface scheme \"pave\" from " + lib +
                   " is already registered (built in)");
  EXPECT_EQ(r.origin(2, "pave"), Registry::kBuiltIn);
}

TEST(PluginPath, DirectoriesExpandToTheirLibrariesInNameOrder) {
  const fs::path dir = fs::temp_directory_path() / "cooperage-plugin-path-test";
  fs::remove_all(dir);
  fs::create_directories(dir / "sub.so");
  for (const char* f : {"b.so", "a.so", "readme.txt"}) std::ofstream(dir / f) << "x";
  const auto libs = plugin_path_libraries("::" + dir.string() + ":" + kTriPrimitive + ":");
  fs::remove_all(dir);
  EXPECT_EQ(libs, (std::vector<std::string>{(dir / "a.so").string(), (dir / "b.so").string(),
                                            kTriPrimitive}));
  const std::string m = error_of([] { plugin_path_libraries("/no/such/dir"); });
  EXPECT_EQ(m, "COOPERAGE_PLUGIN_PATH: \"/no/such/dir\" does not exist");
}

TEST(PluginPath, TheVariableLoadsItsLibraries) {
  ASSERT_EQ(::setenv(kPluginPathVariable, kTriPrimitive.c_str(), 1), 0);
  Registry with;
  load_plugin_path(with);
  ::unsetenv(kPluginPathVariable);
  EXPECT_NE(with.surface_scheme("triprimitive"), nullptr);
  Registry without;
  load_plugin_path(without);
  EXPECT_EQ(without.surface_scheme("triprimitive"), nullptr);
}

}  // namespace
}  // namespace cooperage::scheme
