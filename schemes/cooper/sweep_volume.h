// Meshing a planned volume (Blacker 1996, sec. 4-6), one code path for one
// barrel and many: ribs down the meshed sides barrel by barrel
// (form_barrels.h), the ends of every barrel imprinted until all subcaps
// match (imprint_subcaps.h, repeated across the barrels), cap stacks meshed
// once and projected through the barrels, then every barrel swept layer by
// layer (sweep_barrel.h). The sides and the caps the plan gives to surface
// schemes are meshed in view.mesh; the caps meshed here come back in
// surface_quads / surface_tris.
#pragma once

#include "framework/scheme/polygon_mesher.h"
#include "framework/scheme/scheme.h"
#include "schemes/cooper/imprint_subcaps.h"
#include "schemes/cooper/plan_volume.h"

#include <vector>

namespace cooperage::cooper {

/// What happened in one barrel.
struct BarrelReport {
  int barrel = 0;               ///< index in the plan's tree
  std::vector<int> upper_caps;  ///< its real upper caps
  int layers = 0;
  double min_scaled_jacobian = 1.0;
  bool smoothed = false;
  std::vector<ImprintStep> imprint_steps;  ///< sec. 5.1-5.5, in order
};

/// Meshes the volume of `plan` (plan.ok). Throws MeshingError naming the
/// volume and the barrel on failure (a rib that runs into another, a
/// subcap imprinting that does not resolve, elements that stay inverted).
/// \param[in] polygon_mesher  meshes cap stacks that have no cap meshed by
///                            a surface scheme (plan.roles.needs_polygon_mesher)
scheme::EntityMesh sweep_volume(const scheme::VolumeView& view, const VolumePlan& plan,
                                const scheme::PolygonMesher* polygon_mesher = nullptr,
                                std::vector<BarrelReport>* reports = nullptr);

}  // namespace cooperage::cooper
