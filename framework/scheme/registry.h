// The schemes known to a run, by dimension and name, each with where it came
// from: built in, or the plug-in library that registered it
// (plugin_loader.h). Volume schemes ask the registry for the surface schemes
// that serve a role (cooper's caps and sides, the volume map's faces;
// scheme::Role) and rank them by their applicable() score, so a plug-in's
// scheme competes with the built-in ones; schemes never include each other.
// register_builtin_schemes() (schemes/builtin_schemes.h) adds the built-ins.
#pragma once

#include "framework/scheme/scheme.h"

#include <memory>
#include <set>
#include <string>
#include <vector>

namespace cooperage::scheme {

class Registry {
 public:
  /// The origin of the schemes compiled into cooperage.
  static constexpr const char* kBuiltIn = "built in";

  Registry() = default;
  // Schemes keep pointers to their registry (cooper asks it for its cap and
  // side schemes), so a registry stays where it was built.
  Registry(const Registry&) = delete;
  Registry& operator=(const Registry&) = delete;

  /// Adds a scheme with the current origin (kBuiltIn outside an
  /// OriginScope). Throws MeshingError(InvalidInput) when a scheme of that
  /// dimension already has the name (naming both origins), or for a name
  /// that is empty, "auto", or has characters other than letters, digits,
  /// '_', '-' and '.'.
  void add(std::unique_ptr<SurfaceScheme> scheme);
  void add(std::unique_ptr<VolumeScheme> scheme);

  /// The scheme of that name, or null.
  const SurfaceScheme* surface_scheme(std::string_view name) const;
  const VolumeScheme* volume_scheme(std::string_view name) const;

  /// In registration order (the built-ins' order of preference, then the
  /// plug-ins in load order).
  std::vector<const SurfaceScheme*> surface_schemes() const;
  std::vector<const VolumeScheme*> volume_schemes() const;
  /// The surface schemes that serve `role` (SurfaceScheme::serves()), in
  /// registration order.
  std::vector<const SurfaceScheme*> surface_schemes(Role role) const;

  /// The names of the schemes of dimension `dim` (2 or 3), in registration order.
  std::vector<std::string> names(int dim) const;
  /// Where the scheme of dimension `dim` named `name` came from: kBuiltIn or
  /// a plug-in library's absolute path; "" when there is none.
  std::string origin(int dim, std::string_view name) const;

  /// Attributes the schemes added while it lives to `origin` (the plug-in
  /// loader passes the library's path) and records the library as loaded.
  class OriginScope {
   public:
    OriginScope(Registry& registry, std::string origin);
    ~OriginScope();
    OriginScope(const OriginScope&) = delete;
    OriginScope& operator=(const OriginScope&) = delete;

   private:
    Registry& registry_;
    std::string previous_;
  };
  /// Whether a plug-in library (absolute path) was loaded into this registry.
  bool has_library(const std::string& path) const { return libraries_.count(path) > 0; }

 private:
  template <class Scheme>
  struct Entry {
    std::unique_ptr<Scheme> scheme;
    std::string origin;
  };
  void check_name(int dim, std::string_view name) const;

  std::vector<Entry<SurfaceScheme>> surface_;
  std::vector<Entry<VolumeScheme>> volume_;
  std::string origin_ = kBuiltIn;
  std::set<std::string> libraries_;
};

/// The applicable surface scheme serving a role with the best score on one
/// surface (ties: registration order), as volume schemes pick their cap and
/// side schemes.
struct RoleChoice {
  const SurfaceScheme* scheme = nullptr;  ///< null: none applies
  Applicability applicability;            ///< the chosen scheme's
  /// Every rejected candidate's reason, "pave: ...; tri_fan: ...", or "no
  /// registered scheme serves <role>" when there is no candidate.
  std::string reasons;
};
RoleChoice best_surface_scheme(const Registry& registry, Role role, const SurfaceView& view);

}  // namespace cooperage::scheme
