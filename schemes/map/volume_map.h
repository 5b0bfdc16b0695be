// The volume map scheme "map": a topological hexahedron (one shell of 6
// mappable surfaces whose logical sides pair up into 12 block edges and 8
// corners) meshed by 3D transfinite interpolation from its surface meshes.
#pragma once

#include "framework/scheme/scheme.h"

#include <memory>

namespace cooperage::map {

class VolumeMap final : public scheme::VolumeScheme {
 public:
  std::string_view name() const override { return "map"; }
  /// One shell of exactly 6 map-applicable surfaces, every logical side in
  /// exactly 2 of them, 8 corner vertices each in 3. Score: the worst face's.
  scheme::Applicability applicable(const scheme::VolumeView& view) const override;
  /// Each face's map constraints; together they make the 4 parallel block
  /// edges of each direction equal.
  void constrain(const scheme::VolumeView& view,
                 intervals::IntervalProblem& problem) const override;
  /// Every surface -> "map".
  scheme::SurfaceRoles roles(const scheme::VolumeView& view) const override;
  /// Recovers the boundary lattice from the surface quads, fills the interior
  /// by 3D TFI, emits hexes in Exodus order with positive Jacobian. Throws
  /// MeshingError(MeshingFailed) when the lattice cannot be recovered or a hex
  /// has a non-positive scaled Jacobian.
  scheme::EntityMesh mesh(const scheme::VolumeView& view,
                          const scheme::Settings& params) const override;
};

std::unique_ptr<scheme::VolumeScheme> make_volume_map();

}  // namespace cooperage::map
