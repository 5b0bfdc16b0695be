#include "schemes/builtin_schemes.h"

#include "schemes/map/surface_map.h"
#include "schemes/map/volume_map.h"
#include "schemes/submap/submap_scheme.h"

namespace cooperage {

void register_builtin_schemes(scheme::Registry& registry, const BuiltinOptions& options) {
  registry.add(map::make_surface_map());
  registry.add(submap::make_submap(options.vertex_types));
  registry.add(map::make_volume_map());
}

}  // namespace cooperage
