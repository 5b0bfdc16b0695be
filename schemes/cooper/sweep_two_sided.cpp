// A barrel with subcaps on both ends (appendages on top and bottom, Blacker
// 1996, Fig. 1/20): both real caps are pieces of subcaps, so cooper meshes
// them. Steps: ribs (sec. 4); the two ends in 2D along the barrel axis, the
// lower end mapped onto the upper by the least-squares map of the rings;
// imprint_subcaps (sec. 5) pairs the subcaps and adds interior ribs; every
// cap stack (sec. 6.1) is meshed once -- from an inflowing virtual subcap's
// mesh (projected through this barrel when it arrives on the lower end), or
// by the polygon mesher for an imprinted piece of a real cap -- and the
// upper end is swept to the lower one with the far ends of the interior
// ribs onto existing subcaps held fixed (sec. 6.2-6.3).
#include "schemes/cooper/imprint_subcaps.h"
#include "schemes/cooper/least_squares_map.h"
#include "schemes/cooper/loop_nodes.h"
#include "schemes/cooper/many_to_one_builder.h"
#include "schemes/cooper/smooth_cap.h"
#include "schemes/cooper/sweep_barrel.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <map>

namespace cooperage::cooper::detail {
namespace {

// Orients a subcap's loops in 2D: the largest loop first and counter-clockwise,
// the others clockwise.
void orient(Subcap& s, const std::map<int, Vec2>& xy) {
  size_t outer = 0;
  double best = -1;
  for (size_t l = 0; l < s.loops.size(); ++l) {
    const double a = std::abs(signed_area(s.loops[l], xy));
    if (a > best) {
      best = a;
      outer = l;
    }
  }
  std::swap(s.loops[0], s.loops[outer]);
  for (size_t l = 0; l < s.loops.size(); ++l) {
    const double a = signed_area(s.loops[l], xy);
    if ((l == 0) != (a > 0)) std::reverse(s.loops[l].begin(), s.loops[l].end());
  }
}

constexpr int kSentinel = 1000000000;  // imprint's new node ids start above it

}  // namespace

BarrelReport Builder::two_sided(size_t b) {
  const BarrelPlan& p = plan_.barrels[b];
  const std::string name = "barrel " + std::to_string(b + 1) + " between caps " +
                           std::to_string(p.upper) + " and " + std::to_string(p.lower);
  if (!mesher_) fail(vid_, name + " has subcaps on both ends and needs a polygon mesher");
  BarrelInput bin;
  std::vector<int> lower_nodes;
  const Barrel barrel = ribs(b, bin, lower_nodes);
  const size_t B = barrel.ribs.size();
  const size_t J = static_cast<size_t>(barrel.layers);

  // Rings and the least-squares maps between the ends (sec. 6.1).
  std::vector<Vec3> up_ring, lo_ring;
  std::vector<size_t> starts;
  for (const auto& loop : bin.upper_loops) {
    starts.push_back(up_ring.size());
    for (size_t k = 0; k < loop.size(); ++k) {
      const auto& rib = barrel.ribs[up_ring.size()];
      up_ring.push_back(db_.node(rib.front()));
      lo_ring.push_back(db_.node(rib.back()));
    }
  }
  const AffineMap to_lower = least_squares_map(up_ring.data(), lo_ring.data(), B, starts);
  const AffineMap to_upper = least_squares_map(lo_ring.data(), up_ring.data(), B, starts);
  if (!to_lower.ok || !to_upper.ok) fail(vid_, name + ": the least-squares map between its rings is singular");
  const Vec3 d = (to_lower.to_centre - to_lower.from_centre).normalized();
  Vec3 e = Vec3::UnitX();
  if (std::abs(d.x()) > 0.6) e = std::abs(d.y()) < std::abs(d.z()) ? Vec3::UnitY() : Vec3::UnitZ();
  const Vec3 u = (e - e.dot(d) * d).normalized();
  const Vec3 v = d.cross(u);  // u x v = d: counter-clockwise about the sweep direction
  auto plane = [&](const Vec3& x) { return Vec2(x.dot(u), x.dot(v)); };

  // The two ends as subcaps (EntityMesh-local node ids).
  BarrelEnds ends;
  auto add_loops = [&](int surface, int end, std::vector<Subcap>& list, int id) {
    Subcap real{id, {}};
    const auto loops = loop_nodes(model_, db_, vid_, surface);
    for (size_t k = 0; k < loops.size(); ++k) {
      std::vector<int> l;
      for (int g : loops[k]) {
        const int n = existing(g);
        l.push_back(n);
        const Vec3& x = out_.coords[static_cast<size_t>(n)];
        ends.xy[n] = plane(end == 0 ? x : to_upper.apply(x));
      }
      real.loops.push_back(l);
    }
    orient(real, ends.xy);
    list.push_back(real);
  };
  add_loops(p.upper, 0, ends.upper, 1);
  add_loops(p.lower, 1, ends.lower, 2);
  // Inflowing virtual subcaps: the loops of the real caps they fill.
  std::map<int, int> virtual_of_cap;  // subcap id -> barrel index (with a mesh)
  std::map<int, std::vector<int>> region_up, region_lo;  // from-middle barrel -> footprint loop
  auto add_virtual = [&](const std::vector<int>& inflow, int surface, std::vector<Subcap>& list, int base) {
    const auto loops = loop_nodes(model_, db_, vid_, surface);
    const auto& geo = model_.surface(surface).loops;
    const int end = &list == &ends.upper ? 0 : 1;
    for (int i : inflow) {
      const auto curves = lower_curves(plan_.barrels[static_cast<size_t>(i)]);
      Subcap s{base + i, {}};
      for (size_t k = 0; k < loops.size(); ++k) {
        if (!curves.count(geo[k].uses.front().curve)) continue;
        std::vector<int> l;
        for (int g : loops[k]) l.push_back(existing(g));
        s.loops.push_back(l);
      }
      if (plan_.barrels[static_cast<size_t>(i)].flush) {
        // Beside the real cap (a step flush with a wall): its rim, whose
        // nodes on the wall are in no loop of the real cap.
        s.loops.clear();
        for (const auto& rim : virtual_[static_cast<size_t>(i)].rim) {
          std::vector<int> l;
          for (int g : rim) {
            const int n = existing(g);
            const Vec3& x = out_.coords[static_cast<size_t>(n)];
            ends.xy[n] = plane(end == 0 ? x : to_upper.apply(x));
            l.push_back(n);
          }
          s.loops.push_back(l);
        }
      }
      orient(s, ends.xy);
      list.push_back(s);
      if (plan_.barrels[static_cast<size_t>(i)].from_middle) {
        (&list == &ends.upper ? region_up : region_lo)[i] = s.loops.front();
      } else {
        virtual_of_cap[s.id] = i;
      }
    }
  };
  add_virtual(p.inflow, p.upper, ends.upper, 100);
  add_virtual(p.lower_inflow, p.lower, ends.lower, 100000);
  for (const auto& rib : barrel.ribs) ends.ribs.push_back({existing(rib.front()), existing(rib.back())});
  ends.xy[kSentinel] = Vec2::Zero();

  const ImprintResult imp = imprint_subcaps(ends);
  if (!imp.ok) {
    fail(vid_, name + ": subcap imprinting failed (" + imp.why +
                   "); subcaps arriving on both ends overlap, an intersection (sec. 5.3) that is "
                   "resolved only on value types so far: move or webcut the appendages");
  }
  for (const auto& [id, i] : virtual_of_cap) {
    bool kept = false;
    for (const auto& [ua, lb] : imp.matches) kept = kept || ua == id || lb == id;
    if (!kept) {
      fail(vid_, name + ": the virtual subcap of barrel " + std::to_string(i + 1) +
                     " was split by imprinting (overlapping subcaps, sec. 5.3); not supported end to end");
    }
  }
  std::set<int> upper_nodes;
  for (const Subcap& s : imp.ends.upper) {
    for (const auto& l : s.loops) upper_nodes.insert(l.begin(), l.end());
  }
  std::map<int, int> down, up;  // imprint ids across the ribs
  for (const auto& [a, z] : imp.ends.ribs) {
    down[a] = z;
    up[z] = a;
  }
  // Imprint ids -> EntityMesh-local nodes: new upper nodes lie on the upper
  // cap (interior ribs from existing lower nodes, projected up).
  const auto upper_geometry = model_.surface(p.upper).geometry;
  const auto lower_geometry = model_.surface(p.lower).geometry;
  // Which from-middle footprint (barrel index) a 2D point lies in, or -1.
  auto region_of = [&](const std::map<int, std::vector<int>>& regions, const Vec2& x) {
    for (const auto& [i, loop] : regions) {
      if (detail::point_in_loop(x, loop, imp.ends.xy)) return i;
    }
    return -1;
  };
  // Onto a real cap; a point over a flush subcap (beside the cap, outside its
  // parameter box, where the projection clamps) stays where it was placed.
  auto flush_at = [&](const std::map<int, std::vector<int>>& regions, const Vec2& x) {
    const int i = region_of(regions, x);
    return i >= 0 && plan_.barrels[static_cast<size_t>(i)].flush;
  };
  auto onto_upper = [&](const Vec3& x) {
    return flush_at(region_up, plane(x)) ? x : upper_geometry->project(x).point;
  };
  auto onto_lower = [&](const Vec3& x) {
    return flush_at(region_lo, plane(to_upper.apply(x))) ? x : lower_geometry->project(x).point;
  };
  // A new node at x on the upper end: on the real cap, or inside a virtual
  // footprint of a barrel meshed from the middle (then a volume node).
  auto add_upper = [&](const Vec3& x) {
    return region_of(region_up, plane(x)) >= 0 ? out_.add(x) : out_.add_owned(x, {2, p.upper});
  };
  std::map<int, int> local;
  std::set<int> on_upper;  // nodes made here on the upper end (movable by the smooth)
  auto upper_local = [&](int id) {
    if (id < kSentinel) return id;
    auto it = local.find(id);
    if (it != local.end()) return it->second;
    const auto dn = down.find(id);
    if (dn == down.end() || dn->second >= kSentinel) {
      fail(vid_, name + ": an imprinted upper node has no rib to an existing lower node");
    }
    const Vec3 x = onto_upper(to_upper.apply(out_.coords[static_cast<size_t>(dn->second)]));
    const int n = add_upper(x);
    local[id] = n;
    on_upper.insert(n);
    return n;
  };

  // Cap stacks (sec. 6.1): the upper end's elements, one stack at a time;
  // quads and (wedge / mixed mode) triangles alike.
  CapFaces<4> cap_quads;
  CapFaces<3> cap_tris;
  VirtualCap upper_surface;                // the part that is the real upper cap
  std::map<int, int> fixed;                // upper local node -> existing lower local node
  const double level = to_lower.from_centre.dot(d);
  for (const auto& [ua, lb] : imp.matches) {
    const Subcap* su = nullptr;
    for (const Subcap& s : imp.ends.upper) {
      if (s.id == ua) su = &s;
    }
    if (virtual_of_cap.count(ua)) {  // an inflowing subcap on the upper end: its own mesh
      const VirtualCap& vc = virtual_[static_cast<size_t>(virtual_of_cap.at(ua))];
      for (const auto& q : vc.quads) cap_quads.add(q, false, -1);
      for (const auto& t : vc.tris) cap_tris.add(t, false, -1);
      continue;
    }
    if (virtual_of_cap.count(lb)) {  // a subcap arriving on the lower end: project it up
      const VirtualCap& vc = virtual_[static_cast<size_t>(virtual_of_cap.at(lb))];
      std::map<int, int> image;
      auto lift = [&](auto f) {
        for (auto& w : f) {
          auto it = image.find(w);
          if (it == image.end()) {
            int n;
            if (up.count(w)) {
              n = upper_local(up.at(w));
            } else {
              const Vec3 x = onto_upper(to_upper.apply(out_.coords[static_cast<size_t>(w)]));
              n = out_.add_owned(x, {2, p.upper});
              on_upper.insert(n);
            }
            it = image.emplace(w, n).first;
            fixed[n] = w;
          }
          w = it->second;
        }
        return reversed(f);  // it was made sweeping the other way
      };
      for (const auto& q : vc.quads) {
        cap_quads.add(lift(q), true, -1);
        upper_surface.quads.push_back(cap_quads.faces.back());
      }
      for (const auto& t : vc.tris) {
        cap_tris.add(lift(t), true, -1);
        upper_surface.tris.push_back(cap_tris.faces.back());
      }
      continue;
    }
    // An imprinted piece of the real upper cap: the polygon mesher.
    std::vector<std::vector<Eigen::Vector2d>> loops;
    std::vector<int> boundary;
    for (const auto& l : su->loops) {
      loops.emplace_back();
      for (int id : l) {
        loops.back().push_back(imp.ends.xy.at(id));
        boundary.push_back(upper_local(id));
      }
    }
    scheme::QuadMesh2D m;
    try {
      m = mesher_->mesh(loops);
    } catch (const std::exception& ex) {
      fail(vid_, name + ": meshing the imprinted part of cap " + std::to_string(p.upper) + ": " + ex.what());
    }
    // The stack this piece belongs to: inside a from-middle footprint on
    // either end (a point inside its first element decides).
    int up_region = -1, lo_region = -1;
    if (!m.quads.empty() || !m.tris.empty()) {
      Vec2 c = Vec2::Zero();
      if (!m.quads.empty()) {
        for (int k : m.quads.front()) c += m.points[static_cast<size_t>(k)] / 4.0;
      } else {
        for (int k : m.tris.front()) c += m.points[static_cast<size_t>(k)] / 3.0;
      }
      up_region = region_of(region_up, c);
      lo_region = region_of(region_lo, c);
    }
    std::vector<int> node(m.points.size());
    for (size_t k = 0; k < m.points.size(); ++k) {
      if (k < boundary.size()) {
        node[k] = boundary[k];
      } else {
        const Vec3 x = onto_upper(u * m.points[k].x() + v * m.points[k].y() + level * d);
        node[k] = up_region >= 0 ? out_.add(x) : out_.add_owned(x, {2, p.upper});
        on_upper.insert(node[k]);
      }
    }
    VirtualCap& home = up_region >= 0 ? virtual_[static_cast<size_t>(up_region)]  // swept out later
                                      : upper_surface;
    for (const auto& q : m.quads) {
      cap_quads.add(renumbered(q, node), false, lo_region);
      home.quads.push_back(cap_quads.faces.back());
    }
    for (const auto& t : m.tris) {
      cap_tris.add(renumbered(t, node), false, lo_region);
      home.tris.push_back(cap_tris.faces.back());
    }
  }
  // The subcaps forming the real upper cap are smoothed together (sec. 6.1).
  {
    std::map<int, int> idx;
    std::vector<Vec3> pts;
    std::vector<char> movable;
    VirtualCap all = upper_surface;
    for (const auto& [i, loop] : region_up) {
      const VirtualCap& vc = virtual_[static_cast<size_t>(i)];
      all.quads.insert(all.quads.end(), vc.quads.begin(), vc.quads.end());
      all.tris.insert(all.tris.end(), vc.tris.begin(), vc.tris.end());
    }
    auto local_face = [&](auto f) {
      for (auto& k : f) {
        auto [it, added] = idx.emplace(k, static_cast<int>(pts.size()));
        if (added) {
          pts.push_back(out_.coords[static_cast<size_t>(k)]);
          movable.push_back(on_upper.count(k) ? 1 : 0);
        }
        k = it->second;
      }
      return f;
    };
    std::vector<mesh::Quad> quads;
    std::vector<mesh::Tri> tris;
    for (const auto& q : all.quads) quads.push_back(local_face(q));
    for (const auto& t : all.tris) tris.push_back(local_face(t));
    auto project = [&](const Vec3& x) { return onto_upper(x); };
    if (smooth_cap(pts, quads, tris, movable, d, project)) {
      for (const auto& [n, i] : idx) out_.coords[static_cast<size_t>(n)] = pts[static_cast<size_t>(i)];
    }
  }
  // Interior ribs ending on existing lower nodes are fixed targets.
  for (const auto& [a, z] : imp.ends.ribs) {
    if (z < kSentinel && upper_nodes.count(a)) fixed.emplace(upper_local(a), z);
  }

  // The sweep of the upper end (sec. 6.2-6.3).
  SweepInput in;
  in.layers = static_cast<int>(J);
  in.boundary = static_cast<int>(B);
  in.loop_starts = starts;
  std::vector<int> cap_entity;
  std::unordered_map<int, int> cap_index;
  auto index_of = [&](int n) {
    auto [it, added] = cap_index.emplace(n, static_cast<int>(cap_entity.size()));
    if (added) cap_entity.push_back(n);
    return it->second;
  };
  for (const auto& rib : barrel.ribs) index_of(existing(rib.front()));
  for (const auto& q : cap_quads.faces) in.quads.push_back({index_of(q[0]), index_of(q[1]), index_of(q[2]), index_of(q[3])});
  for (const auto& t : cap_tris.faces) in.tris.push_back({index_of(t[0]), index_of(t[1]), index_of(t[2])});
  in.cap_nodes = static_cast<int>(cap_entity.size());
  in.has_fixed_target.assign(cap_entity.size(), 0);
  in.fixed_target.assign(cap_entity.size(), Vec3::Zero());
  for (size_t i = 0; i < cap_entity.size(); ++i) {
    in.source.push_back(out_.coords[static_cast<size_t>(cap_entity[i])]);
    const auto f = fixed.find(cap_entity[i]);
    if (i >= B && f != fixed.end()) {
      in.has_fixed_target[i] = 1;
      in.fixed_target[i] = out_.coords[static_cast<size_t>(f->second)];
    }
  }
  for (const auto& rib : barrel.ribs) {
    for (int g : rib) in.ribs.push_back(db_.node(g));
  }
  in.project_target = onto_lower;
  const SweepResult sweep = sweep_barrel(in);
  if (!sweep.ok) fail(vid_, name + ": " + sweep.why);

  const size_t n = cap_entity.size();
  std::vector<int> node(sweep.points.size());
  for (size_t j = 0; j <= J; ++j) {
    for (size_t i = 0; i < n; ++i) {
      const size_t q = j * n + i;
      if (i < B) {
        node[q] = existing(barrel.ribs[i][j]);
      } else if (j == 0) {
        node[q] = cap_entity[i];
      } else if (j == J && in.has_fixed_target[i]) {
        node[q] = fixed.at(cap_entity[i]);
      } else if (j == J) {
        const bool virtual_node = region_of(region_lo, plane(in.source[i])) >= 0;
        node[q] = virtual_node ? out_.add(sweep.points[q]) : out_.add_owned(sweep.points[q], {2, p.lower});
      } else {
        node[q] = out_.add(sweep.points[q]);
      }
    }
  }
  for (const auto& h : sweep.hexes) out_.hexes.push_back(renumbered(h, node));
  for (const auto& w : sweep.wedges) out_.wedges.push_back(renumbered(w, node));
  // Surface meshes of the two real caps, with their natural normals.
  const bool upper_outward = model_.sense_in(p.upper, vid_) == geom::Sense::Forward;
  for (const auto& f : upper_surface.quads) out_.surface_quads[p.upper].push_back(upper_outward ? reversed(f) : f);
  for (const auto& f : upper_surface.tris) out_.surface_tris[p.upper].push_back(upper_outward ? reversed(f) : f);
  const bool lower_outward = model_.sense_in(p.lower, vid_) == geom::Sense::Forward;
  const size_t top = J * n;
  auto place_lower = [&](const auto& cap, const auto& local_faces, auto& surface, auto virtual_faces) {
    for (size_t k = 0; k < local_faces.size(); ++k) {
      if (cap.arriving[k]) continue;  // the face of an arriving subcap, not of the real lower cap
      auto f = local_faces[k];
      for (auto& c : f) c = node[top + static_cast<size_t>(c)];
      if (cap.lower_region[k] >= 0) {  // a virtual subcap swept out later (from the middle)
        virtual_faces(static_cast<size_t>(cap.lower_region[k])).push_back(f);
        continue;
      }
      surface.push_back(lower_outward ? f : reversed(f));
    }
  };
  place_lower(cap_quads, in.quads, out_.surface_quads[p.lower],
              [&](size_t i) -> std::vector<mesh::Quad>& { return virtual_[i].quads; });
  place_lower(cap_tris, in.tris, out_.surface_tris[p.lower],
              [&](size_t i) -> std::vector<mesh::Tri>& { return virtual_[i].tris; });
  if (out_.surface_tris[p.lower].empty()) out_.surface_tris.erase(p.lower);
  return {p.upper, barrel.layers, sweep.min_scaled_jacobian, sweep.smoothed, imp.steps};
}

}  // namespace cooperage::cooper::detail
