// Imprinting across all barrels (Blacker 1996, sec. 5: "iteratively
// matching and imprinting all subcaps to produce stacks of caps"). Each
// barrel's two ends go through imprint_subcaps() in its chart; a virtual
// cap split in one barrel is split in the barrel on its other side too
// (the pieces are shared), so the barrels are imprinted again until no
// subcap changes. New nodes get positions on their end (projected onto a
// real cap); a cap meshed beforehand must never be cut.
#include "framework/core/text.h"
#include "schemes/cooper/chart_warp.h"
#include "schemes/cooper/imprint_debug.h"
#include "schemes/cooper/imprint_polygons.h"
#include "schemes/cooper/imprint_site.h"
#include "schemes/cooper/sweep_state.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <set>
#include <string>

namespace cooperage::cooper::detail {
namespace {

// The lower end of barrel b onto its upper end's chart, exactly at the ribs.
ChartWarp warp_of(const SweepState& s, size_t b) {
  const BarrelState& st = s.barrels[b];
  std::vector<std::pair<Vec2, Vec2>> ribs;
  for (const auto& [up, low] : st.rib_pairs)
    ribs.push_back({s.plane(b, st.to_upper.apply(s.pos(low))), s.plane(b, s.pos(up))});
  return ChartWarp(ribs);
}

// One barrel's ends as value types, in its chart.
BarrelEnds ends_of(const SweepState& s, size_t b, const ChartWarp& warp) {
  BarrelEnds ends;
  const BarrelState& st = s.barrels[b];
  for (const Piece& p : s.pieces) {
    if (!p.alive) continue;
    const int end = p.upper_of == static_cast<int>(b)   ? 0
                    : p.lower_of == static_cast<int>(b) ? 1
                                                        : -1;
    if (end < 0) continue;
    for (const auto& l : p.loops) {
      for (int n : l) {
        const Vec3& x = s.pos(n);
        ends.xy[n] = end == 0 ? s.plane(b, x) : warp.forward(s.plane(b, st.to_upper.apply(x)));
        if (s.out.global[static_cast<size_t>(n)] >= 0) ends.fixed.insert(n);
      }
    }
  }
  for (const Piece& p : s.pieces) {
    if (!p.alive) continue;
    const bool upper = p.upper_of == static_cast<int>(b);
    if (!upper && p.lower_of != static_cast<int>(b)) continue;
    (upper ? ends.upper : ends.lower).push_back({p.id, oriented_loops(p.loops, ends.xy)});
  }
  ends.ribs = st.rib_pairs;
  return ends;
}

// Where a new node of a virtual cap lies off the plane of its end: an end
// is flat only when its ring is (a virtual cap next to an inclined cap, a
// lug's conical underside, follows the cone's rim). The ring's offsets from
// the plane (upper end) or from the map of the upper ring (lower end),
// weighted by inverse distance (power 3) in the chart. A node placed on
// the mean plane instead lay 1 mm below the cone under it, and the hex
// between them inverted (gmsh_918_pump_carter_sup). On a lower end the
// height along d is the lower ring's own, measured from the node's `base`:
// through the map of the upper end's mean plane, a node under a curved
// upper end (a dome's slice beside a slot) inherited the map's fit of that
// curve and fell up to 0.9 under a flat lower ring, inverting a hex below.
// With the offset, the barrel's depth along d there: the ribs' drops from
// upper to lower end, weighted alike.
struct RingBlend {
  Vec3 offset = Vec3::Zero();
  double depth = 0;
};

RingBlend ring_offset(const SweepState& s, size_t b, const Vec2& at, bool lower, const Vec3& base) {
  const BarrelState& st = s.barrels[b];
  RingBlend sum;
  double wsum = 0;
  for (const auto& rib : st.ribs) {
    const Vec3& top = s.db.node(rib.front());
    const Vec3& bottom = s.db.node(rib.back());
    const Vec2 q = s.plane(b, top);
    Vec3 offset = (top.dot(st.d) - st.level) * st.d;
    if (lower) {
      offset = bottom - st.to_lower.apply(top);
      offset += ((bottom - base).dot(st.d) - offset.dot(st.d)) * st.d;
    }
    const double drop = (bottom - top).dot(st.d);
    const double d2 = (q - at).squaredNorm();
    if (d2 <= 0) return {offset, drop};
    const double w = 1.0 / (d2 * std::sqrt(d2));
    sum.offset += w * offset;
    sum.depth += w * drop;
    wsum += w;
  }
  if (wsum > 0) return {sum.offset / wsum, sum.depth / wsum};
  return {};
}

// Applies one barrel's imprint result; true when a subcap or rib changed.
bool apply(SweepState& s, size_t b, const BarrelEnds& in, const ImprintResult& r,
           const ChartWarp& warp) {
  BarrelState& st = s.barrels[b];
  std::set<int> upper_nodes, lower_nodes;
  for (const Subcap& c : r.ends.upper) {
    for (const auto& l : c.loops) upper_nodes.insert(l.begin(), l.end());
  }
  for (const Subcap& c : r.ends.lower) {
    for (const auto& l : c.loops) lower_nodes.insert(l.begin(), l.end());
  }
  // The piece (input id) a node of the result lies on, for its surface.
  std::map<int, int> piece_of_node;
  for (const auto* list : {&r.ends.upper, &r.ends.lower}) {
    for (const Subcap& c : *list) {
      const auto o = r.origin.find(c.id);
      const int origin = o == r.origin.end() ? c.id : o->second;
      for (const auto& l : c.loops) {
        for (int n : l) piece_of_node.emplace(n, origin);
      }
    }
  }
  std::map<int, int> rib_top;  // lower node -> upper node, result ids
  for (const auto& [a, z] : r.ends.ribs) rib_top.emplace(z, a);
  std::map<int, int> remap;
  bool changed = false;
  std::function<int(int)> node = [&](int id) {
    if (in.xy.count(id)) return id;
    const auto it = remap.find(id);
    if (it != remap.end()) return it->second;
    const auto at = r.ends.xy.find(id);
    const auto on = piece_of_node.find(id);
    if (at == r.ends.xy.end() || on == piece_of_node.end()) {
      // A rib of the result ending on no subcap's loop (seed 4 case 118 of
      // the campaign, swept upwards): a step lost a loop it had ribbed.
      fail(s.vid, s.barrel_name(b) + ": subcap imprinting left a rib ending on no subcap");
    }
    const Vec2& p2 = at->second;
    const bool lower = lower_nodes.count(id) > 0;
    const Vec2 q = lower ? warp.inverse(p2) : p2;
    Vec3 x = st.u * q.x() + st.v * q.y() + st.level * st.d;
    if (lower) x = st.to_lower.apply(x);
    const Piece& p = s.pieces[static_cast<size_t>(on->second)];
    if (!p.cap) {
      const RingBlend ring = ring_offset(s, b, p2, lower, x);
      x += ring.offset;
      // A virtual lower node keeps half the local depth below the top of its
      // rib: the ring's heights rising beside a lug's cone lifted a pocket
      // floor's rib end above the floor, and the hexes there turned inside out.
      const auto top = rib_top.find(id);
      if (lower && top != rib_top.end()) {
        const Vec3 up = s.pos(node(top->second));
        const double least = 0.5 * ring.depth;
        const double drop = (x - up).dot(st.d);
        if (least > 0 && drop < least) x += (least - drop) * st.d;
      }
    }
    int n;
    if (p.cap) {
      x = s.model.surface(p.cap).geometry->project(x).point;
      n = s.out.add_owned(x, {2, p.cap});
    } else {
      n = s.out.add(x);
    }
    remap[id] = n;
    changed = true;
    return n;
  };
  auto loops_of = [&](const Subcap& c) {
    std::vector<std::vector<int>> out;
    for (const auto& l : c.loops) {
      out.emplace_back();
      for (int n : l) out.back().push_back(node(n));
    }
    return out;
  };
  std::set<int> input_ids;
  for (const auto* list : {&in.upper, &in.lower}) {
    for (const Subcap& c : *list) input_ids.insert(c.id);
  }
  std::set<int> kept;
  std::map<int, int> new_piece;  // imprint subcap id -> piece id
  for (const auto* list : {&r.ends.upper, &r.ends.lower}) {
    for (const Subcap& c : *list) {
      auto loops = loops_of(c);
      if (input_ids.count(c.id)) {
        Piece& p = s.pieces[static_cast<size_t>(c.id)];
        std::set<int> before, after;
        for (const auto& l : p.loops) before.insert(l.begin(), l.end());
        for (const auto& l : loops) after.insert(l.begin(), l.end());
        if (before != after || p.loops.size() != loops.size()) {
          if (p.premeshed) {
            fail(s.vid,
                 s.barrel_name(b) + ": imprinting cuts cap " + std::to_string(p.cap) +
                     ", which was meshed by its surface scheme (the plan did not foresee it)");
          }
          changed = true;
        }
        p.loops = std::move(loops);
        kept.insert(c.id);
        new_piece[c.id] = c.id;
        continue;
      }
      const auto o = r.origin.find(c.id);
      if (o == r.origin.end())
        fail(s.vid, s.barrel_name(b) + ": an imprinted subcap has no origin");
      const Piece& parent = s.pieces[static_cast<size_t>(o->second)];
      if (parent.premeshed) {
        fail(s.vid, s.barrel_name(b) + ": imprinting cuts cap " + std::to_string(parent.cap) +
                        ", which was meshed by its surface scheme (the plan did not foresee it)");
      }
      Piece p;
      p.id = static_cast<int>(s.pieces.size());
      p.cap = parent.cap;
      p.interface = parent.interface;
      p.upper_of = parent.upper_of;
      p.lower_of = parent.lower_of;
      p.loops = std::move(loops);
      s.pieces.push_back(std::move(p));
      new_piece[c.id] = static_cast<int>(s.pieces.size()) - 1;
      changed = true;
    }
  }
  for (const auto* list : {&in.upper, &in.lower}) {
    for (const Subcap& c : *list) {
      if (!kept.count(c.id)) {
        s.pieces[static_cast<size_t>(c.id)].alive = false;
        changed = true;
      }
    }
  }
  std::vector<std::pair<int, int>> ribs;
  for (const auto& [a, z] : r.ends.ribs) ribs.push_back({node(a), node(z)});
  if (ribs != st.rib_pairs) changed = true;
  st.rib_pairs = std::move(ribs);
  st.matches.clear();
  for (const auto& [a, z] : r.matches) {
    const auto u = new_piece.find(a), l = new_piece.find(z);
    if (u == new_piece.end() || l == new_piece.end())
      fail(s.vid, s.barrel_name(b) + ": subcap imprinting matched a subcap it did not keep");
    st.matches.push_back({u->second, l->second});
  }
  st.steps.insert(st.steps.end(), r.steps.begin(), r.steps.end());
  return changed;
}

// Where the subcaps no step could resolve lie, for a person: " on surfaces
// 3, 5 (upper end) and 9, a virtual cap (lower end)"; empty when none.
std::string unmatched_surfaces(const SweepState& s, const ImprintResult& r) {
  std::string out;
  for (size_t e = 0; e < 2; ++e) {
    std::set<int> caps;
    for (int id : r.unmatched[e]) {
      // A subcap cut during this imprinting names the piece it came from.
      for (auto o = r.origin.find(id); o != r.origin.end(); o = r.origin.find(id)) id = o->second;
      if (id >= 0 && static_cast<size_t>(id) < s.pieces.size())
        caps.insert(s.pieces[static_cast<size_t>(id)].cap);
    }
    if (caps.empty()) continue;
    std::string list;
    for (int c : caps) {
      if (c == 0) continue;
      list += (list.empty() ? "" : ", ") + std::to_string(c);
    }
    const bool virtual_cap = caps.count(0) > 0;
    std::string what =
        list.empty() ? "" : (caps.size() - virtual_cap > 1 ? "surfaces " : "surface ") + list;
    if (virtual_cap) what += std::string(what.empty() ? "" : ", ") + "a virtual cap";
    out += std::string(out.empty() ? " on " : " and ") + what +
           (e == 0 ? " (upper end)" : " (lower end)");
  }
  return out;
}

// Where an imprint stopped, in model coordinates: "; near (1.2, 3.4, 5.6)",
// the closest approach of the rims left unmatched on its two ends (a
// crossing or a near miss: both where features meet). `in`: the ends given
// (their nodes are the sweep's).
std::string failure_site(const SweepState& s, const BarrelEnds& in, const ImprintResult& r) {
  const ImprintSite site = narrowest_gap(r);
  if (site.node < 0) return "";
  // A node the imprint made has no 3D position yet: the given node nearest it.
  int known = site.node;
  if (!in.xy.count(known)) {
    if (in.xy.empty()) return "";
    double best = std::numeric_limits<double>::infinity();
    for (const auto& [n, p] : in.xy) {
      const double d = (p - site.at).norm();
      if (d < best) {
        best = d;
        known = n;
      }
    }
  }
  const Vec3& x = s.pos(known);
  return "; near " + point_text(x.x(), x.y(), x.z());
}

}  // namespace

// cite: Blacker 1996, sec. 5 (5.1 matching, 5.2 subtraction, 5.3
// intersection, 5.4 seaming, 5.5 self-intersection), repeated over the
// barrels until every subcap is matched in every barrel.
void imprint_barrels(SweepState& s) {
  ImprintOptions options;
  options.even_parity = s.plan.elements != Elements::Wedge;
  options.trace_steps = imprint_debug_steps();
  const size_t passes = 4 + 2 * s.barrels.size();
  for (size_t pass = 0; pass < passes; ++pass) {
    bool changed = false;
    for (size_t b = 0; b < s.barrels.size(); ++b) {
      // The affine chart first; where imprinting fails in it, the chart
      // warped along the ribs (chart_warp.h), kept for the barrel's later
      // passes once it succeeds. Warping every barrel moved the minima of
      // a quarter of the campaign's parts, as many down as up, so it is
      // not the default.
      BarrelState& st = s.barrels[b];
      ChartWarp warp = st.warped_chart ? warp_of(s, b) : ChartWarp();
      BarrelEnds ends = ends_of(s, b, warp);
      ImprintResult r = imprint_subcaps(ends, options);
      if (!r.ok && !st.warped_chart) {
        ChartWarp warped = warp_of(s, b);
        if (warped.active()) {
          BarrelEnds warped_ends = ends_of(s, b, warped);
          ImprintResult warped_r = imprint_subcaps(warped_ends, options);
          if (warped_r.ok) {
            st.warped_chart = true;
            warp = std::move(warped);
            ends = std::move(warped_ends);
            r = std::move(warped_r);
          }
        }
      }
      if (!r.ok) {
        write_imprint_debug("volume" + std::to_string(s.vid) + "-barrel" + std::to_string(b + 1),
                            ends, r);
        fail(s.vid, s.barrel_name(b) + ": subcap imprinting failed" + unmatched_surfaces(s, r) +
                        " (" + r.summary + failure_site(s, ends, r) + ")");
      }
      try {
        changed = apply(s, b, ends, r, warp) || changed;
      } catch (const MeshingError&) {
        // An imprint the sweep cannot take (a cap meshed beforehand cut):
        // its ends and result, as for an imprint that failed.
        write_imprint_debug("volume" + std::to_string(s.vid) + "-barrel" + std::to_string(b + 1),
                            ends, r);
        throw;
      }
    }
    if (!changed) return;
  }
  fail(s.vid, "subcap imprinting did not settle after " + std::to_string(passes) +
                  " passes over the barrels");
}

}  // namespace cooperage::cooper::detail
