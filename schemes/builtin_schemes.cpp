#include "schemes/builtin_schemes.h"

#include "framework/mesh/improve_split_nodes.h"
#include "framework/mesh2d/triangulate.h"
#include "framework/scheme/plugin_loader.h"

#include "schemes/cooper/cooper_scheme.h"
#include "schemes/map/surface_map.h"
#include "schemes/map/volume_map.h"
#include "schemes/pave/pave_2d.h"
#include "schemes/pave/pave_scheme.h"
#include "schemes/quad_dominant/fallback_chain.h"
#include "schemes/quad_dominant/pave_with_ear.h"
#include "schemes/quad_dominant/quad_dominant_scheme.h"
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

// The triangle counterpart for wedge mode: the tri scheme's 2D core,
// framework/mesh2d.
class Triangles2D final : public scheme::PolygonMesher {
 public:
  scheme::QuadMesh2D mesh(const std::vector<std::vector<Eigen::Vector2d>>& loops) const override {
    mesh2d::Triangulation2D t = mesh2d::triangulate(loops);
    scheme::QuadMesh2D out;
    out.boundary_count = static_cast<int>(t.boundary_count);
    out.points = std::move(t.points);
    out.tris = std::move(t.triangles);
    return out;
  }
};

// The quad-dominant counterpart for mixed mode, as the quad_dominant scheme:
// pave's quads, those below the mixed quad quality split into triangles; an
// odd boundary (an imprinted subcap) gets one triangle at a corner first.
class QuadDominant2D final : public scheme::PolygonMesher {
 public:
  scheme::QuadMesh2D mesh(const std::vector<std::vector<Eigen::Vector2d>>& loops) const override {
    quad_dominant::PavedWithEar paved = quad_dominant::pave_with_ear(loops);
    pave::QuadMesh2D& m = paved.mesh;
    std::vector<geom::Vec3> points;
    points.reserve(m.points.size());
    for (const Eigen::Vector2d& p : m.points) points.emplace_back(p.x(), p.y(), 0.0);
    std::vector<bool> movable(points.size());
    for (size_t i = 0; i < movable.size(); ++i)
      movable[i] = static_cast<int>(i) >= m.boundary_count;
    mesh::QuadDominant split = mesh::make_quad_dominant(
        points, m.quads, movable, [](const geom::Vec3& x) { return geom::Vec3(x.x(), x.y(), 0.0); },
        cooper::kMixedMinQuadQuality);
    for (size_t i = 0; i < points.size(); ++i) m.points[i] = points[i].head<2>();
    if (paved.ear) split.tris.push_back(*paved.ear);
    return {std::move(m.points), std::move(split.quads), m.boundary_count, std::move(split.tris)};
  }
};

}  // namespace

void register_builtin_schemes(scheme::Registry& registry) {
  // map, submap and pave fall back (pave, quad-dominant, triangles) when the
  // surface mesh is the product (--dim 2); as the roles of a volume scheme
  // they are themselves alone.
  using quad_dominant::FallbackChain;
  registry.add(
      std::make_unique<FallbackChain>(map::make_surface_map(), pave::make_pave(), tri::make_tri()));
  registry.add(
      std::make_unique<FallbackChain>(submap::make_submap(), pave::make_pave(), tri::make_tri()));
  registry.add(std::make_unique<FallbackChain>(pave::make_pave(), nullptr, tri::make_tri()));
  registry.add(tri::make_tri());  // triangles: chosen only when pinned (score 0.1)
  // Likewise; cooper's mixed caps: pave's quads, the poor ones split.
  registry.add(std::make_unique<quad_dominant::QuadDominantScheme>(pave::make_pave(),
                                                                   cooper::kMixedMinQuadQuality));
  registry.add(map::make_volume_map());
  cooper::CooperOptions cooper_options;
  cooper_options.polygon_mesher = std::make_shared<Pave2D>();
  cooper_options.triangle_mesher = std::make_shared<Triangles2D>();
  cooper_options.quad_dominant_mesher = std::make_shared<QuadDominant2D>();
  registry.add(cooper::make_cooper(registry, std::move(cooper_options)));
}

std::vector<io::PluginSetting> run_plugins(const std::vector<std::string>& command_line,
                                           const std::vector<io::PluginSetting>& journal) {
  std::vector<io::PluginSetting> out;
  for (const std::string& file : command_line) out.push_back({file, file, {"", 0, "--plugin"}});
  out.insert(out.end(), journal.begin(), journal.end());
  return out;
}

void register_schemes(scheme::Registry& registry, const std::vector<io::PluginSetting>& plugins,
                      bool plugin_path) {
  register_builtin_schemes(registry);
  if (plugin_path) scheme::load_plugin_path(registry);
  for (const io::PluginSetting& p : plugins) {
    const std::string where =
        p.where.line > 0 ? p.where.file + ":" + std::to_string(p.where.line) : p.where.element;
    scheme::load_plugin(registry, p.path, where);
  }
}

}  // namespace cooperage
