#include "schemes/cooper/barrel_tree.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <set>

namespace cooperage::cooper {
namespace {

using RegionKey = std::pair<size_t, size_t>;  // (slab, region)

std::vector<std::vector<int>> region_cycles(const Slab& slab, size_t r) {
  std::vector<std::vector<int>> out;
  for (int c : slab.regions[r]) out.push_back(slab.cycles[static_cast<size_t>(c)].faces);
  return out;
}

std::set<int> region_faces(const Slab& slab, size_t r) {
  std::set<int> out;
  for (int c : slab.regions[r]) {
    const auto& f = slab.cycles[static_cast<size_t>(c)].faces;
    out.insert(f.begin(), f.end());
  }
  return out;
}

// The region of slab k holding face f, or -1.
int region_of_face(const Slab& slab, int f) {
  for (size_t c = 0; c < slab.cycles.size(); ++c) {
    const auto& faces = slab.cycles[c].faces;
    if (std::binary_search(faces.begin(), faces.end(), f))
      return region_of_cycle(slab, static_cast<int>(c));
  }
  return -1;
}

}  // namespace

// cite: Blacker 1996, sec. 4 (barrel formation; the barrels are a unique set).
BarrelTree form_barrel_tree(const VolumeFacts& facts, const SideLattice& lattice,
                            const SweepOrder& order, const SlabRegions& slabs) {
  BarrelTree out;
  const double tol = slabs.tolerance;
  const size_t ns = slabs.slabs.size();
  auto level_index = [&](double h) {
    for (size_t i = 0; i < slabs.levels.size(); ++i) {
      if (std::abs(slabs.levels[i] - h) <= tol) return i;
    }
    return slabs.levels.size();
  };
  // Regions of the slab on one side of a level that a cap's contacts reach.
  auto contact_regions = [&](int cap, size_t k) {
    std::set<int> regions;
    for (const CapContact& c : lattice.contacts) {
      if (c.cap != cap) continue;
      const int r = region_of_face(slabs.slabs[k], c.face);
      if (r >= 0) regions.insert(r);
    }
    return regions;
  };
  // Regions of slab `to` continuing the cycles of region r of slab `from`:
  // a cycle passing the level between them unchanged, else one that keeps
  // a face of it across the level (a wall whose ring gains a face between
  // levels: a lug's conical underside joins the ring below the level it
  // ends on, so the rings above and below that level differ by it).
  auto continuing = [&](size_t from, int r, size_t to) {
    std::set<int> regions;
    const Slab& f = slabs.slabs[from];
    const Slab& t = slabs.slabs[to];
    const auto cycles = region_cycles(f, static_cast<size_t>(r));
    for (size_t c = 0; c < t.cycles.size(); ++c) {
      if (std::find(cycles.begin(), cycles.end(), t.cycles[c].faces) != cycles.end()) {
        regions.insert(region_of_cycle(t, static_cast<int>(c)));
      }
    }
    if (!regions.empty()) return regions;
    for (int fc : f.regions[static_cast<size_t>(r)]) {
      const Cycle& mine = f.cycles[static_cast<size_t>(fc)];
      for (size_t c = 0; c < t.cycles.size(); ++c) {
        const Cycle& theirs = t.cycles[c];
        if (theirs.outer != mine.outer) continue;
        std::vector<int> common;
        std::set_intersection(mine.faces.begin(), mine.faces.end(), theirs.faces.begin(),
                              theirs.faces.end(), std::back_inserter(common));
        if (!common.empty()) regions.insert(region_of_cycle(t, static_cast<int>(c)));
      }
    }
    return regions;
  };
  // Caps to region ends: an upper cap is on the upper end of a region below it.
  std::map<RegionKey, std::vector<int>> upper_caps, lower_caps;
  std::map<int, RegionKey> placed;
  std::vector<int> deferred;
  for (int cap : lattice.caps) {
    const size_t i = level_index(order.height[static_cast<size_t>(lattice.cap_class.at(cap))]);
    const bool upper = order.upper.at(cap);
    if (i >= slabs.levels.size() || (upper && i >= ns) || (!upper && i == 0)) {
      out.why = "cap " + std::to_string(cap) + " has no volume on its " +
                (upper ? "lower" : "upper") + " side along the sweep";
      return out;
    }
    const size_t k = upper ? i : i - 1;      // the slab on its material side
    const size_t other = upper ? i - 1 : i;  // the slab on its void side (if any)
    std::set<int> regions = contact_regions(cap, k);
    if (regions.empty() && other < ns && (upper ? i > 0 : i < ns)) {
      // A floor or a ceiling inside a hole: the region continuing the one
      // whose hole wall ends on it (Fig. 8: the reached cap joins the
      // virtual cap of the ring that continues).
      for (int r : contact_regions(cap, other)) {
        const auto next = continuing(other, r, k);
        regions.insert(next.begin(), next.end());
      }
    }
    if (regions.empty()) {
      deferred.push_back(cap);
      continue;
    }
    if (regions.size() != 1) {
      out.why = "cap " + std::to_string(cap) + " bounds " + std::to_string(regions.size()) +
                " regions between two levels; it must bound one";
      return out;
    }
    const RegionKey key{k, static_cast<size_t>(*regions.begin())};
    (upper ? upper_caps : lower_caps)[key].push_back(cap);
    placed[cap] = key;
  }
  // A cap touching only caps (a subcap filling a hole loop of its host, a
  // piece of a composite cap): the region end of a neighbour on its level.
  for (bool progress = true; progress && !deferred.empty();) {
    progress = false;
    for (auto it = deferred.begin(); it != deferred.end();) {
      const int cap = *it;
      std::set<int> curves;
      for (const auto& loop : facts.face(cap)->loops) {
        for (const UseFact& u : loop) curves.insert(u.curve);
      }
      const RegionKey* found = nullptr;
      for (const auto& [other, key] : placed) {
        if (order.upper.at(other) != order.upper.at(cap)) continue;
        for (const auto& loop : facts.face(other)->loops) {
          for (const UseFact& u : loop) {
            if (curves.count(u.curve)) found = &key;
          }
        }
        if (found) break;
      }
      if (!found) {
        ++it;
        continue;
      }
      const RegionKey key = *found;
      (order.upper.at(cap) ? upper_caps : lower_caps)[key].push_back(cap);
      placed[cap] = key;
      it = deferred.erase(it);
      progress = true;
    }
  }
  if (!deferred.empty()) {
    out.why = "cap " + std::to_string(deferred.front()) + " bounds no region between two levels";
    return out;
  }
  for (auto* m : {&upper_caps, &lower_caps}) {
    for (auto& [key, list] : *m) std::sort(list.begin(), list.end());
  }
  // Regions merge across a level when their cycles pass it unchanged and no
  // cap there belongs to either.
  std::map<RegionKey, int> barrel_of;
  for (size_t k = 0; k < ns; ++k) {
    const Slab& slab = slabs.slabs[k];
    for (size_t r = 0; r < slab.regions.size(); ++r) {
      const RegionKey key{k, r};
      int joined = -1;
      if (k > 0 && !upper_caps.count(key)) {
        const Slab& above = slabs.slabs[k - 1];
        const auto mine = region_cycles(slab, r);
        for (size_t q = 0; q < above.regions.size(); ++q) {
          if (region_cycles(above, q) != mine || lower_caps.count({k - 1, q})) continue;
          joined = barrel_of.at({k - 1, q});
        }
      }
      if (joined < 0) {
        BarrelNode b;
        b.top = slab.top;
        b.first_slab = k;
        b.cycles = region_cycles(slab, r);
        out.barrels.push_back(b);
        joined = static_cast<int>(out.barrels.size()) - 1;
      }
      BarrelNode& b = out.barrels[static_cast<size_t>(joined)];
      b.bottom = slab.bottom;
      b.last_slab = k;
      const auto faces = region_faces(slab, r);
      std::set<int> sides(b.sides.begin(), b.sides.end());
      sides.insert(faces.begin(), faces.end());
      b.sides.assign(sides.begin(), sides.end());
      barrel_of[key] = joined;
    }
  }
  // Real caps on the ends.
  for (const auto& [key, caps] : upper_caps) {
    const int b = barrel_of.at(key);
    if (out.barrels[static_cast<size_t>(b)].first_slab != key.first) {
      out.why = "internal: cap " + std::to_string(caps.front()) + " inside a barrel";
      return out;
    }
    for (int c : caps) {
      out.barrels[static_cast<size_t>(b)].upper.push_back({c, -1});
      out.cap_end[c] = {b, true};
    }
  }
  for (const auto& [key, caps] : lower_caps) {
    const int b = barrel_of.at(key);
    for (int c : caps) {
      out.barrels[static_cast<size_t>(b)].lower.push_back({c, -1});
      out.cap_end[c] = {b, false};
    }
  }
  // Virtual caps between a barrel ending on a level and one starting there.
  for (size_t x = 0; x < out.barrels.size(); ++x) {
    const BarrelNode& bx = out.barrels[x];
    if (bx.last_slab + 1 >= ns) continue;
    const size_t k = bx.last_slab + 1;
    std::set<int> fx;
    for (const auto& c : bx.cycles) fx.insert(c.begin(), c.end());
    for (size_t y = 0; y < out.barrels.size(); ++y) {
      const BarrelNode& by = out.barrels[y];
      if (by.first_slab != k) continue;
      std::set<int> fy;
      for (const auto& c : by.cycles) fy.insert(c.begin(), c.end());
      bool connected = false;
      for (int f : fx) connected = connected || fy.count(f);
      for (const CapContact& c : lattice.contacts) {
        const auto it = out.cap_end.find(c.cap);
        if (it == out.cap_end.end()) continue;
        if (it->second == std::make_pair(static_cast<int>(y), true) && fx.count(c.face))
          connected = true;
        if (it->second == std::make_pair(static_cast<int>(x), false) && fy.count(c.face))
          connected = true;
      }
      if (!connected) continue;
      out.interfaces.push_back({static_cast<int>(x), static_cast<int>(y)});
    }
  }
  for (size_t i = 0; i < out.interfaces.size(); ++i) {
    out.barrels[static_cast<size_t>(out.interfaces[i].above)].lower.push_back(
        {0, static_cast<int>(i)});
    out.barrels[static_cast<size_t>(out.interfaces[i].below)].upper.push_back(
        {0, static_cast<int>(i)});
  }
  // Level classes of the ends.
  for (BarrelNode& b : out.barrels) {
    std::set<int> up, lo;
    for (const EndPiece& p : b.upper) {
      if (p.cap) up.insert(lattice.cap_class.at(p.cap));
    }
    for (const EndPiece& p : b.lower) {
      if (p.cap) lo.insert(lattice.cap_class.at(p.cap));
    }
    for (int s : b.sides) {
      for (int cls : lattice.face_classes.at(s)) {
        const double h = order.height[static_cast<size_t>(cls)];
        if (std::abs(h - b.top) <= tol) up.insert(cls);
        if (std::abs(h - b.bottom) <= tol) lo.insert(cls);
      }
    }
    b.upper_classes.assign(up.begin(), up.end());
    b.lower_classes.assign(lo.begin(), lo.end());
  }
  for (size_t i = 0; i < out.barrels.size(); ++i) {
    const BarrelNode& b = out.barrels[i];
    if (b.upper.empty() || b.lower.empty() || b.upper_classes.empty() || b.lower_classes.empty()) {
      out.why = "the barrel of side surfaces " + std::to_string(b.sides.front()) + ", ... has no " +
                (b.upper.empty() || b.upper_classes.empty() ? "upper" : "lower") + " cap";
      return out;
    }
  }
  out.ok = true;
  return out;
}

}  // namespace cooperage::cooper
