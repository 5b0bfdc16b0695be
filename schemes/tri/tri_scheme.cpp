#include "schemes/tri/tri_scheme.h"

#include <string>
#include <unordered_map>

#include "framework/core/error.h"
#include "schemes/tri/face_space.h"

namespace cooperage::tri {
namespace {

[[noreturn]] void fail(int surface_id, const std::string& message) {
  throw MeshingError(ErrorCode::MeshingFailed, EntityRef::surface(surface_id), message);
}

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
                                   const scheme::MeshParams& /*params*/) const {
  const int sid = view.surface_id;
  if (!view.mesh) fail(sid, "tri needs the meshed curves");
  if (view.surface().loops.empty()) fail(sid, "no boundary loops");
  FlatFace flat;
  const FaceSpace space(view.model, sid, *view.mesh, flat);

  mesh2d::Triangulation2D t;
  try {
    t = mesh2d::triangulate(flat.loops, options_);
  } catch (const MeshingError& e) {
    fail(sid, "tri: the loops are not valid in the face's parameter plane (" + e.message() + ")");
  }

  scheme::EntityMesh out;
  std::vector<int> local(t.points.size(), -1);
  std::unordered_map<int, int> local_of_node;  // seam nodes appear twice in the loops
  size_t k = 0;
  for (const auto& ring : flat.nodes) {
    for (int node : ring) {
      auto [it, fresh] = local_of_node.emplace(node, 0);
      if (fresh) it->second = out.add(view.mesh->node(node), node);
      local[k++] = it->second;
    }
  }
  for (size_t i = t.boundary_count; i < t.points.size(); ++i)
    local[i] = out.add(space.point(t.points[i]));
  out.tris.reserve(t.triangles.size());
  for (const auto& tri : t.triangles) {
    const mesh::Tri e{local[static_cast<size_t>(tri[0])], local[static_cast<size_t>(tri[1])],
                      local[static_cast<size_t>(tri[2])]};
    const Vec3& a = out.coords[static_cast<size_t>(e[0])];
    const Vec3& b = out.coords[static_cast<size_t>(e[1])];
    const Vec3& c = out.coords[static_cast<size_t>(e[2])];
    const Vec3 n = (b - a).cross(c - a);
    if (!(n.dot(space.normal((a + b + c) / 3.0)) > 0.0)) {
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
