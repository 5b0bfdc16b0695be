#include "schemes/cooper/sweep_volume.h"

#include "schemes/cooper/sweep_state.h"

namespace cooperage::cooper {

// cite: Blacker 1996, sec. 2 (the process: sides meshed, barrels formed,
// subcaps imprinted, cap stacks meshed, interior nodes projected, elements).
scheme::EntityMesh sweep_volume(const scheme::VolumeView& view, const VolumePlan& plan,
                                const scheme::PolygonMesher* polygon_mesher,
                                std::vector<BarrelReport>* reports) {
  if (!view.mesh) detail::fail(view.volume_id, "cooper needs the meshed side and cap surfaces");
  if (!plan.ok)
    throw MeshingError(ErrorCode::NotApplicable, EntityRef::volume(view.volume_id), plan.why);
  detail::SweepState s(view, plan, polygon_mesher);
  detail::form_ribs(s);
  detail::make_charts(s);
  detail::make_pieces(s);
  detail::imprint_barrels(s);
  detail::mesh_stacks(s);
  detail::smooth_ends(s);
  detail::sweep_barrels(s, reports);
  detail::check_seams_welded(s);
  return std::move(s.out);
}

}  // namespace cooperage::cooper
