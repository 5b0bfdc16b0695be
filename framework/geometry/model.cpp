#include "framework/geometry/model.h"

#include "framework/core/error.h"

#include <algorithm>

namespace cooperage::geom {
namespace {

template <class T>
const T& at(const std::vector<T>& items, int id, int dim) {
  if (id < 1 || id > static_cast<int>(items.size())) {
    throw MeshingError(ErrorCode::InvalidInput, EntityRef{dim, id},
                       "no such entity (the model has " + std::to_string(items.size()) + ")");
  }
  return items[static_cast<size_t>(id - 1)];
}

// Broken topology comes from the input (a damaged file), not from a bug here.
[[noreturn]] void broken(int dim, int id, const std::string& what) {
  throw MeshingError(ErrorCode::GeometryError, EntityRef{dim, id},
                     what + "; the B-rep is not valid, repair it in the CAD tool");
}

}  // namespace

const Vertex& Model::vertex(int id) const { return at(vertices_, id, 0); }
const Curve& Model::curve(int id) const { return at(curves_, id, 1); }
const Surface& Model::surface(int id) const { return at(surfaces_, id, 2); }
const Volume& Model::volume(int id) const { return at(volumes_, id, 3); }
Vertex& Model::mutable_vertex(int id) { return const_cast<Vertex&>(vertex(id)); }
Curve& Model::mutable_curve(int id) { return const_cast<Curve&>(curve(id)); }
Surface& Model::mutable_surface(int id) { return const_cast<Surface&>(surface(id)); }
Volume& Model::mutable_volume(int id) { return const_cast<Volume&>(volume(id)); }

int Model::add_vertex(Vertex v) {
  v.id = static_cast<int>(vertices_.size()) + 1;
  vertices_.push_back(std::move(v));
  return vertices_.back().id;
}
int Model::add_curve(Curve c) {
  c.id = static_cast<int>(curves_.size()) + 1;
  curves_.push_back(std::move(c));
  return curves_.back().id;
}
int Model::add_surface(Surface s) {
  s.id = static_cast<int>(surfaces_.size()) + 1;
  surfaces_.push_back(std::move(s));
  return surfaces_.back().id;
}
int Model::add_volume(Volume v) {
  v.id = static_cast<int>(volumes_.size()) + 1;
  volumes_.push_back(std::move(v));
  return volumes_.back().id;
}

Sense Model::sense_in(int surface_id, int volume_id) const {
  for (const auto& shell : volume(volume_id).shells) {
    for (const auto& use : shell) {
      if (use.surface == surface_id) return use.sense;
    }
  }
  throw MeshingError(ErrorCode::InvalidInput, EntityRef::surface(surface_id),
                     "does not bound volume " + std::to_string(volume_id));
}

Vec3 Model::outward_normal(int surface_id, int volume_id, const Vec2& uv) const {
  const Surface& s = surface(surface_id);
  return sign(sense_in(surface_id, volume_id)) * s.geometry->normal(uv);
}

std::vector<int> Model::surfaces_of(int volume_id) const {
  std::vector<int> ids;
  for (const auto& shell : volume(volume_id).shells) {
    for (const auto& use : shell) ids.push_back(use.surface);
  }
  return ids;
}

BoundingBox Model::box() const {
  BoundingBox b;
  for (const auto& v : vertices_) b.add(v.point);
  for (const auto& s : surfaces_) b.add(s.box);
  return b;
}

void Model::validate() const {
  const int nv = static_cast<int>(vertices_.size());
  const int nc = static_cast<int>(curves_.size());
  const int ns = static_cast<int>(surfaces_.size());
  for (const auto& c : curves_) {
    if (c.start_vertex < 1 || c.start_vertex > nv || c.end_vertex < 1 || c.end_vertex > nv)
      broken(1, c.id, "end vertex out of range");
    if (!c.geometry) broken(1, c.id, "no geometry");
    for (int v : {c.start_vertex, c.end_vertex}) {
      const auto& list = vertex(v).curves;
      if (std::find(list.begin(), list.end(), c.id) == list.end())
        broken(1, c.id, "vertex " + std::to_string(v) + " does not list it");
    }
  }
  for (const auto& s : surfaces_) {
    if (!s.geometry) broken(2, s.id, "no geometry");
    if (s.loops.empty()) broken(2, s.id, "has no boundary loop");
    for (const auto& loop : s.loops) {
      if (loop.uses.empty()) broken(2, s.id, "has an empty boundary loop");
      for (size_t i = 0; i < loop.uses.size(); ++i) {
        const CurveUse& a = loop.uses[i];
        const CurveUse& b = loop.uses[(i + 1) % loop.uses.size()];
        if (a.curve < 1 || a.curve > nc) broken(2, s.id, "loop curve out of range");
        const Curve& ca = curve(a.curve);
        const Curve& cb = curve(b.curve);
        const int a_end = a.sense == Sense::Forward ? ca.end_vertex : ca.start_vertex;
        const int b_start = b.sense == Sense::Forward ? cb.start_vertex : cb.end_vertex;
        if (a_end != b_start)
          broken(2, s.id,
                 "boundary loop is not closed between curves " + std::to_string(a.curve) + " and " +
                     std::to_string(b.curve));
        const auto& owners = ca.surfaces;
        if (std::find(owners.begin(), owners.end(), s.id) == owners.end())
          broken(2, s.id, "curve " + std::to_string(a.curve) + " does not list it");
      }
    }
    if (s.volumes.size() > 2) broken(2, s.id, "bounds more than two volumes");
  }
  for (const auto& v : volumes_) {
    if (v.shells.empty()) broken(3, v.id, "no shells");
    for (const auto& shell : v.shells) {
      for (const auto& use : shell) {
        if (use.surface < 1 || use.surface > ns) broken(3, v.id, "shell surface out of range");
        const auto& owners = surface(use.surface).volumes;
        if (std::find(owners.begin(), owners.end(), v.id) == owners.end())
          broken(3, v.id, "surface " + std::to_string(use.surface) + " does not list it");
        const bool first = !owners.empty() && owners.front() == v.id;
        if (first != (use.sense == Sense::Forward))
          broken(3, v.id,
                 "surface " + std::to_string(use.surface) +
                     " sense disagrees with its natural normal");
      }
    }
  }
}

int euler_characteristic(const Model& model) {
  int inner_loops = 0;
  for (const auto& s : model.surfaces()) inner_loops += static_cast<int>(s.loops.size()) - 1;
  return static_cast<int>(model.vertices().size()) - static_cast<int>(model.curves().size()) +
         static_cast<int>(model.surfaces().size()) - inner_loops;
}

}  // namespace cooperage::geom
