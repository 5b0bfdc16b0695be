#include "schemes/tri/tri_scheme.h"

#include <Eigen/Geometry>

#include <memory>
#include <string>
#include <unordered_map>

#include "framework/core/error.h"
#include "framework/mesh/loop_nodes.h"
#include "framework/mesh2d/surface_chart.h"

namespace cooperage::tri {
namespace {

[[noreturn]] void fail(int surface_id, const std::string& message) {
  throw MeshingError(ErrorCode::MeshingFailed, EntityRef::surface(surface_id), message);
}

using geom::Vec3;

std::string surface_name(int id) { return "surface " + std::to_string(id); }

}  // namespace

scheme::Applicability TriScheme::applicable(const scheme::SurfaceView& view) const {
  const geom::Surface& s = view.surface();
  if (s.loops.empty()) {
    return scheme::Applicability::no(
        surface_name(s.id) +
        ": no boundary loops (a closed surface such as a full sphere or "
        "torus has no curve mesh to triangulate); tri needs at least one loop");
  }
  return scheme::Applicability::yes(
      0.1, surface_name(s.id) + ": " + std::to_string(s.loops.size()) +
               " loop(s); tri triangulates any face with loops (triangles, not quads)");
}

void TriScheme::constrain(const scheme::SurfaceView& view,
                          intervals::IntervalProblem& problem) const {
  const geom::Surface& s = view.surface();
  for (size_t l = 0; l < s.loops.size(); ++l) {
    std::vector<int> ids;
    for (const geom::CurveUse& use : s.loops[l].uses) ids.push_back(use.curve);
    problem.add_at_least(ids, 3,
                         "tri: " + surface_name(s.id) + " loop " + std::to_string(l + 1) +
                             " needs at least 3 intervals");
  }
}

scheme::EntityMesh TriScheme::mesh(const scheme::SurfaceView& view,
                                   const scheme::Settings& /*params*/) const {
  const int sid = view.surface_id;
  if (!view.mesh) fail(sid, "tri needs the meshed curves");
  if (view.surface().loops.empty()) fail(sid, "no boundary loops");
  const std::vector<std::vector<int>> rings = mesh::surface_loop_nodes(view.model, sid, *view.mesh);
  for (size_t l = 0; l < rings.size(); ++l) {
    if (rings[l].size() < 3)
      fail(sid, "tri: loop " + std::to_string(l) + " has fewer than 3 intervals");
  }
  std::vector<std::vector<geom::Vec3>> loops3d;
  for (const auto& ring : rings) {
    loops3d.emplace_back();
    for (int node : ring) loops3d.back().push_back(view.mesh->node(node));
  }
  std::unique_ptr<mesh2d::SurfaceChart> chart;
  mesh2d::Triangulation2D t;
  try {
    chart = std::make_unique<mesh2d::SurfaceChart>(*view.surface().geometry, loops3d);
    t = mesh2d::triangulate(chart->loops_2d(), options_);
  } catch (const MeshingError& e) {
    fail(sid, "tri: " + e.message());
  }

  scheme::EntityMesh out;
  std::vector<int> local(t.points.size(), -1);
  std::unordered_map<int, int> local_of_node;  // seam nodes appear twice in the loops
  size_t k = 0;
  for (const auto& loop : chart->sources()) {  // chart points: loop nodes (touching loops merged)
    for (const mesh2d::LoopPointRef& r : loop) {
      const int node = rings[static_cast<size_t>(r.loop)][static_cast<size_t>(r.index)];
      auto [it, fresh] = local_of_node.emplace(node, 0);
      if (fresh) it->second = out.add(view.mesh->node(node), node);
      local[k++] = it->second;
    }
  }
  for (size_t i = t.boundary_count; i < t.points.size(); ++i)
    local[i] = out.add(chart->to_3d(t.points[i]));
  out.tris.reserve(t.triangles.size());
  for (const auto& tri : t.triangles) {
    mesh::Tri e{local[static_cast<size_t>(tri[0])], local[static_cast<size_t>(tri[1])],
                local[static_cast<size_t>(tri[2])]};
    if (chart->mirrored()) std::swap(e[1], e[2]);
    const Vec3& a = out.coords[static_cast<size_t>(e[0])];
    const Vec3& b = out.coords[static_cast<size_t>(e[1])];
    const Vec3& c = out.coords[static_cast<size_t>(e[2])];
    const Vec3 n = (b - a).cross(c - a);
    Eigen::Vector2d centre = Eigen::Vector2d::Zero();
    for (int v : tri) centre += t.points[static_cast<size_t>(v)] / 3.0;
    if (!(n.dot(chart->normal_at(centre)) > 0.0)) {
      fail(sid,
           "tri: a triangle is inverted or flat against the surface normal (the face's "
           "parameterisation is too distorted)");
    }
    out.tris.push_back(e);
  }
  return out;
}

std::unique_ptr<scheme::SurfaceScheme> make_tri() { return std::make_unique<TriScheme>(); }

}  // namespace cooperage::tri
