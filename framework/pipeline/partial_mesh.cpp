#include "framework/pipeline/partial_mesh.h"

#include <vector>

namespace cooperage::pipeline {

mesh::MeshDB keep_entities(const mesh::MeshDB& db, const geom::Model& model,
                           const std::set<int>& volumes, const std::set<int>& surfaces) {
  std::set<int> kept_surfaces = surfaces;
  if (!volumes.empty()) {
    kept_surfaces.clear();
    for (const auto& [sid, s] : db.surfaces()) {
      for (int v : model.surface(sid).volumes)
        if (volumes.count(v)) kept_surfaces.insert(sid);
    }
  }
  std::set<int> kept_curves;
  for (int sid : kept_surfaces)
    for (const geom::Loop& loop : model.surface(sid).loops)
      for (const geom::CurveUse& u : loop.uses) kept_curves.insert(u.curve);

  std::vector<char> used(db.node_count(), 0);
  auto mark = [&](const auto& elements) {
    for (const auto& e : elements)
      for (int n : e) used[static_cast<std::size_t>(n)] = 1;
  };
  for (int vid : volumes) {
    mark(db.volume(vid).hexes);
    mark(db.volume(vid).wedges);
  }
  for (int sid : kept_surfaces) {
    mark(db.surface(sid).quads);
    mark(db.surface(sid).tris);
  }
  for (int cid : kept_curves)
    for (int n : db.curve_nodes(cid)) used[static_cast<std::size_t>(n)] = 1;

  mesh::MeshDB out;
  std::vector<int> renumber(db.node_count(), -1);
  for (std::size_t i = 0; i < db.node_count(); ++i) {
    if (!used[i]) continue;
    const int n = static_cast<int>(i);
    renumber[i] = out.add_node(db.node(n), db.owner(n));
  }
  auto remap = [&](auto elements) {
    for (auto& e : elements)
      for (int& n : e) n = renumber[static_cast<std::size_t>(n)];
    return elements;
  };
  for (const geom::Vertex& v : model.vertices()) {
    const int n = db.vertex_node(v.id);
    if (n >= 0 && renumber[static_cast<std::size_t>(n)] >= 0)
      out.set_vertex_node(v.id, renumber[static_cast<std::size_t>(n)]);
  }
  for (int cid : kept_curves) {
    if (!db.curve_meshed(cid)) continue;
    std::vector<int> chain = db.curve_nodes(cid);
    for (int& n : chain) n = renumber[static_cast<std::size_t>(n)];
    out.set_curve_nodes(cid, std::move(chain));
  }
  for (int sid : kept_surfaces) {
    if (!db.surface_meshed(sid)) continue;
    mesh::SurfaceMeshData& s = out.mutable_surface(sid);
    s.quads = remap(db.surface(sid).quads);
    s.tris = remap(db.surface(sid).tris);
  }
  for (int vid : volumes) {
    if (!db.volume_meshed(vid)) continue;
    mesh::VolumeMeshData& v = out.mutable_volume(vid);
    v.hexes = remap(db.volume(vid).hexes);
    v.wedges = remap(db.volume(vid).wedges);
  }
  return out;
}

}  // namespace cooperage::pipeline
