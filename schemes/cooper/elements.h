// The element kinds cooper sweeps (journal `elements=`). Blacker 1996,
// abstract: hexahedra, "or a wedge/hexahedral element mix if desired ... by
// simply allowing triangle and/or mixed triangle/quadrilateral cap meshes".
// The kind decides how caps are meshed; the sweep makes a hex from every cap
// quad and a wedge from every cap triangle, and side faces stay quads.
#pragma once

namespace cooperage::cooper {

enum class Elements {
  Hex,    ///< quad caps (map / submap / pave) swept into hexes
  Wedge,  ///< triangle caps ("tri") swept into wedges
  /// map / submap caps where they reach a scaled Jacobian of at least
  /// kMixedMinQuadQuality, else "quad_dominant" caps (pave's quads, those
  /// below kMixedMinQuadQuality split into two triangles), swept into hexes
  /// and wedges
  Mixed,
};

/// Mixed mode: the quality a cap quad must reach (map / submap scores are
/// the scaled Jacobian they reach; quad_dominant splits quads below it).
inline constexpr double kMixedMinQuadQuality = 0.5;

}  // namespace cooperage::cooper
