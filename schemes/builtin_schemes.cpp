#include "schemes/builtin_schemes.h"

#include "framework/mesh2d/recombine.h"
#include "framework/mesh2d/triangulate.h"

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

// The triangle (wedge mode) and quad-dominant (mixed mode) counterparts:
// the tri scheme's 2D core, framework/mesh2d, without and with recombination.
class Triangles2D final : public scheme::PolygonMesher {
 public:
  explicit Triangles2D(bool recombine) : recombine_(recombine) {}
  scheme::QuadMesh2D mesh(const std::vector<std::vector<Eigen::Vector2d>>& loops) const override {
    mesh2d::Triangulation2D t = mesh2d::triangulate(loops);
    scheme::QuadMesh2D out;
    out.boundary_count = static_cast<int>(t.boundary_count);
    if (!recombine_) {
      out.points = std::move(t.points);
      out.tris = std::move(t.triangles);
      return out;
    }
    mesh2d::MixedMesh2D m = mesh2d::recombine(t);
    out.points = std::move(m.points);
    out.quads = std::move(m.quads);
    out.tris = std::move(m.triangles);
    return out;
  }

 private:
  bool recombine_;
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
  registry.add(tri::make_quad_dominant());  // likewise; cooper's mixed caps
  registry.add(map::make_volume_map());
  cooper::CooperOptions cooper_options;
  cooper_options.polygon_mesher = std::make_shared<Pave2D>();
  cooper_options.triangle_mesher = std::make_shared<Triangles2D>(false);
  cooper_options.quad_dominant_mesher = std::make_shared<Triangles2D>(true);
  for (const io::VolumeSetting& v : options.volumes) {
    if (!v.sources.empty() || !v.targets.empty() || v.direction) {
      cooper_options.hints[v.id] = {v.sources, v.targets, v.direction};
    }
    if (v.elements == io::ElementKind::Wedge) cooper_options.elements[v.id] = cooper::Elements::Wedge;
    if (v.elements == io::ElementKind::Mixed) cooper_options.elements[v.id] = cooper::Elements::Mixed;
  }
  registry.add(cooper::make_cooper(registry, std::move(cooper_options)));
}

}  // namespace cooperage
