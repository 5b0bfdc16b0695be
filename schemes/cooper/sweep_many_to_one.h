// Meshing a many-to-one volume barrel by barrel (Blacker 1996, sec. 5-6),
// upstream first. Each barrel's upper cap is the mesh of its real cap plus
// the virtual subcaps delivered by the barrels flowing into its hole loops;
// the lower cap has no subcaps, so imprinting is the subtraction of every
// upper subcap from it (sec. 5.2): the subcap boundaries that carry no rib
// (the hole loops) are projected through the barrel and connected by
// interior ribs, which splits the lower cap into matching subcaps. Cap
// stacks (sec. 6.1) are meshed once, from their real top cap, and projected
// through every barrel of the stack with the barrel's least-squares map;
// interior nodes are the two-sided blend of sec. 6.2, elements are formed
// layer by layer per barrel (sec. 6.3).
#pragma once

#include "framework/scheme/polygon_mesher.h"
#include "framework/scheme/scheme.h"
#include "schemes/cooper/classify_barrels.h"
#include "schemes/cooper/imprint_subcaps.h"

namespace cooperage::cooper {

/// Per-barrel diagnostics of a many-to-one sweep.
struct BarrelReport {
  int upper = 0;        ///< real upper cap
  int layers = 0;
  double min_scaled_jacobian = 1.0;
  bool smoothed = false;
  /// Imprinting steps (sec. 5.1-5.5) of a barrel with subcaps on both ends, in order.
  std::vector<ImprintStep> imprint_steps;
};

/// Meshes the volume of `plan` (classify_barrels() ok). The sides and the
/// source caps are meshed in view.mesh; the target's mesh is returned in
/// surface_quads / surface_tris. Throws MeshingError naming the volume and
/// the barrel's caps on failure (irregular sides, ribs that end elsewhere,
/// elements that stay inverted).
/// \param[in] polygon_mesher  meshes imprinted subcaps without a mesh (needed
///                            only for barrels with subcaps on both ends)
scheme::EntityMesh sweep_many_to_one(const scheme::VolumeView& view, const ManyToOne& plan,
                                     const scheme::PolygonMesher* polygon_mesher = nullptr,
                                     std::vector<BarrelReport>* reports = nullptr);

}  // namespace cooperage::cooper
