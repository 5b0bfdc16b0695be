#include "schemes/cooper/cooper_scheme.h"

#include "framework/core/error.h"
#include "schemes/cooper/classify_barrels.h"
#include "schemes/cooper/form_barrels.h"
#include "schemes/cooper/loop_nodes.h"
#include "schemes/cooper/sweep_many_to_one.h"
#include "schemes/cooper/sweep_barrel.h"

#include <algorithm>
#include <set>
#include <unordered_map>

namespace cooperage::cooper {
namespace {

std::string volume_name(int id) { return "volume " + std::to_string(id); }

[[noreturn]] void fail(int volume_id, const std::string& message) {
  throw MeshingError(ErrorCode::MeshingFailed, EntityRef::volume(volume_id), message);
}

const mesh::SurfaceMeshData& meshed(const mesh::MeshDB& db, int volume_id, int surface_id,
                                    const char* what) {
  if (!db.surface_meshed(surface_id)) {
    fail(volume_id, std::string(what) + " surface " + std::to_string(surface_id) + " is not meshed");
  }
  return db.surface(surface_id);
}

}  // namespace

Elements CooperScheme::elements(int volume_id) const {
  const auto it = options_.elements.find(volume_id);
  return it == options_.elements.end() ? Elements::Hex : it->second;
}

Classification CooperScheme::classify(const scheme::VolumeView& view) const {
  const auto it = options_.hints.find(view.volume_id);
  static const SweepHints none;
  return classify_faces(view.model, view.volume_id, *registry_,
                        it == options_.hints.end() ? none : it->second, elements(view.volume_id));
}

const scheme::PolygonMesher* CooperScheme::polygon_mesher(int volume_id) const {
  switch (elements(volume_id)) {
    case Elements::Wedge: return options_.triangle_mesher.get();
    case Elements::Mixed: return options_.quad_dominant_mesher.get();
    case Elements::Hex: break;
  }
  return options_.polygon_mesher.get();
}

// Barrels do not depend on the element kind; the caps' schemes do (wedge
// and mixed mode replace the quad schemes classify_barrels chose).
ManyToOne CooperScheme::classify_many(const scheme::VolumeView& view) const {
  const auto it = options_.hints.find(view.volume_id);
  static const SweepHints none;
  ManyToOne m = classify_barrels(view.model, view.volume_id, *registry_,
                                 it == options_.hints.end() ? none : it->second,
                                 polygon_mesher(view.volume_id) != nullptr);
  const Elements kind = elements(view.volume_id);
  if (!m.ok || kind == Elements::Hex) return m;
  // Flush steps build their rib loops from quads only (flush_upper_loops).
  for (const BarrelPlan& b : m.barrels) {
    if (b.flush) {
      m.ok = false;
      m.why = volume_name(view.volume_id) + ": a step flush with an outer wall (cap " +
              std::to_string(b.upper) + ") is swept in hex mode only, not with wedge or mixed elements";
      return m;
    }
  }
  for (auto& [cap, scheme] : m.cap_schemes) {
    std::string why;
    scheme = detail::cap_scheme(view.model, *registry_, cap, why, kind);
    if (scheme.empty()) {
      m.ok = false;
      m.why = volume_name(view.volume_id) + ": " + why;
      return m;
    }
  }
  return m;
}

// One-to-one (part I) first; else many-to-one (part II) at a lower score, so
// the selector ranks volume map, then cooper one-to-one, then many-to-one.
scheme::Applicability CooperScheme::applicable(const scheme::VolumeView& view) const {
  const Classification c = classify(view);
  if (c.ok) return scheme::Applicability::yes(c.score, c.why);
  const ManyToOne m = classify_many(view);
  if (m.ok) return scheme::Applicability::yes(m.score, m.why);
  if (m.needs_decomposition) return scheme::Applicability::no(m.why);
  return scheme::Applicability::no(c.why + "; as many-to-one: " + m.why);
}

void CooperScheme::constrain(const scheme::VolumeView& view,
                             intervals::IntervalProblem& problem) const {
  const Classification c = classify(view);
  if (!c.ok) {
    constrain_many(view, problem);
    return;
  }
  const std::string tag = volume_name(view.volume_id) + " (cooper)";
  // The target boundary is linked to the source's through every side face.
  for (const SideFace& side : c.sides) {
    problem.add_equal(side.source_curves, side.target_curves,
                      tag + ": side surface " + std::to_string(side.surface) +
                          " source boundary = target boundary");
  }
  // Every linking path from source to target has the same count (the layers).
  std::set<std::vector<int>> seen;
  std::vector<int> first;
  for (const SideFace& side : c.sides) {
    for (const auto& chain : side.linking_chains) {
      std::vector<int> key = chain;
      std::sort(key.begin(), key.end());
      if (!seen.insert(key).second) continue;
      if (first.empty()) {
        first = chain;
        continue;
      }
      problem.add_equal(first, chain, tag + ": linking path of side surface " +
                                          std::to_string(side.surface) + " = layers");
    }
  }
}

// cite: Blacker 1996, sec. 3-4: per side, upper run = lower run; per barrel,
// every linking chain the same count (its layers).
void CooperScheme::constrain_many(const scheme::VolumeView& view,
                                  intervals::IntervalProblem& problem) const {
  const ManyToOne m = classify_many(view);
  if (!m.ok) return;
  const std::string tag = volume_name(view.volume_id) + " (cooper many-to-one)";
  for (const SideFace& side : m.sides) {
    if (side.spans_caps) continue;  // balanced by its submap
    problem.add_equal(side.source_curves, side.target_curves,
                      tag + ": side surface " + std::to_string(side.surface) +
                          " upper cap boundary = lower cap boundary");
  }
  // Even loops where imprinted subcaps are meshed in 2D (pave's 2D core
  // needs every loop even): both real caps of a barrel with subcaps on both
  // ends (Blacker 1996, sec. 5.3, 6.1: even parity for all-quad). Mixed mode
  // meshes them with pave too (then splits poor quads); the triangle mesher
  // of wedge mode needs none.
  for (const BarrelPlan& b : m.barrels) {
    if (b.lower_inflow.empty() || elements(view.volume_id) == Elements::Wedge) continue;
    for (int cap : {b.upper, b.lower}) {
      const auto& loops = view.model.surface(cap).loops;
      for (size_t l = 0; l < loops.size(); ++l) {
        std::vector<int> curves;
        for (const auto& use : loops[l].uses) curves.push_back(use.curve);
        problem.add_even(curves, tag + ": loop " + std::to_string(l) + " of imprinted cap " +
                                     std::to_string(cap) + " even");
      }
    }
  }
  for (size_t b = 0; b < m.barrels.size(); ++b) {
    std::set<std::vector<int>> seen;
    std::vector<int> first;
    for (const auto& chain : m.barrels[b].linking_chains) {
      std::vector<int> key = chain;
      std::sort(key.begin(), key.end());
      if (!seen.insert(key).second) continue;
      if (first.empty()) {
        first = chain;
        continue;
      }
      problem.add_equal(first, chain, tag + ": barrel from cap " +
                                          std::to_string(m.barrels[b].upper) +
                                          ": linking paths = layers");
    }
  }
}

scheme::SurfaceRoles CooperScheme::roles(const scheme::VolumeView& view) const {
  const Classification c = classify(view);
  scheme::SurfaceRoles roles;
  if (!c.ok) {
    const ManyToOne m = classify_many(view);
    if (!m.ok) return roles;
    for (const SideFace& side : m.sides) {
      roles[side.surface] = detail::side_scheme(view.model, *registry_, side.surface);
    }
    for (const auto& [cap, scheme] : m.cap_schemes) roles[cap] = scheme;
    for (int cap : m.volume_caps) roles[cap] = scheme::kMeshedByVolume;
    return roles;
  }
  for (const SideFace& side : c.sides) {
    roles[side.surface] = detail::side_scheme(view.model, *registry_, side.surface);
  }
  roles[c.source] = c.source_scheme;
  for (size_t k = 0; k < c.source_subcaps.size(); ++k) {
    roles[c.source_subcaps[k]] = c.source_subcap_schemes[k];
  }
  roles[c.target] = scheme::kMeshedByVolume;
  return roles;
}

void CooperScheme::set_hints(int volume_id, std::vector<int> sources, std::vector<int> targets,
                             std::optional<geom::Vec3> direction) {
  if (sources.empty() && targets.empty() && !direction) {
    options_.hints.erase(volume_id);
    return;
  }
  options_.hints[volume_id] = SweepHints{std::move(sources), std::move(targets), direction};
}

// cite: Blacker 1996, sec. 4 (barrel formation) and sec. 6 (meshing barrels),
// the one-barrel case.
scheme::EntityMesh CooperScheme::mesh(const scheme::VolumeView& view,
                                      const scheme::MeshParams& /*params*/) const {
  const int vid = view.volume_id;
  const geom::Model& model = view.model;
  if (!view.mesh) fail(vid, "cooper needs the meshed side and source surfaces");
  const mesh::MeshDB& db = *view.mesh;
  const Classification c = classify(view);
  if (!c.ok) {
    const ManyToOne m = classify_many(view);
    if (m.ok) return sweep_many_to_one(view, m, polygon_mesher(vid));
    throw MeshingError(ErrorCode::NotApplicable, EntityRef::volume(vid),
                       m.needs_decomposition ? m.why : c.why + "; as many-to-one: " + m.why);
  }

  // Barrel formation (sec. 4) from the source cap down the side meshes.
  BarrelInput barrel_in;
  std::string side_list;
  for (const SideFace& side : c.sides) {
    const mesh::SurfaceMeshData& s = meshed(db, vid, side.surface, "side");
    if (!s.tris.empty()) {
      fail(vid, "side surface " + std::to_string(side.surface) + " has triangles; ribs need quads");
    }
    barrel_in.side_quads.insert(barrel_in.side_quads.end(), s.quads.begin(), s.quads.end());
    side_list += (side_list.empty() ? "" : ", ") + std::to_string(side.surface);
  }
  barrel_in.upper_loops = loop_nodes(model, db, vid, c.source);
  if (!c.source_loops.empty()) {
    // A composite source cap: its boundary is the loops not filled by subcaps.
    std::vector<std::vector<int>> kept;
    for (int l : c.source_loops) kept.push_back(barrel_in.upper_loops[static_cast<size_t>(l)]);
    barrel_in.upper_loops = std::move(kept);
  }
  std::vector<std::vector<int>> target_loops = loop_nodes(model, db, vid, c.target);
  for (const auto& loop : target_loops) {
    barrel_in.stop_nodes.insert(barrel_in.stop_nodes.end(), loop.begin(), loop.end());
  }
  const Barrel barrel = form_barrels(barrel_in);
  if (!barrel.ok) {
    fail(vid, "barrel formation from source surface " + std::to_string(c.source) +
                  " along side surfaces " + side_list + " failed: " + barrel.why);
  }
  std::vector<int> ends;
  for (const auto& rib : barrel.ribs) ends.push_back(rib.back());
  std::vector<int> stops = barrel_in.stop_nodes;
  std::sort(ends.begin(), ends.end());
  std::sort(stops.begin(), stops.end());
  if (!barrel.all_ribs_on_stop_nodes || ends != stops) {
    fail(vid, "the lower cap of the barrel from source surface " + std::to_string(c.source) +
                  " (ribs along side surfaces " + side_list +
                  ") does not match target surface " + std::to_string(c.target) +
                  "'s boundary; the barrel ends on several caps (many-to-one, cooper part II)");
  }

  // Local cap nodes: rib starts in rib order, then interior source nodes.
  // A composite source cap is the union of its faces' meshes (they share the
  // nodes of the filled hole loops).
  std::vector<int> cap_faces{c.source};
  cap_faces.insert(cap_faces.end(), c.source_subcaps.begin(), c.source_subcaps.end());
  std::vector<const mesh::SurfaceMeshData*> cap_meshes;
  size_t cap_elements = 0;
  for (int f : cap_faces) {
    cap_meshes.push_back(&meshed(db, vid, f, f == c.source ? "source" : "source subcap"));
    cap_elements += cap_meshes.back()->quads.size() + cap_meshes.back()->tris.size();
  }
  SweepInput in;
  in.layers = barrel.layers;
  in.boundary = static_cast<int>(barrel.ribs.size());
  std::unordered_map<int, int> local;
  local.reserve(cap_elements + barrel.ribs.size());
  std::vector<int> cap_global;
  for (const auto& loop : barrel_in.upper_loops) {
    in.loop_starts.push_back(cap_global.size());
    for (int g : loop) {
      local.emplace(g, static_cast<int>(cap_global.size()));
      cap_global.push_back(g);
    }
  }
  auto local_of = [&](int g) {
    auto [it, added] = local.emplace(g, static_cast<int>(cap_global.size()));
    if (added) cap_global.push_back(g);
    return it->second;
  };
  // Source elements are oriented with the natural normal; the sweep wants
  // them counter-clockwise about the direction into the volume.
  for (size_t f = 0; f < cap_faces.size(); ++f) {
    const mesh::SurfaceMeshData& cap = *cap_meshes[f];
    const bool outward = model.sense_in(cap_faces[f], vid) == geom::Sense::Forward;
    for (const auto& q : cap.quads) {
      mesh::Quad l{local_of(q[0]), local_of(q[1]), local_of(q[2]), local_of(q[3])};
      if (outward) std::swap(l[1], l[3]);
      in.quads.push_back(l);
    }
    for (const auto& t : cap.tris) {
      mesh::Tri l{local_of(t[0]), local_of(t[1]), local_of(t[2])};
      if (outward) std::swap(l[1], l[2]);
      in.tris.push_back(l);
    }
  }
  in.cap_nodes = static_cast<int>(cap_global.size());
  in.source.reserve(cap_global.size());
  for (int g : cap_global) in.source.push_back(db.node(g));
  const size_t J1 = static_cast<size_t>(in.layers) + 1;
  in.ribs.reserve(barrel.ribs.size() * J1);
  for (const auto& rib : barrel.ribs) {
    for (int g : rib) in.ribs.push_back(db.node(g));
  }
  const auto target_geometry = model.surface(c.target).geometry;
  in.project_target = [target_geometry](const Vec3& p) { return target_geometry->project(p).point; };

  const SweepResult sweep = sweep_barrel(in);
  if (!sweep.ok) {
    fail(vid, "sweep from surface " + std::to_string(c.source) + " to surface " +
                  std::to_string(c.target) + ": " + sweep.why);
  }

  // Entity mesh: rib nodes and source nodes exist; target cap interior nodes
  // belong to the target surface; interior layer nodes to the volume.
  scheme::EntityMesh out;
  const size_t n = static_cast<size_t>(in.cap_nodes);
  const size_t B = static_cast<size_t>(in.boundary);
  const size_t J = static_cast<size_t>(in.layers);
  std::vector<int> node(sweep.points.size());
  out.global.reserve(sweep.points.size());
  out.coords.reserve(sweep.points.size());
  for (size_t j = 0; j <= J; ++j) {
    for (size_t i = 0; i < n; ++i) {
      const size_t p = j * n + i;
      if (i < B) {
        node[p] = out.add(sweep.points[p], barrel.ribs[i][j]);
      } else if (j == 0) {
        node[p] = out.add(sweep.points[p], cap_global[i]);
      } else if (j == J) {
        node[p] = out.add_owned(sweep.points[p], {2, c.target});
      } else {
        node[p] = out.add(sweep.points[p]);
      }
    }
  }
  out.hexes.reserve(sweep.hexes.size());
  for (const auto& h : sweep.hexes) {
    mesh::Hex e;
    for (size_t k = 0; k < 8; ++k) e[k] = node[static_cast<size_t>(h[k])];
    out.hexes.push_back(e);
  }
  out.wedges.reserve(sweep.wedges.size());
  for (const auto& w : sweep.wedges) {
    mesh::Wedge e;
    for (size_t k = 0; k < 6; ++k) e[k] = node[static_cast<size_t>(w[k])];
    out.wedges.push_back(e);
  }
  // Target cap: the hexes' top faces are counter-clockwise about the outward
  // normal there; store them with the target's natural normal.
  const bool target_outward = model.sense_in(c.target, vid) == geom::Sense::Forward;
  const size_t top = J * n;
  auto& tq = out.surface_quads[c.target];
  tq.reserve(in.quads.size());
  for (const auto& q : in.quads) {
    mesh::Quad f;
    for (size_t k = 0; k < 4; ++k) f[k] = node[top + static_cast<size_t>(q[k])];
    if (!target_outward) std::swap(f[1], f[3]);
    tq.push_back(f);
  }
  if (!in.tris.empty()) {
    auto& tt = out.surface_tris[c.target];
    for (const auto& t : in.tris) {
      mesh::Tri f;
      for (size_t k = 0; k < 3; ++k) f[k] = node[top + static_cast<size_t>(t[k])];
      if (!target_outward) std::swap(f[1], f[2]);
      tt.push_back(f);
    }
  }
  return out;
}

std::unique_ptr<scheme::VolumeScheme> make_cooper(const scheme::Registry& registry,
                                                  CooperOptions options) {
  return std::make_unique<CooperScheme>(registry, std::move(options));
}

}  // namespace cooperage::cooper
