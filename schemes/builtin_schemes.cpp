#include "schemes/builtin_schemes.h"

#include "schemes/map/surface_map.h"
#include "schemes/map/volume_map.h"

namespace cooperage {

void register_builtin_schemes(scheme::Registry& registry) {
  registry.add(map::make_surface_map());
  registry.add(map::make_volume_map());
}

}  // namespace cooperage
