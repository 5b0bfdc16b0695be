// Barrel formation on the meshed sides (Blacker 1996, sec. 4): each barrel
// of the plan, highest first, starts its ribs on the boundary of its upper
// cap -- its real caps and the virtual caps left by the barrels above,
// merged (Fig. 8d) -- and advances them exactly its layer count down the
// side meshes (the count the interval assignment gave its level classes).
// The rib ends, with the lower real caps cut out, are the virtual caps it
// leaves to the barrels below. Then the charts (both ends of a barrel in
// one plane, sec. 5) and the subcaps.
#include "schemes/cooper/form_barrels.h"
#include "schemes/cooper/loop_nodes.h"
#include "schemes/cooper/sweep_state.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace cooperage::cooper::detail {
namespace {

long intervals_of(const SweepState& s, int curve) {
  if (!s.db.curve_meshed(curve)) fail(s.vid, "curve " + std::to_string(curve) + " is not meshed");
  return static_cast<long>(s.db.curve_nodes(curve).size()) - 1;
}

long value(const SweepState& s, const std::map<int, int>& expr) {
  long v = 0;
  for (const auto& [curve, k] : expr) v += k * intervals_of(s, curve);
  return v;
}

// Faces a MeshDB node lies on (its owner surface, or the surfaces of its
// owner curve).
std::vector<int> node_faces(const SweepState& s, int g) {
  const mesh::NodeOwner& o = s.db.owner(g);
  if (o.dim == 2) return {o.id};
  if (o.dim == 1) return s.model.curve(o.id).surfaces;
  return {};
}

// The chart's u axis follows the part, not the global axes, so a moved part
// is imprinted in the moved chart and gives the moved mesh: towards the
// upper ring's first node (its order comes from the topology), or the first
// node off the axis when that one lies on it.
Vec3 chart_u_hint(const std::vector<Vec3>& ring, const Vec3& centre, const Vec3& d) {
  double reach = 0;
  for (const Vec3& p : ring) {
    const Vec3 r = p - centre;
    reach = std::max(reach, (r - r.dot(d) * d).norm());
  }
  for (const Vec3& p : ring) {
    const Vec3 r = p - centre;
    const Vec3 across = r - r.dot(d) * d;
    if (across.norm() > 0.1 * reach) return across.normalized();
  }
  return std::abs(d.x()) > 0.6 ? Vec3::UnitY() : Vec3::UnitX();
}

}  // namespace

std::string SweepState::barrel_name(size_t b) const {
  const BarrelNode& n = plan.tree.barrels[b];
  std::string name = "barrel " + std::to_string(b + 1) + " (sides ";
  for (size_t k = 0; k < n.sides.size() && k < 4; ++k)
    name += (k ? ", " : "") + std::to_string(n.sides[k]);
  return name + (n.sides.size() > 4 ? ", ...)" : ")");
}

