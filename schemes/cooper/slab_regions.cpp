#include "schemes/cooper/slab_regions.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <set>

namespace cooperage::cooper {
namespace {

struct DisjointSets {
  std::vector<int> parent;
  explicit DisjointSets(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int x) {
    while (parent[static_cast<size_t>(x)] != x) {
      parent[static_cast<size_t>(x)] = parent[static_cast<size_t>(parent[static_cast<size_t>(x)])];
      x = parent[static_cast<size_t>(x)];
    }
    return x;
  }
  void unite(int a, int b) {
    a = find(a);
    b = find(b);
    if (a != b) parent[static_cast<size_t>(std::max(a, b))] = std::min(a, b);
  }
};

/// Extent of a cycle's rims: the diagonal of the box of its contact curves.
double rim_extent(const VolumeFacts& facts, const SideLattice& lattice, const Cycle& cycle) {
  std::vector<int> rims;
  for (const CapContact& k : lattice.contacts) {
    if (std::binary_search(cycle.faces.begin(), cycle.faces.end(), k.face)) rims.push_back(k.curve);
  }
  return facts.extent(rims);
}

/// A cap whose one loop runs along two cycles through a seam (an annulus on
/// a sphere or cone, periodic in CAD) makes both of them "outer" by the
/// contact rule. The cycle whose rims span the widest box encloses the
/// others; those become holes. Returns the outer count left (1, or more on
/// a tie within 1 %, which stays refused).
int keep_widest_outer(const VolumeFacts& facts, const SideLattice& lattice,
                      const std::vector<int>& list, std::vector<Cycle>& cycles) {
  // Only through a seamed cap: elsewhere two outer cycles in one region are
  // a real contradiction (a boss flush with a wall), refused as before.
  auto cycle_of = [&](int face) {
    for (int c : list) {
      const auto& f = cycles[static_cast<size_t>(c)].faces;
      if (cycles[static_cast<size_t>(c)].outer && std::binary_search(f.begin(), f.end(), face))
        return c;
    }
    return -1;
  };
  bool seamed = false;
  for (int cap : lattice.caps) {
    std::map<int, int> uses;
    for (const UseFact& u : facts.face(cap)->loops.front()) ++uses[u.curve];
    if (std::none_of(uses.begin(), uses.end(), [](const auto& kv) { return kv.second == 2; }))
      continue;
    std::set<int> joined;
    for (const CapContact& k : lattice.contacts) {
      if (k.cap == cap && k.cap_loop == 0 && cycle_of(k.face) >= 0) joined.insert(cycle_of(k.face));
    }
    seamed = seamed || joined.size() >= 2;
  }
  if (!seamed) return 2;
  int widest = -1;
  double best = -1, second = -1;
  for (int c : list) {
    if (!cycles[static_cast<size_t>(c)].outer) continue;
    const double e = rim_extent(facts, lattice, cycles[static_cast<size_t>(c)]);
    if (e > best) {
      second = best;
      best = e;
      widest = c;
    } else {
      second = std::max(second, e);
    }
  }
  if (second >= 0.99 * best) return 2;
  for (int c : list) cycles[static_cast<size_t>(c)].outer = c == widest;
  return 1;
}

/// The signed area of a cycle's cross-section about `axis`, measured from
/// `middle`: positive when its walls enclose the volume, negative round a
/// hole. Each face's loop runs round its outward normal, so along its
/// lowest rims (the face lies above them) it runs along up x normal:
/// anticlockwise round an outer wall, clockwise round a hole, whatever the
/// ring's shape (an L, a crescent: where the middle lies outside it and
/// some walls face it and some away). Projected across the sweep, the
/// faces' lowest rims close into the section (the curves linking levels
/// project to points), so the faces need no order.
double section_area(const VolumeFacts& facts, const SideLattice& lattice, const SweepOrder& order,
                    const Cycle& cycle, const geom::Vec3& axis, const geom::Vec3& middle) {
  double area = 0;
  for (int f : cycle.faces) {
    const FaceFact& face = *facts.face(f);
    auto level = [&](const UseFact& u) {
      return order
          .height[static_cast<size_t>(lattice.vertex_class.at(facts.curves.at(u.curve).start))];
    };
    double lowest = std::numeric_limits<double>::infinity();
    for (const UseFact& u : face.loops.front()) {
      if (lattice.along.count(u.curve)) lowest = std::min(lowest, level(u));
    }
    for (const UseFact& u : face.loops.front()) {
      if (!lattice.along.count(u.curve) || level(u) > lowest + 1e-9 * facts.size()) continue;
      std::vector<geom::Vec3> q = facts.curves.at(u.curve).samples;
      if (!u.forward) std::reverse(q.begin(), q.end());
      if (q.size() < 2) continue;
      // Which way is up here: the face's centre lies above its lowest rim.
      geom::Vec3 rim = geom::Vec3::Zero();
      for (const geom::Vec3& p : q) rim += p;
      rim /= static_cast<double>(q.size());
      const double up = axis.dot(face.centre - rim) >= 0 ? 1.0 : -1.0;
      for (size_t i = 0; i + 1 < q.size(); ++i)
        area += 0.5 * up * axis.dot((q[i] - middle).cross(q[i + 1] - middle));
    }
  }
  return area;
}

/// For a cycle the caps bounding its slab do not decide, or decide against
/// its faces' own roles: which way its faces face across the sweep. A hole's walls face the middle
/// of its rims, an outer wall faces away from it; where they do not agree
/// and nothing else decides (`by_section`), the sign of the section's area.
/// +1 outer, -1 hole, 0 undecided.
int facing_of_cycle(const VolumeFacts& facts, const SideLattice& lattice, const SweepOrder& order,
                    const Cycle& cycle, bool by_section) {
  geom::Vec3 axis = geom::Vec3::Zero();
  for (int cap : lattice.caps) {
    if (facts.face(cap)->planar) {
      axis = facts.face(cap)->normal.normalized();
      break;
    }
  }
  if (axis.squaredNorm() == 0) return 0;
  auto across = [&](const geom::Vec3& v) { return v - axis * axis.dot(v); };
  geom::Vec3 middle = geom::Vec3::Zero();
  size_t n = 0;
  for (const CapContact& k : lattice.contacts) {
    if (!std::binary_search(cycle.faces.begin(), cycle.faces.end(), k.face)) continue;
    for (const geom::Vec3& p : facts.curves.at(k.curve).samples) {
      middle += p;
      ++n;
    }
  }
  if (n == 0) return 0;
  middle /= static_cast<double>(n);
  // A ring of one face (a whole cylinder closed by its seam): its contacts
  // may be arcs on one side of it, and its one point says nothing about
  // where the rest lies; its area centroid lies inside the ring.
  if (cycle.faces.size() == 1) {
    const FaceFact& face = *facts.face(cycle.faces.front());
    if (across(face.centroid - face.centre).norm() > 1e-6 * facts.size()) middle = face.centroid;
  }
  int away = 0, towards = 0;
  for (int f : cycle.faces) {
    const FaceFact& face = *facts.face(f);
    const geom::Vec3 normal = across(face.normal);
    const geom::Vec3 to_middle = across(middle - face.centre);
    if (normal.norm() < 0.5 || to_middle.norm() < 1e-9 * facts.size()) continue;
    (normal.dot(to_middle) > 0 ? towards : away)++;
  }
  if (away > 0 && towards == 0) return 1;
  if (towards > 0 && away == 0) return -1;
  if (!by_section) return 0;
  const double area = section_area(facts, lattice, order, cycle, axis, middle);
  const double extent = rim_extent(facts, lattice, cycle);
  if (std::abs(area) <= 1e-3 * extent * extent) return 0;
  return area > 0 ? 1 : -1;
}

}  // namespace

int region_of_cycle(const Slab& slab, int c) {
  for (size_t r = 0; r < slab.regions.size(); ++r) {
    if (std::count(slab.regions[r].begin(), slab.regions[r].end(), c)) return static_cast<int>(r);
  }
  return -1;
}

// cite: Blacker 1996, sec. 4 (a complete layer of ribs at a time; barrels
// bounded by ribs on the sides and caps on the ends).
SlabRegions slab_regions(const VolumeFacts& facts, const SideLattice& lattice,
                         const SweepOrder& order) {
  SlabRegions out;
  const double scale = order.straight ? facts.size() : std::max(1.0, [&] {
    double lo = 0, hi = 0;
    for (double h : order.height) {
      lo = std::min(lo, h);
      hi = std::max(hi, h);
    }
    return hi - lo;
  }());
  const double tol = 1e-6 * scale;
  out.tolerance = tol;
  auto height = [&](int cls) { return order.height[static_cast<size_t>(cls)]; };
  // Cap levels, highest first.
  std::vector<double> hs;
  for (const auto& [cap, cls] : lattice.cap_class) hs.push_back(height(cls));
  std::sort(hs.begin(), hs.end(), std::greater<double>());
  for (double h : hs) {
    if (out.levels.empty() || out.levels.back() - h > tol) out.levels.push_back(h);
  }
  if (out.levels.size() < 2) {
    out.why = "all caps lie on one level";
    return out;
  }
  for (int s : lattice.sides) {
    double lo = 1e300, hi = -1e300;
    for (int cls : lattice.face_classes.at(s)) {
      lo = std::min(lo, height(cls));
      hi = std::max(hi, height(cls));
    }
    out.span[s] = {lo, hi};
  }
  // Outer or hole walls, from the contacts: a convex contact on a cap's
  // outer loop or a re-entrant one on a hole loop walls the volume in, a
  // convex one on a hole loop walls a hole; the rest follow neighbours.
  std::map<int, std::set<int>> neighbours;  // sides sharing a non-cap curve
  {
    std::map<int, std::vector<int>> by_curve;
    std::set<int> cap_curves;
    for (const CapContact& k : lattice.contacts) cap_curves.insert(k.curve);
    for (int s : lattice.sides) {
      for (const UseFact& u : facts.face(s)->loops.front()) {
        if (!cap_curves.count(u.curve)) by_curve[u.curve].push_back(s);
      }
    }
    for (const auto& [curve, list] : by_curve) {
      for (int a : list) {
        for (int b : list) {
          if (a != b) neighbours[a].insert(b);
        }
      }
    }
  }
  // A side may wall the volume in at one level and a hole at another (a
  // hole drilled through a boss's edge: its wall is outer beside the boss's
  // top, a hole's below the block's top); each slab's cycles then take
  // their side from the contacts of the caps that bound them.
  auto decides = [](const CapContact& k) { return k.convex || k.cap_loop != 0; };
  auto outer_at = [](const CapContact& k) { return k.convex == (k.cap_loop == 0); };
  std::set<int> mixed;  // sides walling the volume in at one cap and a hole at another
  for (const CapContact& k : lattice.contacts) {
    // A ring rising re-entrantly from a cap's outer loop walls a blind
    // hole above a floor, or a step flush with an outer wall: undecided.
    if (!decides(k)) continue;
    const auto [it, added] = out.outer_face.emplace(k.face, outer_at(k));
    if (!added && it->second != outer_at(k)) mixed.insert(k.face);
  }
  // Whether a cycle is called outer by convex contacts on caps' outer
  // loops alone: those of the caps bounding its slab (`here`), or where no
  // cap bounds it, its faces' own roles, none of them from a hole loop.
  auto outer_by_outer_loops = [&](const std::set<bool>& here, const std::set<bool>& on_holes,
                                  const std::vector<int>& faces) {
    if (!on_holes.empty()) return false;
    if (!here.empty()) return here == std::set<bool>{true};
    for (int f : faces) {
      if (mixed.count(f) || !out.outer_face.at(f)) return false;
    }
    return std::none_of(lattice.contacts.begin(), lattice.contacts.end(), [&](const CapContact& k) {
      return k.cap_loop != 0 && std::binary_search(faces.begin(), faces.end(), k.face);
    });
  };
  for (bool progress = true; progress;) {
    progress = false;
    for (int s : lattice.sides) {
      if (out.outer_face.count(s)) continue;
      for (int n : neighbours[s]) {
        const auto it = out.outer_face.find(n);
        if (it == out.outer_face.end()) continue;
        out.outer_face[s] = it->second;
        progress = true;
        break;
      }
    }
  }
  for (int s : lattice.sides) {
    if (!out.outer_face.count(s)) {
      out.why =
          "side surface " + std::to_string(s) + " cannot be told an outer wall or a hole wall";
      return out;
    }
  }
  // Curve spans (linking curves) and heights (curves running along).
  auto curve_lo_hi = [&](int curve) {
    const CurveFact& c = facts.curves.at(curve);
    const double a = height(lattice.vertex_class.at(c.start)),
                 b = height(lattice.vertex_class.at(c.end));
    return std::make_pair(std::min(a, b), std::max(a, b));
  };
  std::set<int> cap_curves;
  for (const CapContact& k : lattice.contacts) cap_curves.insert(k.curve);
  // Slabs and their cycles.
  for (size_t k = 0; k + 1 < out.levels.size(); ++k) {
    Slab slab;
    slab.top = out.levels[k];
    slab.bottom = out.levels[k + 1];
    std::vector<int> active;
    for (int s : lattice.sides) {
      const auto [lo, hi] = out.span.at(s);
      if (hi > slab.bottom + tol && lo < slab.top - tol) active.push_back(s);
    }
    std::map<int, int> index;
    for (size_t i = 0; i < active.size(); ++i) index[active[i]] = static_cast<int>(i);
    DisjointSets ds(active.size());
    std::map<int, std::vector<int>> by_curve;
    for (int s : active) {
      for (const UseFact& u : facts.face(s)->loops.front()) {
        if (cap_curves.count(u.curve)) continue;
        const auto [lo, hi] = curve_lo_hi(u.curve);
        const bool joins = lattice.along.count(u.curve)
                               ? (lo > slab.bottom + tol && lo < slab.top - tol)
                               : (hi > slab.bottom + tol && lo < slab.top - tol);
        if (joins) by_curve[u.curve].push_back(s);
      }
    }
    for (const auto& [curve, list] : by_curve) {
      for (int s : list) ds.unite(index.at(list.front()), index.at(s));
    }
    std::map<int, std::vector<int>> groups;
    for (int s : active) groups[ds.find(index.at(s))].push_back(s);
    for (auto& [root, faces] : groups) {
      Cycle c;
      c.faces = faces;
      // The contacts of the caps bounding this slab on their material side.
      std::set<bool> here, on_holes;
      bool all_planar = true;
      for (const CapContact& ct : lattice.contacts) {
        if (!decides(ct) || !std::binary_search(faces.begin(), faces.end(), ct.face)) continue;
        const double h = height(lattice.cap_class.at(ct.cap));
        const bool bounds = order.upper.at(ct.cap) ? std::abs(slab.top - h) <= tol
                                                   : std::abs(slab.bottom - h) <= tol;
        if (!bounds) continue;
        here.insert(outer_at(ct));
        if (ct.cap_loop != 0) on_holes.insert(outer_at(ct));
        all_planar = all_planar && facts.face(ct.cap)->planar;
      }
      // A plane cap whose hole loop this cycle walls surrounds it in this
      // slab, so the cycle is what that contact says. A convex contact on
      // an outer loop only says the cap ends at the wall: a blind hole's
      // floor ends at a through hole crossing it, whose wall is still a
      // hole's. (On a sphere or cone which loop is outer is the CAD's
      // choice, so curved caps keep the refusal.)
      if (here.size() > 1 && on_holes.size() == 1 && all_planar) here = on_holes;
      bool any_mixed = false;
      for (int f : faces) any_mixed = any_mixed || mixed.count(f) > 0;
      // The walls' facing across the sweep decides, when it is unanimous,
      // where the caps say nothing (no cap bounds this slab: a blind hole
      // from one end reaching into one from the other), disagree, decide a
      // face that walls a hole elsewhere by an outer loop alone (a shallow
      // blind hole's floor beside a deeper one), or call the cycle other
      // than its faces' own roles (holes and pockets that overlap).
      int facing = 0;
      bool facing_known = false;
      auto facing_now = [&] {
        if (!facing_known)
          facing = order.straight ? facing_of_cycle(facts, lattice, order, c, false) : 0;
        facing_known = true;
        return facing;
      };
      // Where nothing else decides, the section's sign does (added last, so
      // that no ring decided before is decided anew).
      auto section_sign = [&] {
        return order.straight ? facing_of_cycle(facts, lattice, order, c, true) : 0;
      };
      // The sides the cycle's faces wall at every cap (all but the mixed).
      auto own_sides = [&] {
        std::set<bool> own;
        for (int f : faces) {
          if (!mixed.count(f)) own.insert(out.outer_face.at(f));
        }
        return own;
      };
      if (here.size() > 1 || (any_mixed && on_holes.empty())) {
        if (facing_now()) {
          here = {facing > 0};
        } else if (const std::set<bool> own = own_sides(); here.empty() && own.size() == 1) {
          // No cap bounds this slab on its material side (it lies between
          // a blind hole's floor and a notch's floor that face away from
          // it): the faces that wall one side at every cap decide when they
          // agree (the blind hole opens into the notch in the outer wall
          // above it: the hole's wall walls the volume in beside the notch).
          here = own;
        } else if (here.size() != 1) {
          const int sign = section_sign();
          if (sign == 0) {
            out.why = "side surface " + std::to_string(faces.front()) +
                      " walls the volume in at one cap and a hole at another";
            return out;
          }
          here = {sign > 0};
        }
      } else if (outer_by_outer_loops(here, on_holes, faces) && facing_now() < 0) {
        // Outer by convex contacts on outer loops alone, while every wall
        // faces the ring's middle: a hole whose rim has joined a cap's
        // outer loop (it cuts into a boss's footprint that crosses the
        // block's edge, so the rim and the footprint are one notch in it;
        // or it cuts a foot's edge at the foot's bottom).
        here = {false};
      }
      c.outer = here.empty() ? out.outer_face.at(faces.front()) : *here.begin();
      for (int f : faces) {
        if (mixed.count(f) || out.outer_face.at(f) == c.outer) continue;
        if (facing_now()) {
          c.outer = facing > 0;
          break;
        }
        if (const int sign = section_sign()) {
          c.outer = sign > 0;
          break;
        }
        out.why = "the sides " + std::to_string(faces.front()) + " and " + std::to_string(f) +
                  " form one cycle but wall the volume on different sides";
        return out;
      }
      slab.cycles.push_back(std::move(c));
    }
    std::sort(slab.cycles.begin(), slab.cycles.end(),
              [](const Cycle& a, const Cycle& b) { return a.faces.front() < b.faces.front(); });
    out.slabs.push_back(std::move(slab));
  }
  // Regions: union over (slab, cycle).
  std::vector<size_t> offset{0};
  for (const Slab& s : out.slabs) offset.push_back(offset.back() + s.cycles.size());
  DisjointSets ds(offset.back());
  auto node = [&](size_t k, size_t c) { return static_cast<int>(offset[k] + c); };
  auto cycle_of_face = [&](size_t k, int face) -> int {
    const auto& cycles = out.slabs[k].cycles;
    for (size_t c = 0; c < cycles.size(); ++c) {
      if (std::binary_search(cycles[c].faces.begin(), cycles[c].faces.end(), face))
        return static_cast<int>(c);
    }
    return -1;
  };
  // (a) a cap joins the cycles it bounds on its material side.
  for (int cap : lattice.caps) {
    const double h = height(lattice.cap_class.at(cap));
    const bool upper = order.upper.at(cap);
    for (size_t k = 0; k < out.slabs.size(); ++k) {
      const Slab& slab = out.slabs[k];
      const bool bounds = upper ? std::abs(slab.top - h) <= tol : std::abs(slab.bottom - h) <= tol;
      if (!bounds) continue;
      int first = -1;
      for (const CapContact& c : lattice.contacts) {
        if (c.cap != cap) continue;
        const int cy = cycle_of_face(k, c.face);
        if (cy < 0) continue;
        if (first < 0) first = cy;
        ds.unite(node(k, static_cast<size_t>(first)), node(k, static_cast<size_t>(cy)));
      }
    }
  }
  // (b) a cycle passing a level unchanged keeps its region.
  for (size_t k = 0; k + 1 < out.slabs.size(); ++k) {
    for (size_t a = 0; a < out.slabs[k].cycles.size(); ++a) {
      for (size_t b = 0; b < out.slabs[k + 1].cycles.size(); ++b) {
        if (out.slabs[k].cycles[a].faces == out.slabs[k + 1].cycles[b].faces)
          ds.unite(node(k, a), node(k + 1, b));
      }
    }
  }
  for (size_t k = 0; k < out.slabs.size(); ++k) {
    Slab& slab = out.slabs[k];
    std::map<int, std::vector<int>> classes;
    for (size_t c = 0; c < slab.cycles.size(); ++c)
      classes[ds.find(node(k, c))].push_back(static_cast<int>(c));
    std::vector<std::vector<int>> with_outer, holes_only;
    for (auto& [root, list] : classes) {
      int outers = 0;
      for (int c : list) outers += slab.cycles[static_cast<size_t>(c)].outer ? 1 : 0;
      if (outers > 1) outers = keep_widest_outer(facts, lattice, list, slab.cycles);
      if (outers > 1) {
        out.why = "two outer cycles of side faces (" +
                  std::to_string(slab.cycles[static_cast<size_t>(list.front())].faces.front()) +
                  ", ...) bound one region";
        return out;
      }
      (outers ? with_outer : holes_only).push_back(list);
    }
    for (const auto& holes : holes_only) {
      if (with_outer.size() != 1) {
        out.why = "the hole walled by side surface " +
                  std::to_string(slab.cycles[static_cast<size_t>(holes.front())].faces.front()) +
                  " cannot be placed in one of " + std::to_string(with_outer.size()) +
                  " regions between two cap levels";
        return out;
      }
      with_outer.front().insert(with_outer.front().end(), holes.begin(), holes.end());
    }
    for (auto& list : with_outer) {
      std::stable_sort(list.begin(), list.end(), [&](int a, int b) {
        const bool oa = slab.cycles[static_cast<size_t>(a)].outer,
                   ob = slab.cycles[static_cast<size_t>(b)].outer;
        return oa != ob ? oa : a < b;
      });
      slab.regions.push_back(list);
    }
    std::sort(slab.regions.begin(), slab.regions.end());
  }
  out.ok = true;
  return out;
}

}  // namespace cooperage::cooper
