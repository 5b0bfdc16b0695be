#include "schemes/cooper/stepped_ring.h"

#include "schemes/cooper/cap_dihedral.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

namespace cooperage::cooper {
namespace {

std::string text(double d) {
  std::ostringstream s;
  s.precision(4);
  s << d;
  return s.str();
}

}  // namespace

// cite: Blacker 1996, sec. 4 (rib formation ceases at the first cap reached;
// the lower cap is then combined with the adjacent cap, Fig. 8c-d).
SteppedRing split_stepped_ring(const geom::Model& model, int volume_id, const geom::Vec3& axis,
                               const std::vector<int>& side_ids, const std::vector<RingCap>& caps) {
  SteppedRing out;
  auto cap_of_curve = [&](int curve) {
    for (const RingCap& c : caps) {
      if (c.curves.count(curve)) return c.id;
    }
    return 0;
  };
  auto level = [&](int cap) {
    const auto& b = model.surface(cap).box;
    return (0.5 * (b.min + b.max)).dot(axis);
  };
  // Caps touched by each side, with the dihedral class there.
  std::map<int, double> lev;
  std::map<std::pair<int, int>, bool> convex;  // (side, cap) -> below pi
  // (side, cap) -> the side leaves the cap downwards (against `axis`): the
  // contact bounds the segment below the cap. A side lies inside the volume
  // from a convex contact, outside the cap's outward normal from a re-entrant one.
  std::map<std::pair<int, int>, bool> goes_down;
  // Returns a Vec3, not an Eigen expression: the expression would refer to
  // the projection, a temporary gone at the end of the return statement.
  auto outward = [&](int cap) -> geom::Vec3 {
    const geom::Surface& f = model.surface(cap);
    return geom::sign(model.sense_in(cap, volume_id)) * f.geometry->project(0.5 * (f.box.min + f.box.max)).normal;
  };
  std::map<int, std::pair<double, double>> extent;  // side -> (lowest, highest level)
  for (int s : side_ids) {
    const auto& uses = model.surface(s).loops.front().uses;
    SideFace sf;
    sf.surface = s;
    sf.spans_caps = true;
    std::map<int, int> first_curve;
    for (const auto& u : uses) {
      const int c = cap_of_curve(u.curve);
      if (c) first_curve.emplace(c, u.curve);
    }
    if (first_curve.size() < 2) {
      out.why = "side surface " + std::to_string(s) + " touches fewer than two caps";
      return out;
    }
    double lo = 1e300, hi = -1e300;
    int lowest = 0;
    for (const auto& [c, curve] : first_curve) {
      const double d = cap_dihedral_degrees(model, volume_id, c, s, curve);
      if (d >= kMaxCapDihedral && d <= kReentrantMin) {
        out.why = "side surface " + std::to_string(s) + " meets cap " + std::to_string(c) + " at " +
                  text(d) + " degrees (tangent: neither an end nor a re-entrant shoulder)";
        return out;
      }
      convex[{s, c}] = d < kMaxCapDihedral;
      goes_down[{s, c}] = (d < kMaxCapDihedral ? -1.0 : 1.0) * outward(c).dot(axis) < 0;
      lev[c] = level(c);
      if (lev[c] < lo) {
        lo = lev[c];
        lowest = c;
      }
      hi = std::max(hi, lev[c]);
    }
    extent[s] = {lo, hi};
    for (const auto& u : uses) {
      const int c = cap_of_curve(u.curve);
      if (!c) continue;
      (c == lowest ? sf.target_curves : sf.source_curves).push_back(u.curve);
    }
    // Linking chains: maximal runs of non-cap curves, with the caps at their ends.
    const size_t n = uses.size();
    size_t start = 0;
    while (start < n && !cap_of_curve(uses[start].curve)) ++start;
    for (size_t k = 1; k <= n; ++k) {
      const size_t i = (start + k) % n;
      if (cap_of_curve(uses[i].curve)) continue;
      const int before = cap_of_curve(uses[(i + n - 1) % n].curve);
      if (!before) continue;  // inside a chain, handled from its first curve
      std::vector<int> chain;
      size_t j = i;
      while (!cap_of_curve(uses[j].curve)) {
        chain.push_back(uses[j].curve);
        j = (j + 1) % n;
      }
      sf.linking_chains.push_back(chain);
    }
    out.sides.push_back(sf);
  }
  // Caps by level, highest first; one cap per level.
  std::vector<int> order;
  for (const auto& [c, l] : lev) order.push_back(c);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return lev[a] > lev[b] || (lev[a] == lev[b] && a < b); });
  const double span = lev[order.front()] - lev[order.back()];
  for (size_t k = 0; k + 1 < order.size(); ++k) {
    if (lev[order[k]] - lev[order[k + 1]] <= 1e-6 * span) {
      out.why = "caps " + std::to_string(order[k]) + " and " + std::to_string(order[k + 1]) +
                " of one ring of sides lie at the same level";
      return out;
    }
  }
  const double tol = 1e-6 * span;
  for (size_t k = 0; k + 1 < order.size(); ++k) {
    RingSegment seg;
    seg.upper = order[k];
    seg.lower = order[k + 1];
    int touch[2] = {0, 0}, conv[2] = {0, 0};
    for (const SideFace& sf : out.sides) {
      const auto [lo, hi] = extent.at(sf.surface);
      if (hi < lev[seg.upper] - tol || lo > lev[seg.lower] + tol) continue;
      seg.sides.push_back(sf.surface);
      for (int e = 0; e < 2; ++e) {
        const int c = e == 0 ? seg.upper : seg.lower;
        const auto it = convex.find({sf.surface, c});
        if (it == convex.end() || goes_down.at({sf.surface, c}) != (e == 0)) continue;
        ++touch[e];
        conv[e] += it->second ? 1 : 0;
      }
      for (const auto& chain : sf.linking_chains) {
        const auto& uses = model.surface(sf.surface).loops.front().uses;
        const size_t n = uses.size();
        size_t at = 0;
        while (uses[at].curve != chain.front()) ++at;
        const int a = cap_of_curve(uses[(at + n - 1) % n].curve);
        const int b = cap_of_curve(uses[(at + chain.size()) % n].curve);
        if ((a == seg.upper && b == seg.lower) || (a == seg.lower && b == seg.upper)) {
          seg.linking_chains.push_back(chain);
        }
      }
    }
    for (int e = 0; e < 2; ++e) {
      if (touch[e] == 0 || (conv[e] != 0 && conv[e] != touch[e])) {
        out.why = "the sides between caps " + std::to_string(seg.upper) + " and " + std::to_string(seg.lower) +
                  (touch[e] == 0 ? " do not touch cap " : " meet cap ") +
                  std::to_string(e == 0 ? seg.upper : seg.lower) +
                  (touch[e] == 0 ? "" : " both below and above pi");
        return out;
      }
    }
    seg.convex_upper = conv[0] > 0;
    seg.convex_lower = conv[1] > 0;
    std::sort(seg.sides.begin(), seg.sides.end());
    out.segments.push_back(std::move(seg));
  }
  // Supported: open segments stepping down into one closed segment (each
  // starts convex and ends in a virtual cap beside the next segment's upper
  // cap), then open segments stepping up out of it (each ends convex on a
  // real cap below and starts in a virtual cap beside the previous segment's
  // lower cap): steps flush with outer walls on both ends of one barrel.
  size_t closed = out.segments.size();
  for (size_t k = 0; k < out.segments.size() && closed == out.segments.size(); ++k) {
    if (out.segments[k].convex_upper && out.segments[k].convex_lower) closed = k;
  }
  for (size_t k = 0; k < out.segments.size(); ++k) {
    const RingSegment& seg = out.segments[k];
    const bool ok = k < closed   ? seg.convex_upper && !seg.convex_lower
                    : k > closed ? !seg.convex_upper && seg.convex_lower
                                 : true;
    if (!ok || closed == out.segments.size()) {
      out.why = "the sides between caps " + std::to_string(seg.upper) + " and " + std::to_string(seg.lower) +
                " do not step from one convex cap to the next (open segments stepping down, one closed "
                "segment, open segments stepping up)";
      return out;
    }
  }
  std::sort(out.sides.begin(), out.sides.end(),
            [](const SideFace& a, const SideFace& b) { return a.surface < b.surface; });
  return out;
}

}  // namespace cooperage::cooper