// cite: Blacker 1996, sec. 4 (rib progression, Figure 7; the lower cap
// re-formed with the caps reached, Figure 8).
void form_ribs(SweepState& s) {
  const VolumePlan& p = s.plan;
  const BarrelTree& tree = p.tree;
  std::vector<size_t> extra;
  const auto lambda = layer_potentials(p.lattice, p.order, &extra);
  for (size_t i : extra) {
    const LinkChain& c = p.lattice.chains[i];
    long sum = 0;
    for (int curve : c.curves) sum += intervals_of(s, curve);
    const long span = value(s, lambda[static_cast<size_t>(p.order.chain_upper[i])]) -
                      value(s, lambda[static_cast<size_t>(p.order.chain_lower[i])]);
    if (sum != span) {
      fail(s.vid, "the linking curves of side surface " + std::to_string(c.face) + " have " +
                      std::to_string(sum) + " intervals where the barrels need " +
                      std::to_string(span));
    }
  }
  std::set<int> cap_nodes;
  for (const auto& [cap, where] : tree.cap_end) {
    for (const auto& loop : loop_nodes(s.model, s.db, s.vid, cap))
      cap_nodes.insert(loop.begin(), loop.end());
  }
  s.barrels.assign(tree.barrels.size(), {});
  s.interface_loops.assign(tree.interfaces.size(), {});
  std::set<int> used;  // side nodes in ribs so far
  for (size_t b = 0; b < tree.barrels.size(); ++b) {
    const BarrelNode& node = tree.barrels[b];
    BarrelState& st = s.barrels[b];
    const long top = value(s, lambda[static_cast<size_t>(node.upper_classes.front())]);
    const long bottom = value(s, lambda[static_cast<size_t>(node.lower_classes.front())]);
    for (int c : node.upper_classes) {
      if (value(s, lambda[static_cast<size_t>(c)]) != top)
        fail(s.vid, s.barrel_name(b) + ": its upper cap is not on one layer");
    }
    for (int c : node.lower_classes) {
      if (value(s, lambda[static_cast<size_t>(c)]) != bottom)
        fail(s.vid, s.barrel_name(b) + ": its lower cap is not on one layer");
    }
    st.layers = static_cast<int>(top - bottom);
    if (st.layers < 1)
      fail(s.vid, s.barrel_name(b) + " has " + std::to_string(st.layers) + " layers");
    // The upper cap: its pieces' loops merged (shared edges cancel).
    std::vector<std::vector<int>> loops;
    for (const EndPiece& e : node.upper) {
      if (e.cap) {
        const auto l = loop_nodes(s.model, s.db, s.vid, e.cap);
        loops.insert(loops.end(), l.begin(), l.end());
      } else {
        const auto& l = s.interface_loops[static_cast<size_t>(e.interface)];
        if (l.empty()) fail(s.vid, s.barrel_name(b) + ": the virtual cap above it was not formed");
        loops.insert(loops.end(), l.begin(), l.end());
      }
    }
    BarrelInput bin;
    bin.upper_loops = node.upper.size() == 1 ? loops : merge_loops(loops, {});
    if (bin.upper_loops.empty())
      fail(s.vid,
           s.barrel_name(b) + ": its upper subcaps do not form a cap bounded by simple loops");
    std::set<int> front;
    for (const auto& l : bin.upper_loops) front.insert(l.begin(), l.end());
    for (int g : used) {
      if (!front.count(g)) bin.blocked_nodes.push_back(g);
    }
    for (int side : node.sides) {
      if (!s.db.surface_meshed(side))
        fail(s.vid, "side surface " + std::to_string(side) + " is not meshed");
      const mesh::SurfaceMeshData& m = s.db.surface(side);
      if (!m.tris.empty())
        fail(s.vid, "side surface " + std::to_string(side) + " has triangles; ribs need quads");
      bin.side_quads.insert(bin.side_quads.end(), m.quads.begin(), m.quads.end());
    }
    bin.stop_nodes.assign(cap_nodes.begin(), cap_nodes.end());
    bin.layers = st.layers;
    const Barrel ribs = form_barrels(bin);
    if (!ribs.ok) fail(s.vid, s.barrel_name(b) + ": rib formation failed: " + ribs.why);
    st.ribs = ribs.ribs;
    size_t r = 0;
    for (const auto& l : bin.upper_loops) {
      st.loop_starts.push_back(r);
      st.upper_loops.push_back(l);
      st.lower_loops.emplace_back();
      for (size_t k = 0; k < l.size(); ++k, ++r) st.lower_loops.back().push_back(st.ribs[r].back());
    }
    for (const auto& rib : st.ribs) used.insert(rib.begin(), rib.end());
    // The virtual caps below: the rib ends without the real lower caps.
    std::vector<int> below;
    std::vector<std::vector<int>> lower_caps;
    for (const EndPiece& e : node.lower) {
      if (e.cap) {
        const auto l = loop_nodes(s.model, s.db, s.vid, e.cap);
        lower_caps.insert(lower_caps.end(), l.begin(), l.end());
      } else {
        below.push_back(e.interface);
      }
    }
    if (below.empty()) continue;
    std::vector<std::vector<int>> all = st.lower_loops;
    all.insert(all.end(), lower_caps.begin(), lower_caps.end());
    const auto virtual_loops = lower_caps.empty() ? st.lower_loops : merge_loops(all, {});
    if (virtual_loops.empty())
      fail(s.vid, s.barrel_name(b) + ": its virtual lower cap is not bounded by simple loops");
    if (below.size() == 1) {
      s.interface_loops[static_cast<size_t>(below.front())] = virtual_loops;
      continue;
    }
    // Several barrels below: each loop goes to the one whose sides or caps it touches.
    for (const auto& l : virtual_loops) {
      int owner = -1;
      for (int i : below) {
        const BarrelNode& y =
            tree.barrels[static_cast<size_t>(tree.interfaces[static_cast<size_t>(i)].below)];
        std::set<int> faces(y.sides.begin(), y.sides.end());
        for (const EndPiece& e : y.upper) {
          if (e.cap) faces.insert(e.cap);
        }
        for (int g : l) {
          for (int f : node_faces(s, g)) {
            if (faces.count(f)) owner = i;
          }
        }
      }
      if (owner < 0)
        fail(s.vid, s.barrel_name(b) + ": a loop of its virtual lower cap touches no barrel below");
      s.interface_loops[static_cast<size_t>(owner)].push_back(l);
    }
  }
}

