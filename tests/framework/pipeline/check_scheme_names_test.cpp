// Scheme pins are checked against the registry of the run (built-in and
// plug-in schemes), not against a fixed list: an unknown name is an error
// naming the journal line, the closest registered name and all of them.
#include "framework/core/error.h"
#include "framework/pipeline/check_settings.h"
#include "schemes/builtin_schemes.h"

#include <gtest/gtest.h>

namespace cooperage::pipeline {
namespace {

io::MeshSettings pins(const std::string& surface, const std::string& volume) {
  io::MeshSettings s;
  io::SurfaceSetting f;
  f.id = 1;
  f.scheme = surface;
  f.where = {"job.xml", 7, "surface"};
  s.surfaces.push_back(f);
  io::VolumeSetting v;
  v.id = 1;
  v.scheme = volume;
  v.where = {"job.xml", 8, "volume"};
  s.volumes.push_back(v);
  return s;
}

std::string error_of(const io::MeshSettings& settings, const scheme::Registry& registry) {
  try {
    check_scheme_names(settings, registry);
  } catch (const MeshingError& e) {
    EXPECT_EQ(e.code(), ErrorCode::InvalidInput);
    return e.message();
  }
  return {};
}

TEST(CheckSchemeNames, RegisteredNamesAndAutoPass) {
  scheme::Registry r;
  register_builtin_schemes(r);
  EXPECT_EQ(error_of(pins("auto", "auto"), r), "");
  EXPECT_EQ(error_of(pins("submap", "cooper"), r), "");
  EXPECT_EQ(error_of(pins("quad_dominant", "map"), r), "");
}

TEST(CheckSchemeNames, ATypoNamesTheLineTheClosestNameAndEveryName) {
  scheme::Registry r;
  register_builtin_schemes(r);
  const std::string m = error_of(pins("subamp", "auto"), r);
  EXPECT_NE(m.find("job.xml:7: <surface>: no surface scheme \"subamp\" is registered"),
            std::string::npos)
      << m;
  EXPECT_NE(m.find("\"submap\""), std::string::npos) << m;
  for (const std::string& name : r.names(2)) EXPECT_NE(m.find(name), std::string::npos) << m;
}

TEST(CheckSchemeNames, ADimensionsNamesAreItsOwn) {
  scheme::Registry r;
  register_builtin_schemes(r);
  // cooper is a volume scheme, pave a surface scheme.
  const std::string surface = error_of(pins("cooper", "auto"), r);
  EXPECT_NE(surface.find("no surface scheme \"cooper\""), std::string::npos) << surface;
  const std::string volume = error_of(pins("auto", "pave"), r);
  EXPECT_NE(volume.find("job.xml:8: <volume>: no volume scheme \"pave\""), std::string::npos)
      << volume;
}

TEST(CheckSchemeNames, AnEmptyRegistryRejectsEveryPin) {
  const scheme::Registry r;
  EXPECT_NE(error_of(pins("map", "auto"), r).find("no surface scheme \"map\""), std::string::npos);
}

}  // namespace
}  // namespace cooperage::pipeline
