#include "schemes/cooper/classify_barrels.h"

#include "framework/scheme/vertex_angles.h"
#include "schemes/cooper/cap_dihedral.h"
#include "schemes/cooper/stepped_ring.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <set>
#include <sstream>

#include <Eigen/Geometry>

namespace cooperage::cooper {
namespace {

std::string join(const std::vector<int>& ids) {
  std::string s;
  for (size_t i = 0; i < ids.size(); ++i) s += (i ? ", " : "") + std::to_string(ids[i]);
  return s;
}

std::string vec_text(const geom::Vec3& v) {
  std::ostringstream s;
  s.precision(3);
  s << "(" << (std::abs(v.x()) < 5e-4 ? 0.0 : v.x()) << ", " << (std::abs(v.y()) < 5e-4 ? 0.0 : v.y())
    << ", " << (std::abs(v.z()) < 5e-4 ? 0.0 : v.z()) << ")";
  return s.str();
}

struct Face {
  int id = 0;
  int loops = 0;
  bool planar = false;
  std::set<int> curves;
  bool side_ok = false;
  double side_score = 0;
  std::string side_why;
  std::vector<scheme::LoopCorner> corners;
  geom::Vec3 normal = geom::Vec3::Zero();  // outward at the box centre
};

// A set of side faces joined by linking curves, between caps x < y.
struct Ring {
  std::vector<int> sides;  // indices into the side list
  int x = 0, y = 0;
  bool convex_x = false, convex_y = false;
  // A segment of a stepped ring (sides spanning several caps; its upper cap
  // is y) and its own linking chains.
  bool stepped = false;
  std::vector<std::vector<int>> chains;
};

int find(std::vector<int>& parent, int i) {
  while (parent[static_cast<size_t>(i)] != i) {
    parent[static_cast<size_t>(i)] = parent[static_cast<size_t>(parent[static_cast<size_t>(i)])];
    i = parent[static_cast<size_t>(i)];
  }
  return i;
}

// The 2D outline (along `axis`) of the loops of cap `cap` reached by the
// lower runs of `sides`: sampled curve points, for a priori overlap tests.
std::vector<std::vector<Eigen::Vector2d>> footprint(const geom::Model& model, int cap,
                                                   const std::set<int>& lower_curves,
                                                   const geom::Vec3& axis) {
  geom::Vec3 e = std::abs(axis.x()) > 0.6 ? geom::Vec3::UnitY() : geom::Vec3::UnitX();
  const geom::Vec3 u = (e - e.dot(axis) * axis).normalized();
  const geom::Vec3 v = axis.cross(u);
  std::vector<std::vector<Eigen::Vector2d>> out;
  for (const auto& loop : model.surface(cap).loops) {
    if (!lower_curves.count(loop.uses.front().curve)) continue;
    std::vector<Eigen::Vector2d> poly;
    for (const auto& use : loop.uses) {
      const auto& g = *model.curve(use.curve).geometry;
      const auto [t0, t1] = g.range();
      for (int k = 0; k < 16; ++k) {
        const double f = use.sense == geom::Sense::Forward ? k / 16.0 : 1.0 - k / 16.0;
        const geom::Vec3 x = g.point(t0 + f * (t1 - t0));
        poly.emplace_back(x.dot(u), x.dot(v));
      }
    }
    out.push_back(poly);
  }
  return out;
}

bool polygons_cross(const std::vector<Eigen::Vector2d>& a, const std::vector<Eigen::Vector2d>& b) {
  auto orient = [](const Eigen::Vector2d& p, const Eigen::Vector2d& q, const Eigen::Vector2d& r) {
    return (q - p).x() * (r - p).y() - (q - p).y() * (r - p).x();
  };
  for (size_t i = 0; i < a.size(); ++i) {
    const auto& p0 = a[i];
    const auto& p1 = a[(i + 1) % a.size()];
    for (size_t k = 0; k < b.size(); ++k) {
      const auto& q0 = b[k];
      const auto& q1 = b[(k + 1) % b.size()];
      const double d1 = orient(p0, p1, q0), d2 = orient(p0, p1, q1);
      const double d3 = orient(q0, q1, p0), d4 = orient(q0, q1, p1);
      if (((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0))) return true;
    }
  }
  return false;
}

bool polygon_contains(const std::vector<Eigen::Vector2d>& poly, const Eigen::Vector2d& p) {
  bool in = false;
  for (size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    if ((poly[i].y() > p.y()) != (poly[j].y() > p.y()) &&
        p.x() < (poly[j].x() - poly[i].x()) * (p.y() - poly[i].y()) / (poly[j].y() - poly[i].y()) + poly[i].x()) {
      in = !in;
    }
  }
  return in;
}

// Dihedral classes: below pi an end (convex), above pi re-entrant (virtual),
// kMaxCapDihedral and kReentrantMin (classify_faces.h) apart.

// Tries one sweep axis; empty why on success.
std::string try_axis(const geom::Model& model, int vid, const scheme::Registry& registry,
                     const std::vector<Face>& faces, const geom::Vec3& axis, bool two_sided,
                     ManyToOne& out) {
  const double cos_cap = std::cos(30.0 * M_PI / 180.0);
  std::vector<const Face*> caps, sides;
  for (const Face& f : faces) {
    const bool facing = std::abs(f.normal.dot(axis)) > cos_cap;
    if (!f.side_ok && !facing) {
      return "surface " + std::to_string(f.id) + " cannot be a side (" + f.side_why +
             ") and does not face the axis " + vec_text(axis);
    }
    (facing ? caps : sides).push_back(&f);
  }
  if (caps.size() < 3) return "only " + std::to_string(caps.size()) + " caps face the axis " + vec_text(axis);
  auto cap_of = [&](int id) -> const Face* {
    for (const Face* c : caps) {
      if (c->id == id) return c;
    }
    return nullptr;
  };
  // Sides: each links two caps (sec. 3); one touching more is split with its
  // ring below (stepped rings).
  std::vector<SideFace> side_faces(sides.size());
  std::vector<std::array<int, 2>> ends(sides.size());
  std::vector<std::array<bool, 2>> convex(sides.size());
  std::vector<char> multi(sides.size(), 0);
  for (size_t s = 0; s < sides.size(); ++s) {
    const Face& f = *sides[s];
    std::vector<int> touched;
    for (const Face* c : caps) {
      for (int k : f.curves) {
        if (c->curves.count(k)) {
          touched.push_back(c->id);
          break;
        }
      }
    }
    if (touched.size() < 2) {
      return "side surface " + std::to_string(f.id) + " touches " + std::to_string(touched.size()) +
             " caps (" + join(touched) + "); a side links two caps along the axis " + vec_text(axis);
    }
    if (touched.size() > 2) {  // spans several barrels: split with its ring below
      multi[s] = 1;
      continue;
    }
    const Face& a = *cap_of(touched[0]);
    const Face& b = *cap_of(touched[1]);
    const std::string why =
        detail::check_side(model, f.id, f.corners, a.id, a.curves, b.id, b.curves, side_faces[s]);
    if (!why.empty()) return why;
    ends[s] = {a.id, b.id};
    const double da = cap_dihedral_degrees(model, vid, a.id, f.id, side_faces[s].source_curves.front());
    const double db = cap_dihedral_degrees(model, vid, b.id, f.id, side_faces[s].target_curves.front());
    for (int e = 0; e < 2; ++e) {
      const double d = e == 0 ? da : db;
      if (d >= kMaxCapDihedral && d <= kReentrantMin) {
        std::ostringstream m;
        m.precision(4);
        m << "side surface " << f.id << " meets cap " << (e == 0 ? a.id : b.id) << " at " << d
          << " degrees (tangent: neither an end nor a re-entrant shoulder)";
        return m.str();
      }
      convex[s][static_cast<size_t>(e)] = d < kMaxCapDihedral;
    }
  }
  // Rings: sides sharing a curve (a linking curve) are one ring.
  std::vector<int> parent(sides.size());
  std::iota(parent.begin(), parent.end(), 0);
  for (size_t i = 0; i < sides.size(); ++i) {
    for (size_t j = i + 1; j < sides.size(); ++j) {
      for (int k : sides[i]->curves) {
        if (sides[j]->curves.count(k)) {
          parent[static_cast<size_t>(find(parent, static_cast<int>(i)))] = find(parent, static_cast<int>(j));
          break;
        }
      }
    }
  }
  std::map<int, std::vector<int>> components;
  for (size_t s = 0; s < sides.size(); ++s) components[find(parent, static_cast<int>(s))].push_back(static_cast<int>(s));
  std::vector<Ring> rings;
  std::vector<char> stepped_side(sides.size(), 0);
  std::map<int, SideFace> stepped_faces;  // surface -> its SideFace in a stepped ring
  for (const auto& [root, members] : components) {
    bool uniform = true;
    for (int s : members) {
      const size_t i = static_cast<size_t>(s), f = static_cast<size_t>(members.front());
      uniform = uniform && !multi[i] && ends[i] == ends[f] && convex[i] == convex[f];
    }
    if (uniform) {
      Ring r;
      r.sides = members;
      const size_t f = static_cast<size_t>(members.front());
      r.x = ends[f][0];
      r.y = ends[f][1];
      r.convex_x = convex[f][0];
      r.convex_y = convex[f][1];
      rings.push_back(r);
      continue;
    }
    // Sides linking different caps, or one side touching three or more:
    // split the ring at the level of every cap it touches (sec. 4, Fig. 8).
    std::vector<int> ids;
    for (int s : members) ids.push_back(sides[static_cast<size_t>(s)]->id);
    std::vector<RingCap> ring_caps;
    for (const Face* c : caps) ring_caps.push_back({c->id, c->curves});
    // Levels along the direction in which most open segments step down
    // (their virtual caps at their lower ends, so a closed barrel with flush
    // subcaps on one end only is swept from that end); the axis sign is
    // arbitrary.
    auto steps_up = [](const SteppedRing& r) {
      long up = 0;
      for (const RingSegment& seg : r.segments) up += !seg.convex_upper ? 1 : seg.convex_lower ? 0 : -1;
      return up;
    };
    SteppedRing st = split_stepped_ring(model, vid, axis, ids, ring_caps);
    SteppedRing flipped = split_stepped_ring(model, vid, -axis, ids, ring_caps);
    if (flipped.why.empty() && (!st.why.empty() || steps_up(flipped) < steps_up(st))) st = std::move(flipped);
    if (!st.why.empty()) return "the side faces joined to surface " + std::to_string(ids.front()) + ": " + st.why;
    for (const SideFace& sf : st.sides) stepped_faces[sf.surface] = sf;
    for (int s : members) stepped_side[static_cast<size_t>(s)] = 1;
    for (const RingSegment& seg : st.segments) {
      Ring r;
      for (int s : members) {
        if (std::binary_search(seg.sides.begin(), seg.sides.end(), sides[static_cast<size_t>(s)]->id)) r.sides.push_back(s);
      }
      r.x = seg.lower;
      r.y = seg.upper;
      r.convex_x = seg.convex_lower;
      r.convex_y = seg.convex_upper;
      r.stepped = true;
      r.chains = seg.linking_chains;
      rings.push_back(r);
    }
  }
  // Barrels: rings grouped by the cap they start from (sec. 4).
  struct Group {
    int from = 0, other = 0;
    bool closed = false;
    std::vector<int> sides;
    bool stepped = false;  // holds a segment of a stepped ring
    int stepped_upper = 0;
    std::vector<std::vector<int>> chains;  // the stepped segments' linking chains
  };
  std::map<int, Group> by_cap;  // start cap -> barrel
  std::map<int, std::vector<int>> inflow;  // cap -> start caps of open barrels into it
  for (const Ring& r : rings) {
    std::vector<int> ids;
    for (int s : r.sides) ids.push_back(sides[static_cast<size_t>(s)]->id);
    if (!r.convex_x && !r.convex_y) {
      return "side surfaces " + join(ids) + " meet both caps " + std::to_string(r.x) + " and " +
             std::to_string(r.y) + " re-entrantly (a barrel between two virtual caps)";
    }
    std::vector<int> starts;
    if (r.convex_x) starts.push_back(r.x);
    if (r.convex_y) starts.push_back(r.y);
    for (int from : starts) {
      const int other = from == r.x ? r.y : r.x;
      const bool closed = r.convex_x && r.convex_y;
      auto [it, added] = by_cap.try_emplace(from);
      Group& g = it->second;
      if (added) {
        g.from = from;
        g.other = other;
        g.closed = closed;
      } else if (g.other != other || g.closed != closed) {
        return "cap " + std::to_string(from) + " starts barrels towards caps " +
               std::to_string(g.other) + " and " + std::to_string(other) +
               ": its lower cap would need subcaps imprinted on a real cap (sec. 5.2-5.3 with "
               "polygon meshing), not supported";
      }
      g.sides.insert(g.sides.end(), r.sides.begin(), r.sides.end());
      if (r.stepped) {
        g.stepped = true;
        g.stepped_upper = r.y;
        g.chains.insert(g.chains.end(), r.chains.begin(), r.chains.end());
      }
    }
    if (!(r.convex_x && r.convex_y)) inflow[r.convex_x ? r.y : r.x].push_back(r.convex_x ? r.x : r.y);
  }
  // One barrel per closed cap pair, oriented from the end with inflow.
  std::vector<Group> barrels;
  std::set<int> used;
  for (const auto& [from, g] : by_cap) {
    if (used.count(from)) continue;
    used.insert(from);
    Group b = g;
    if (g.closed) {
      used.insert(g.other);
      const bool in_from = inflow.count(from) > 0, in_other = inflow.count(g.other) > 0;
      if (in_from && in_other) {
        if (!two_sided) {
          return "the barrel between caps " + std::to_string(from) + " and " +
                 std::to_string(g.other) +
                 " has subcaps at both ends (appendages on both sides): its imprinted subcaps "
                 "need a polygon mesher (pave's 2D core), which is not available";
        }
        // Deterministic: a stepped ring's upper cap is upper (its flush
        // subcaps arrive beside both real caps), else the lower id.
        if (b.stepped ? b.from != b.stepped_upper : b.other < b.from) std::swap(b.from, b.other);
      } else if (in_other) {
        std::swap(b.from, b.other);
      }
      std::sort(b.sides.begin(), b.sides.end());
      b.sides.erase(std::unique(b.sides.begin(), b.sides.end()), b.sides.end());
    }
    // Open stepped segments start from their convex end (down or up).
    if (b.stepped && b.closed && b.from != b.stepped_upper) {
      return "the barrel from cap " + std::to_string(b.from) + " runs up a ring of sides that spans "
             "several caps; only rings swept from their upper caps down are supported";
    }
    barrels.push_back(b);
  }
  int closed_count = 0;
  for (const Group& b : barrels) closed_count += b.closed ? 1 : 0;
  if (barrels.size() < 2) return "one barrel along the axis " + vec_text(axis) + " (a one-to-one sweep)";
  if (closed_count != 1) {
    return std::to_string(closed_count) + " barrels end on real caps along the axis " + vec_text(axis) +
           "; many-to-one needs exactly one target";
  }
  for (const Face* c : caps) {
    bool covered = false;
    for (const Group& b : barrels) covered = covered || b.from == c->id || (b.closed && b.other == c->id);
    if (!covered) return "cap " + std::to_string(c->id) + " starts no barrel";
  }
  // Order upstream first (a barrel after all barrels flowing into its cap).
  std::vector<int> order;
  std::set<int> done;
  while (order.size() < barrels.size()) {
    bool progress = false;
    for (size_t i = 0; i < barrels.size(); ++i) {
      if (done.count(barrels[i].from)) continue;
      bool ready = true;
      for (int src : inflow[barrels[i].from]) ready = ready && done.count(src);
      if (barrels[i].closed) {
        for (int src : inflow[barrels[i].other]) ready = ready && done.count(src);
      }
      if (!ready) continue;
      order.push_back(static_cast<int>(i));
      done.insert(barrels[i].from);
      progress = true;
    }
    if (!progress) return "the barrels flow in a cycle";
  }
  out.barrels.clear();
  out.sides.clear();
  std::map<int, int> index_of_start;
  for (int i : order) {
    const Group& g = barrels[static_cast<size_t>(i)];
    BarrelPlan p;
    p.upper = g.from;
    for (int src : inflow[g.from]) p.inflow.push_back(index_of_start.at(src));
    std::sort(p.inflow.begin(), p.inflow.end());
    if (g.closed) {
      p.lower = g.other;
      out.target = g.other;
      for (int src : inflow[g.other]) p.lower_inflow.push_back(index_of_start.at(src));
      std::sort(p.lower_inflow.begin(), p.lower_inflow.end());
      out.volume_caps.push_back(g.other);
      if (!p.lower_inflow.empty()) out.volume_caps.push_back(g.from);
      std::sort(out.volume_caps.begin(), out.volume_caps.end());
    } else {
      p.into = g.other;
    }
    p.flush = g.stepped && !g.closed;
    p.linking_chains = g.chains;
    for (int s : g.sides) {
      if (stepped_side[static_cast<size_t>(s)]) {
        const SideFace& sf = stepped_faces.at(sides[static_cast<size_t>(s)]->id);
        p.sides.push_back(sf.surface);
        out.sides.push_back(sf);
        continue;
      }
      SideFace sf = side_faces[static_cast<size_t>(s)];
      if (ends[static_cast<size_t>(s)][0] != g.from) std::swap(sf.source_curves, sf.target_curves);
      p.sides.push_back(sf.surface);
      p.linking_chains.insert(p.linking_chains.end(), sf.linking_chains.begin(), sf.linking_chains.end());
      out.sides.push_back(std::move(sf));
    }
    std::sort(p.sides.begin(), p.sides.end());
    index_of_start[g.from] = static_cast<int>(out.barrels.size());
    out.barrels.push_back(std::move(p));
  }
  std::sort(out.sides.begin(), out.sides.end(),
            [](const SideFace& a, const SideFace& b) { return a.surface < b.surface; });
  out.sides.erase(std::unique(out.sides.begin(), out.sides.end(),
                              [](const SideFace& a, const SideFace& b) { return a.surface == b.surface; }),
                  out.sides.end());
  // Subcaps arriving on both ends of a barrel that overlap (sec. 5.3): their
  // barrels are meshed from the middle, their real caps by cooper.
  for (BarrelPlan& m : out.barrels) {
    if (m.lower_inflow.empty()) continue;
    auto lower_of = [&](int i) {
      std::set<int> c;
      for (int s : out.barrels[static_cast<size_t>(i)].sides) {
        for (const SideFace& sf : out.sides) {
          if (sf.surface == s) c.insert(sf.target_curves.begin(), sf.target_curves.end());
        }
      }
      return c;
    };
    // A hole loop of the real cap, or for a flush virtual cap (beside the
    // real cap, no loop of it) the outline of the barrel's own real cap.
    auto footprint_of = [&](int i, int cap) {
      const BarrelPlan& q = out.barrels[static_cast<size_t>(i)];
      if (!q.flush) return footprint(model, cap, lower_of(i), axis);
      const auto& outer = model.surface(q.upper).loops.front().uses;
      return footprint(model, q.upper, {outer.front().curve}, axis);
    };
    for (int ti : m.inflow) {
      const auto ft = footprint_of(ti, m.upper);
      for (int bj : m.lower_inflow) {
        const auto fb = footprint_of(bj, m.lower);
        if (ft.empty() || fb.empty()) continue;
        if (polygons_cross(ft.front(), fb.front())) {
          out.barrels[static_cast<size_t>(ti)].from_middle = true;
          out.barrels[static_cast<size_t>(bj)].from_middle = true;
        } else if (polygon_contains(ft.front(), fb.front().front()) ||
                   polygon_contains(fb.front(), ft.front().front())) {
          return "the subcaps arriving from caps " + std::to_string(out.barrels[static_cast<size_t>(ti)].upper) +
                 " and " + std::to_string(out.barrels[static_cast<size_t>(bj)].upper) +
                 " on the two ends of the barrel between caps " + std::to_string(m.upper) + " and " +
                 std::to_string(m.lower) + " contain one another; not supported";
        }
      }
    }
  }
  for (const BarrelPlan& b : out.barrels) {
    if (!b.from_middle) continue;
    if (!b.inflow.empty()) {
      return "cap " + std::to_string(b.upper) + " receives subcaps and its barrel overlaps another "
             "barrel's subcap; chains of overlapping barrels are not supported";
    }
    out.volume_caps.push_back(b.upper);
  }
  std::sort(out.volume_caps.begin(), out.volume_caps.end());
  out.cap_schemes.clear();
  for (const Face* c : caps) {
    if (std::count(out.volume_caps.begin(), out.volume_caps.end(), c->id)) continue;
    std::string why;
    const std::string s = detail::cap_scheme(model, registry, c->id, why);
    if (s.empty()) return why;
    out.cap_schemes[c->id] = s;
  }
  double worst = 1.0;
  for (const Face* f : sides) worst = std::min(worst, f->side_score);
  out.score = 0.3 + 0.15 * std::clamp(worst, 0.0, 1.0);
  out.axis = axis;
  return {};
}

}  // namespace

// cite: Blacker 1996, sec. 3 (classification), sec. 4 (barrel formation:
// end caps, subcaps, a unique set of barrels).
ManyToOne classify_barrels(const geom::Model& model, int volume_id,
                           const scheme::Registry& registry, const SweepHints& hints,
                           bool polygon_mesher_available) {
  ManyToOne out;
  const std::string vname = "volume " + std::to_string(volume_id);
  std::vector<int> ids = model.surfaces_of(volume_id);
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  if (ids.size() < 4 || model.volume(volume_id).shells.size() != 1) {
    out.why = vname + ": a many-to-one sweep needs one shell and at least 4 surfaces";
    return out;
  }
  if (registry.surface_schemes(scheme::Role::SweepSide).empty()) {
    out.why = vname + ": no registered surface scheme serves sweep sides (submap does); cooper "
                      "needs one for the sides";
    return out;
  }
  std::vector<Face> faces;
  for (int id : ids) {
    const geom::Surface& s = model.surface(id);
    Face f;
    f.id = id;
    f.loops = static_cast<int>(s.loops.size());
    f.planar = s.geometry->type() == geom::SurfaceType::Plane;
    for (const auto& loop : s.loops) {
      for (const auto& use : loop.uses) f.curves.insert(use.curve);
    }
    const geom::Vec3 centre = 0.5 * (s.box.min + s.box.max);
    f.normal = geom::sign(model.sense_in(id, volume_id)) * s.geometry->project(centre).normal;
    if (f.loops != 1) {
      f.side_why = "it has " + std::to_string(f.loops) + " loops";
    } else {
      const scheme::RoleChoice side = scheme::best_surface_scheme(
          registry, scheme::Role::SweepSide, scheme::SurfaceView{model, id, nullptr});
      f.side_ok = side.scheme != nullptr;
      f.side_score = side.applicability.score;
      f.side_why = f.side_ok ? side.applicability.why : side.reasons;
      if (f.side_ok) f.corners = scheme::loop_corners(model, id, 0);
    }
    faces.push_back(std::move(f));
  }
  // Fig. 3a: the virtual faces (hole loops of planar faces, where parts of
  // the volume meet) must all face one direction (sec. 3).
  const double cos_parallel = std::cos(10.0 * M_PI / 180.0);
  for (size_t i = 0; i < faces.size(); ++i) {
    for (size_t j = i + 1; j < faces.size(); ++j) {
      const Face& a = faces[i];
      const Face& b = faces[j];
      if (a.loops < 2 || b.loops < 2 || !a.planar || !b.planar) continue;
      if (std::abs(a.normal.dot(b.normal)) >= cos_parallel) continue;
      out.needs_decomposition = true;
      out.why = vname + " is not cooperable: surfaces " + std::to_string(a.id) + " (normal " +
                vec_text(a.normal) + ") and " + std::to_string(b.id) + " (normal " +
                vec_text(b.normal) + ") both carry virtual faces (hole loops where parts of the "
                "volume meet), in different directions (Blacker 1996, sec. 3, Fig. 3a); "
                "decompose it, e.g. with <webcut>, into pieces that sweep in one direction each";
      return out;
    }
  }
  // Candidate axes: the hint, then normals of faces with holes, then of the
  // planar faces, in id order (deterministic, independent of shell order).
  std::vector<geom::Vec3> axes;
  auto add_axis = [&](geom::Vec3 d) {
    if (d.norm() == 0) return;
    d.normalize();
    for (const auto& a : axes) {
      if (std::abs(a.dot(d)) > 0.999) return;
    }
    axes.push_back(d);
  };
  if (hints.direction) add_axis(*hints.direction);
  for (const Face& f : faces) {
    if (f.loops > 1 && f.planar) add_axis(f.normal);
  }
  for (const Face& f : faces) {
    if (f.planar) add_axis(f.normal);
  }
  std::string first_failure;
  for (const geom::Vec3& axis : axes) {
    ManyToOne trial;
    const std::string why =
        try_axis(model, volume_id, registry, faces, axis, polygon_mesher_available, trial);
    if (!why.empty()) {
      if (first_failure.empty()) first_failure = why;
      continue;
    }
    if (!hints.targets.empty() && (hints.targets.size() != 1 || hints.targets.front() != trial.target)) {
      if (first_failure.empty()) {
        first_failure = "the hinted targets (" + join(hints.targets) + ") are not the target " +
                        std::to_string(trial.target) + " of the barrels";
      }
      continue;
    }
    bool sources_ok = true;
    for (int s : hints.sources) sources_ok = sources_ok && trial.cap_schemes.count(s);
    if (!sources_ok) {
      if (first_failure.empty()) first_failure = "a hinted source is not a source cap of the barrels";
      continue;
    }
    trial.ok = true;
    std::ostringstream w;
    w << vname << ": many-to-one sweep along " << vec_text(axis) << " in " << trial.barrels.size()
      << " barrels from " << trial.cap_schemes.size() << " source caps to surface " << trial.target;
    trial.why = w.str();
    return trial;
  }
  out.why = vname + ": no many-to-one barrel structure (" +
            (first_failure.empty() ? std::string("no planar face gives an axis") : first_failure) + ")";
  return out;
}

}  // namespace cooperage::cooper
