#include "schemes/builtin_schemes.h"

#include "schemes/cooper/cooper_scheme.h"
#include "schemes/map/surface_map.h"
#include "schemes/map/volume_map.h"
#include "schemes/pave/pave_2d.h"
#include "schemes/pave/pave_scheme.h"
#include "schemes/submap/submap_scheme.h"
#include "schemes/tri/tri_scheme.h"

namespace cooperage {
namespace {

// Pave's 2D core as the polygon mesher cooper uses for cap pieces that are
// not model surfaces (imprinted and virtual subcaps, Blacker 1996 sec. 6.1).
class Pave2D final : public scheme::PolygonMesher {
 public:
  scheme::QuadMesh2D mesh(const std::vector<std::vector<Eigen::Vector2d>>& loops) const override {
    pave::QuadMesh2D m = pave::pave_2d(loops);
    return {std::move(m.points), std::move(m.quads), m.boundary_count};
  }
};

}  // namespace

BuiltinOptions builtin_options(const io::MeshSettings& settings) {
  return {settings.vertex_types, settings.volumes};
}

void register_builtin_schemes(scheme::Registry& registry, const BuiltinOptions& options) {
  registry.add(map::make_surface_map());
  registry.add(submap::make_submap(options.vertex_types));
  registry.add(pave::make_pave());
  registry.add(tri::make_tri());  // triangles: chosen only when pinned (score 0.1)
  registry.add(map::make_volume_map());
  cooper::CooperOptions cooper_options;
  cooper_options.polygon_mesher = std::make_shared<Pave2D>();
  for (const io::VolumeSetting& v : options.volumes) {
    if (!v.sources.empty() || !v.targets.empty() || v.direction) {
      cooper_options.hints[v.id] = {v.sources, v.targets, v.direction};
    }
    // Mixed is rejected by pipeline::check_settings before meshing.
    if (v.elements == io::ElementKind::Wedge) cooper_options.elements[v.id] = cooper::Elements::Wedge;
  }
  registry.add(cooper::make_cooper(registry, std::move(cooper_options)));
}

}  // namespace cooperage
