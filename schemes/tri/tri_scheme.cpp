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
  if (recombine_) {
    return scheme::Applicability::yes(
        0.1, surface_name(s.id) + ": " + std::to_string(s.loops.size()) +
                 " loop(s); quad_dominant meshes any face with loops (quads, triangles where "
                 "no good quad fits)");
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
  const std::string scheme_name(name());
  // Corner (a, b, c) turns counter-clockwise about the surface normal.
  auto check = [&](int a, int b, int c) {
    const Vec3& pa = out.coords[static_cast<size_t>(a)];
    const Vec3& pb = out.coords[static_cast<size_t>(b)];
    const Vec3& pc = out.coords[static_cast<size_t>(c)];
    if (!((pb - pa).cross(pc - pa).dot(space.normal((pa + pb + pc) / 3.0)) > 0.0)) {
      fail(sid, scheme_name +
                    ": an element is inverted or flat against the surface normal (the face's "
                    "parameterisation is too distorted)");
    }
  };
  auto to_local = [&](int k) { return local[static_cast<size_t>(k)]; };
  if (!recombine_) {
    out.tris.reserve(t.triangles.size());
    for (const auto& tri : t.triangles) {
      const mesh::Tri e{to_local(tri[0]), to_local(tri[1]), to_local(tri[2])};
      check(e[0], e[1], e[2]);
      out.tris.push_back(e);
    }
    return out;
  }
  const mesh2d::MixedMesh2D m = mesh2d::recombine(t, *recombine_);
  for (const auto& q : m.quads) {
    const mesh::Quad e{to_local(q[0]), to_local(q[1]), to_local(q[2]), to_local(q[3])};
    for (size_t k = 0; k < 4; ++k) check(e[k], e[(k + 1) % 4], e[(k + 3) % 4]);
    out.quads.push_back(e);
  }
  for (const auto& tri : m.triangles) {
    const mesh::Tri e{to_local(tri[0]), to_local(tri[1]), to_local(tri[2])};
    check(e[0], e[1], e[2]);
    out.tris.push_back(e);
  }
  return out;
}

std::unique_ptr<scheme::SurfaceScheme> make_tri() { return std::make_unique<TriScheme>(); }

std::unique_ptr<scheme::SurfaceScheme> make_quad_dominant() {
  return std::make_unique<TriScheme>(mesh2d::RefineOptions{}, mesh2d::RecombineOptions{});
}

}  // namespace cooperage::tri
