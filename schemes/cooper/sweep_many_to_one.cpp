#include "schemes/cooper/sweep_many_to_one.h"

#include "schemes/cooper/loop_nodes.h"
#include "schemes/cooper/many_to_one_builder.h"
#include "schemes/cooper/sweep_barrel.h"

#include <algorithm>

namespace cooperage::cooper::detail {

scheme::EntityMesh Builder::run(std::vector<BarrelReport>* reports) {
  virtual_.resize(plan_.barrels.size());
  for (size_t b = 0; b < plan_.barrels.size(); ++b) {
    const BarrelPlan& p = plan_.barrels[b];
    if (p.from_middle) {  // after the barrel it flows into; a flush one's outline now
      if (p.flush) {
        BarrelInput bin;
        std::vector<int> lower_nodes;
        record_ribs(b, bin, ribs(b, bin, lower_nodes));
      }
      continue;
    }
    const BarrelReport r = p.lower_inflow.empty() ? barrel(b) : two_sided(b);
    if (reports) reports->push_back(r);
    // Barrels meshed from the middle: out through the upper end (their
    // elements face the other way), then through the lower end.
    for (int i : p.inflow) {
      if (plan_.barrels[static_cast<size_t>(i)].from_middle) {
        const BarrelReport o = sweep_out(static_cast<size_t>(i), true);
        if (reports) reports->push_back(o);
      }
    }
    for (int i : p.lower_inflow) {
      if (plan_.barrels[static_cast<size_t>(i)].from_middle) {
        const BarrelReport o = sweep_out(static_cast<size_t>(i), false);
        if (reports) reports->push_back(o);
      }
    }
  }
  return std::move(out_);
}

int Builder::existing(int g) {
  auto [it, added] = local_.emplace(g, 0);
  if (added) it->second = out_.add(db_.node(g), g);
  return it->second;
}

const mesh::SurfaceMeshData& Builder::meshed(int surface, const std::string& what) const {
  if (!db_.surface_meshed(surface)) {
    fail(vid_, what + " surface " + std::to_string(surface) + " is not meshed");
  }
  return db_.surface(surface);
}

const SideFace& Builder::side(int surface) const {
  for (const SideFace& s : plan_.sides) {
    if (s.surface == surface) return s;
  }
  fail(vid_, "side surface " + std::to_string(surface) + " is not in the plan");
}

std::set<int> Builder::lower_curves(const BarrelPlan& p) const {
  std::set<int> c;
  for (int s : p.sides) {
    const auto& t = side(s).target_curves;
    c.insert(t.begin(), t.end());
  }
  return c;
}

// cite: Blacker 1996, sec. 4 (rib progression from the upper cap's loops
// that carry no inflowing subcap, until a rib reaches the lower cap).
Barrel Builder::ribs(size_t b, BarrelInput& bin, std::vector<int>& lower_loop_nodes) const {
  const BarrelPlan& p = plan_.barrels[b];
  const std::string name = "barrel " + std::to_string(b + 1) + " from cap " + std::to_string(p.upper);
  for (int s : p.sides) {
    const mesh::SurfaceMeshData& m = meshed(s, "side");
    if (!m.tris.empty()) fail(vid_, "side surface " + std::to_string(s) + " has triangles; ribs need quads");
    bin.side_quads.insert(bin.side_quads.end(), m.quads.begin(), m.quads.end());
  }
  std::set<int> filled;
  bool flush = false;
  for (int i : p.inflow) {
    const auto c = lower_curves(plan_.barrels[static_cast<size_t>(i)]);
    filled.insert(c.begin(), c.end());
    if (plan_.barrels[static_cast<size_t>(i)].flush) {
      flush = true;
      const auto& done = virtual_[static_cast<size_t>(i)].rib_nodes;
      bin.blocked_nodes.insert(bin.blocked_nodes.end(), done.begin(), done.end());
    }
  }
  const auto upper_loops = loop_nodes(model_, db_, vid_, p.upper);
  const auto& upper_geo = model_.surface(p.upper).loops;
  for (size_t k = 0; k < upper_loops.size() && !flush; ++k) {
    if (!filled.count(upper_geo[k].uses.front().curve)) bin.upper_loops.push_back(upper_loops[k]);
  }
  const bool two_sided = !p.lower_inflow.empty();
  if (flush && two_sided) {
    // The real cap is meshed here later: the upper cap is its loops merged
    // with the flush subcaps' rims; the nodes inside are taken by no rib.
    std::vector<std::vector<int>> rims;
    for (int i : p.inflow) {
      const auto& rim = virtual_[static_cast<size_t>(i)].rim;
      rims.insert(rims.end(), rim.begin(), rim.end());
    }
    bin.upper_loops = merge_loops(upper_loops, rims);
    if (bin.upper_loops.empty()) {
      fail(vid_, name + ": cap " + std::to_string(p.upper) + " and the flush subcaps beside it do not "
                        "form an upper cap bounded by side nodes");
    }
    std::set<int> rim;
    for (const auto& l : bin.upper_loops) rim.insert(l.begin(), l.end());
    rims.insert(rims.end(), upper_loops.begin(), upper_loops.end());
    for (const auto& l : rims) {
      for (int g : l) {
        if (!rim.count(g)) bin.blocked_nodes.push_back(g);
      }
    }
  } else if (flush) {
    // The combined cap's inner nodes (e.g. on the curve where the real cap
    // meets the virtual one) lie on side faces too: no rib takes them.
    bin.upper_loops = flush_upper_loops(p);
    std::set<int> rim;
    for (const auto& l : bin.upper_loops) rim.insert(l.begin(), l.end());
    for (const auto& q : meshed(p.upper, "source cap").quads) {
      for (int g : q) {
        if (!rim.count(g)) bin.blocked_nodes.push_back(g);
      }
    }
  }
  const int lower_surface = p.lower ? p.lower : p.into;
  const auto lower_loops = loop_nodes(model_, db_, vid_, lower_surface);
  const std::set<int> mine = lower_curves(p);
  std::vector<int> expected;
  for (size_t k = 0; k < lower_loops.size(); ++k) {
    bin.stop_nodes.insert(bin.stop_nodes.end(), lower_loops[k].begin(), lower_loops[k].end());
    lower_loop_nodes.insert(lower_loop_nodes.end(), lower_loops[k].begin(), lower_loops[k].end());
    if (mine.count(model_.surface(lower_surface).loops[k].uses.front().curve)) {
      expected.insert(expected.end(), lower_loops[k].begin(), lower_loops[k].end());
    }
  }
  // Flush subcaps arriving beside the real lower cap: the ribs end on the
  // merged outline of the cap and their rims (sec. 4 Fig. 8d, upside down).
  std::vector<std::vector<int>> lower_rims;
  for (int i : p.lower_inflow) {
    if (!plan_.barrels[static_cast<size_t>(i)].flush) continue;
    const auto& rim = virtual_[static_cast<size_t>(i)].rim;
    lower_rims.insert(lower_rims.end(), rim.begin(), rim.end());
  }
  if (!lower_rims.empty()) {
    expected.clear();
    for (const auto& l : merge_loops(lower_loops, lower_rims)) {
      expected.insert(expected.end(), l.begin(), l.end());
      bin.stop_nodes.insert(bin.stop_nodes.end(), l.begin(), l.end());
    }
  }
  const Barrel barrel = form_barrels(bin);
  if (!barrel.ok) fail(vid_, name + ": rib formation failed: " + barrel.why);
  std::vector<int> ends;
  for (const auto& rib : barrel.ribs) ends.push_back(rib.back());
  std::sort(ends.begin(), ends.end());
  std::sort(expected.begin(), expected.end());
  if (!p.flush && (!barrel.all_ribs_on_stop_nodes || ends != expected)) {
    fail(vid_, name + ": the ribs do not end on the loops of cap " + std::to_string(lower_surface) +
                   " that the barrel's sides reach");
  }
  return barrel;
}

void Builder::record_ribs(size_t b, const BarrelInput& bin, const Barrel& barrel) {
  VirtualCap& v = virtual_[b];
  v.rib_nodes.clear();
  v.rim.clear();
  for (const auto& rib : barrel.ribs) v.rib_nodes.insert(v.rib_nodes.end(), rib.begin(), rib.end() - 1);
  size_t r = 0;
  for (const auto& loop : bin.upper_loops) {
    v.rim.emplace_back();
    for (size_t k = 0; k < loop.size(); ++k, ++r) v.rim.back().push_back(barrel.ribs[r].back());
  }
}

// cite: Blacker 1996, sec. 4, Fig. 8d (the lower cap of a barrel stopped by
// an adjacent cap is combined with it into the next barrel's upper cap).
std::vector<std::vector<int>> Builder::flush_upper_loops(const BarrelPlan& p) const {
  std::vector<mesh::Quad> quads;
  const bool outward = model_.sense_in(p.upper, vid_) == geom::Sense::Forward;
  for (mesh::Quad q : meshed(p.upper, "source cap").quads) {
    if (outward) std::swap(q[1], q[3]);
    quads.push_back(q);
  }
  auto global = [&](int local) {
    const int g = out_.global[static_cast<size_t>(local)];
    return g >= 0 ? g : -2 - local;  // volume nodes: never on the boundary
  };
  for (int i : p.inflow) {
    for (const auto& q : virtual_[static_cast<size_t>(i)].quads) {
      quads.push_back({global(q[0]), global(q[1]), global(q[2]), global(q[3])});
    }
  }
  auto loops = quad_boundary_loops(quads);
  // Same direction as the real cap's loops (loop_nodes): compare a shared edge.
  const auto real = loop_nodes(model_, db_, vid_, p.upper);
  int sense = 0;
  for (const auto& l : loops) {
    for (size_t k = 0; k < l.size() && !sense; ++k) {
      const int a = l[k], b = l[(k + 1) % l.size()];
      for (const auto& r : real) {
        const auto it = std::find(r.begin(), r.end(), a);
        if (it == r.end()) continue;
        const size_t i = static_cast<size_t>(it - r.begin());
        if (r[(i + 1) % r.size()] == b) sense = 1;
        if (r[(i + r.size() - 1) % r.size()] == b) sense = -1;
      }
    }
  }
  bool ok = sense != 0 && !loops.empty();
  for (auto& l : loops) {
    if (sense < 0) std::reverse(l.begin(), l.end());
    for (int v : l) ok = ok && v >= 0;
  }
  if (!ok) {
    fail(vid_, "cap " + std::to_string(p.upper) + " and the virtual caps beside it do not form an upper cap "
               "bounded by side nodes");
  }
  return loops;
}

// cite: Blacker 1996, sec. 5.2 (subtraction onto a lower cap without
// subcaps), 6.1-6.3 (stack projection, interior nodes, elements).
BarrelReport Builder::barrel(size_t b) {
  const BarrelPlan& p = plan_.barrels[b];
  const std::string name = "barrel " + std::to_string(b + 1) + " from cap " + std::to_string(p.upper);
  const int lower_surface = p.lower ? p.lower : p.into;
  BarrelInput bin;
  std::vector<int> lower_nodes;
  const Barrel barrel = ribs(b, bin, lower_nodes);

  // Upper cap = real cap mesh + virtual subcaps (cap-local numbering:
  // rib starts first, in rib order).
  SweepInput in;
  in.layers = barrel.layers;
  in.boundary = static_cast<int>(barrel.ribs.size());
  std::vector<int> cap_entity;  // cap index -> EntityMesh-local node
  std::unordered_map<int, int> cap_index;
  auto index_of = [&](int e) {
    auto [it, added] = cap_index.emplace(e, static_cast<int>(cap_entity.size()));
    if (added) cap_entity.push_back(e);
    return it->second;
  };
  for (const auto& loop : bin.upper_loops) {
    in.loop_starts.push_back(cap_entity.size());
    for (int g : loop) index_of(existing(g));
  }
  const mesh::SurfaceMeshData& cap = meshed(p.upper, "source cap");
  const bool outward = model_.sense_in(p.upper, vid_) == geom::Sense::Forward;
  for (const auto& q : cap.quads) {
    mesh::Quad l;
    for (size_t k = 0; k < 4; ++k) l[k] = index_of(existing(q[k]));
    if (outward) std::swap(l[1], l[3]);
    in.quads.push_back(l);
  }
  for (const auto& t : cap.tris) {
    mesh::Tri l;
    for (size_t k = 0; k < 3; ++k) l[k] = index_of(existing(t[k]));
    if (outward) std::swap(l[1], l[2]);
    in.tris.push_back(l);
  }
  for (int i : p.inflow) {
    const VirtualCap& v = virtual_[static_cast<size_t>(i)];
    for (const auto& q : v.quads) in.quads.push_back({index_of(q[0]), index_of(q[1]), index_of(q[2]), index_of(q[3])});
    for (const auto& t : v.tris) in.tris.push_back({index_of(t[0]), index_of(t[1]), index_of(t[2])});
  }
  in.cap_nodes = static_cast<int>(cap_entity.size());
  for (int e : cap_entity) in.source.push_back(out_.coords[static_cast<size_t>(e)]);
  for (const auto& rib : barrel.ribs) {
    for (int g : rib) in.ribs.push_back(db_.node(g));
  }
  if (p.lower) {
    const auto geometry = model_.surface(p.lower).geometry;
    in.project_target = [geometry](const Vec3& x) { return geometry->project(x).point; };
  }
  const SweepResult sweep = sweep_barrel(in);
  if (!sweep.ok) fail(vid_, name + " to cap " + std::to_string(lower_surface) + ": " + sweep.why);

  // Nodes: ribs exist; the upper cap is known; the lower cap's interior
  // nodes belong to the target (or, virtual, to the volume).
  const size_t n = static_cast<size_t>(in.cap_nodes);
  const size_t B = static_cast<size_t>(in.boundary);
  const size_t J = static_cast<size_t>(in.layers);
  std::vector<int> node(sweep.points.size());
  for (size_t j = 0; j <= J; ++j) {
    for (size_t i = 0; i < n; ++i) {
      const size_t q = j * n + i;
      if (i < B) {
        node[q] = existing(barrel.ribs[i][j]);
      } else if (j == 0) {
        node[q] = cap_entity[i];
      } else if (j == J && p.lower) {
        node[q] = out_.add_owned(sweep.points[q], {2, p.lower});
      } else {
        node[q] = out_.add(sweep.points[q]);
      }
    }
  }
  for (const auto& h : sweep.hexes) {
    mesh::Hex e;
    for (size_t k = 0; k < 8; ++k) e[k] = node[static_cast<size_t>(h[k])];
    out_.hexes.push_back(e);
  }
  for (const auto& w : sweep.wedges) {
    mesh::Wedge e;
    for (size_t k = 0; k < 6; ++k) e[k] = node[static_cast<size_t>(w[k])];
    out_.wedges.push_back(e);
  }
  const size_t top = J * n;
  if (p.lower) {
    // The target: stored with its natural normal (part I convention).
    const bool target_outward = model_.sense_in(p.lower, vid_) == geom::Sense::Forward;
    auto& tq = out_.surface_quads[p.lower];
    for (const auto& q : in.quads) {
      mesh::Quad f;
      for (size_t k = 0; k < 4; ++k) f[k] = node[top + static_cast<size_t>(q[k])];
      if (!target_outward) std::swap(f[1], f[3]);
      tq.push_back(f);
    }
    for (const auto& t : in.tris) {
      mesh::Tri f;
      for (size_t k = 0; k < 3; ++k) f[k] = node[top + static_cast<size_t>(t[k])];
      if (!target_outward) std::swap(f[1], f[2]);
      out_.surface_tris[p.lower].push_back(f);
    }
  } else {
    record_ribs(b, bin, barrel);
    VirtualCap& v = virtual_[b];
    for (const auto& q : in.quads) {
      v.quads.push_back({node[top + static_cast<size_t>(q[0])], node[top + static_cast<size_t>(q[1])],
                         node[top + static_cast<size_t>(q[2])], node[top + static_cast<size_t>(q[3])]});
    }
    for (const auto& t : in.tris) {
      v.tris.push_back({node[top + static_cast<size_t>(t[0])], node[top + static_cast<size_t>(t[1])],
                        node[top + static_cast<size_t>(t[2])]});
    }
  }
  return {p.upper, barrel.layers, sweep.min_scaled_jacobian, sweep.smoothed, {}};
}

}  // namespace cooperage::cooper::detail

namespace cooperage::cooper {

scheme::EntityMesh sweep_many_to_one(const scheme::VolumeView& view, const ManyToOne& plan,
                                     const scheme::PolygonMesher* polygon_mesher,
                                     std::vector<BarrelReport>* reports) {
  if (!view.mesh) detail::fail(view.volume_id, "cooper needs the meshed side and source surfaces");
  if (!plan.ok) throw MeshingError(ErrorCode::NotApplicable, EntityRef::volume(view.volume_id), plan.why);
  return detail::Builder(view, plan, polygon_mesher).run(reports);
}

}  // namespace cooperage::cooper
