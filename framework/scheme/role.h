// The roles a volume scheme gives the surface schemes of its faces (a cap,
// a side), which surface schemes declare they serve. Volume schemes ask the
// registry by role, never by name, so a plug-in scheme can serve them too.
#pragma once

#include <string>

namespace cooperage::scheme {

/// What a volume scheme may ask of a surface scheme (SurfaceScheme::serves()),
/// as flags. A volume scheme asks the registry for the schemes serving the
/// role it needs (Registry::surface_schemes(Role), best_surface_scheme()),
/// so a plug-in scheme that declares a role competes for it on its score.
enum class Role : unsigned {
  None = 0,
  /// An all-quad mesh of the face, any connectivity: cooper's source caps
  /// in hex mode (swept to the target).
  QuadCap = 1u << 0,
  /// All triangles: the source caps of wedge sweeps (elements="wedge").
  TriCap = 1u << 1,
  /// Quads and triangles: the source caps of mixed sweeps. An all-quad
  /// scheme (one that also serves QuadCap) is taken for it only where its
  /// score reaches cooper's kMixedMinQuadQuality.
  MixedCap = 1u << 2,
  /// A structured mesh whose interval constraints are submap's per-direction
  /// sums, so that its rows run along the sweep. Declared by submap; cooper's
  /// side lattice still asks for submap by name (its rows are submap's).
  SweepSide = 1u << 3,
  /// One logically rectangular grid, opposite sides equal. Declared by map;
  /// the volume map still gives its six faces "map" by name.
  MappedFace = 1u << 4,
};
constexpr Role operator|(Role a, Role b) {
  return static_cast<Role>(static_cast<unsigned>(a) | static_cast<unsigned>(b));
}
/// Whether the flags `set` include every flag of `role`.
constexpr bool serves(Role set, Role role) {
  return role != Role::None &&
         (static_cast<unsigned>(set) & static_cast<unsigned>(role)) == static_cast<unsigned>(role);
}
/// "quad cap", "tri cap", ...; flags joined by ", " ("none" for None).
std::string to_string(Role roles);

}  // namespace cooperage::scheme