// cite: Blacker 1996, sec. 5 (the two caps of a barrel, connected through
// its ribs, compared in one plane) and sec. 6.1 (least-squares projection).
void make_charts(SweepState& s) {
  for (size_t b = 0; b < s.barrels.size(); ++b) {
    BarrelState& st = s.barrels[b];
    std::vector<Vec3> up, lo;
    for (const auto& rib : st.ribs) {
      up.push_back(s.db.node(rib.front()));
      lo.push_back(s.db.node(rib.back()));
    }
    st.to_lower = least_squares_map(up.data(), lo.data(), up.size(), st.loop_starts);
    st.to_upper = least_squares_map(lo.data(), up.data(), lo.size(), st.loop_starts);
    if (!st.to_lower.ok || !st.to_upper.ok) {
      fail(s.vid, s.barrel_name(b) +
                      ": the least-squares map between its upper and lower rings is singular");
    }
    Vec3 d = st.to_lower.to_centre - st.to_lower.from_centre;
    if (!(d.norm() > 0)) fail(s.vid, s.barrel_name(b) + ": its two rings have one centre");
    d.normalize();
    // In a straight sweep every barrel's chart faces the sweep axis. The
    // centres' offset leans where a thin barrel's rings shift sideways (a
    // dome's slice over a countersink shrinking inward: occt_screw's first
    // barrel leaned 22 degrees, and the nodes imprinted on its lower end
    // fell 0.9 under their ring, inverting a hex below at D/25 to D/100).
    if (s.plan.down && s.plan.down->dot(d) > 0) d = s.plan.down->normalized();
    // A barrel that turns back (a ring swept half a turn or more, from one
    // end wall round to the other) has its ring centres side by side or
    // behind the way its ribs leave: a chart across that line sees the upper
    // cap edge on or from behind, and orders its elements at random or
    // inside out. Such a chart faces the upper ring instead, the way the
    // ribs leave it.
    Vec3 leave = Vec3::Zero();
    for (const auto& rib : st.ribs) {
      if (rib.size() > 1) leave += s.db.node(rib[1]) - s.db.node(rib[0]);
    }
    const Vec3 area = pseudo_area(up.data(), up.size(), st.loop_starts);
    if (area.norm() > 0 && (std::abs(area.normalized().dot(d)) < 0.5 || d.dot(leave) <= 0)) {
      d = area.normalized();
      if (d.dot(leave) < 0) d = -d;
    }
    Vec3 e = chart_u_hint(up, st.to_lower.from_centre, d);
    st.d = d;
    st.u = (e - e.dot(d) * d).normalized();
    st.v = d.cross(st.u);  // u x v = d: counter-clockwise about the sweep direction
    st.level = st.to_lower.from_centre.dot(d);
    for (const auto& rib : st.ribs)
      st.rib_pairs.push_back({s.existing(rib.front()), s.existing(rib.back())});
  }
}

void make_pieces(SweepState& s) {
  const BarrelTree& tree = s.plan.tree;
  auto local_loops = [&](const std::vector<std::vector<int>>& loops) {
    std::vector<std::vector<int>> out;
    for (const auto& l : loops) {
      out.emplace_back();
      for (int g : l) out.back().push_back(s.existing(g));
    }
    return out;
  };
  for (const auto& [cap, where] : tree.cap_end) {
    Piece pc;
    pc.id = static_cast<int>(s.pieces.size());
    pc.cap = cap;
    (where.second ? pc.upper_of : pc.lower_of) = where.first;
    pc.premeshed = s.plan.roles.scheme.count(cap) > 0;
    pc.loops = local_loops(loop_nodes(s.model, s.db, s.vid, cap));
    s.pieces.push_back(std::move(pc));
  }
  for (size_t i = 0; i < tree.interfaces.size(); ++i) {
    const auto loops = local_loops(s.interface_loops[i]);
    // One subcap per region of the virtual cap, in the chart of the barrel above.
    const size_t above = static_cast<size_t>(tree.interfaces[i].above);
    std::map<int, Vec2> xy;
    for (const auto& l : loops) {
      for (int n : l) xy[n] = s.plane(above, s.barrels[above].to_upper.apply(s.pos(n)));
    }
    for (auto& region : separate_regions(loops, xy)) {
      Piece pc;
      pc.id = static_cast<int>(s.pieces.size());
      pc.interface = static_cast<int>(i);
      pc.lower_of = tree.interfaces[i].above;
      pc.upper_of = tree.interfaces[i].below;
      pc.loops = std::move(region);
      s.pieces.push_back(std::move(pc));
    }
  }
}

}  // namespace cooperage::cooper::detail
