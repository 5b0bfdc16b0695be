// The schemes known to a run, by name. Schemes ask the registry for each
// other by name (cooper asks for "submap" and "pave"); they never include
// each other. register_builtin_schemes() (schemes/builtin_schemes.h) fills it.
#pragma once

#include "framework/scheme/scheme.h"

#include <memory>
#include <string>
#include <vector>

namespace cooperage::scheme {

class Registry {
 public:
  Registry() = default;
  // Schemes keep pointers to their registry (cooper asks it for submap and
  // pave), so a registry stays where it was built.
  Registry(const Registry&) = delete;
  Registry& operator=(const Registry&) = delete;

  /// Adds a scheme; throws MeshingError(InvalidInput) if the name is taken.
  void add(std::unique_ptr<SurfaceScheme> scheme);
  void add(std::unique_ptr<VolumeScheme> scheme);

  /// The scheme of that name, or null.
  const SurfaceScheme* surface_scheme(std::string_view name) const;
  const VolumeScheme* volume_scheme(std::string_view name) const;

  /// In registration order (the order of preference of the built-ins).
  std::vector<const SurfaceScheme*> surface_schemes() const;
  std::vector<const VolumeScheme*> volume_schemes() const;

 private:
  std::vector<std::unique_ptr<SurfaceScheme>> surface_;
  std::vector<std::unique_ptr<VolumeScheme>> volume_;
};

}  // namespace cooperage::scheme
