#include "schemes/cooper/cap_roles.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

namespace cooperage::cooper {
namespace {

using P2 = Eigen::Vector2d;

// A face loop as a closed 2D polyline along `down`.
std::vector<P2> project_loop(const VolumeFacts& facts, const std::vector<UseFact>& loop,
                             const geom::Vec3& u, const geom::Vec3& v) {
  std::vector<P2> out;
  for (const UseFact& use : loop) {
    const auto& s = facts.curves.at(use.curve).samples;
    const size_t n = s.size();
    for (size_t k = 0; k + 1 < n; ++k) {
      const geom::Vec3& x = use.forward ? s[k] : s[n - 1 - k];
      out.emplace_back(x.dot(u), x.dot(v));
    }
  }
  return out;
}

bool inside(const std::vector<std::vector<P2>>& loops, const P2& p) {
  bool in = false;
  for (const auto& poly : loops) {
    for (size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
      if ((poly[i].y() > p.y()) != (poly[j].y() > p.y()) &&
          p.x() <
              (poly[j].x() - poly[i].x()) * (p.y() - poly[i].y()) / (poly[j].y() - poly[i].y()) +
                  poly[i].x()) {
        in = !in;
      }
    }
  }
  return in;
}

double distance(const std::vector<std::vector<P2>>& loops, const P2& p) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& poly : loops) {
    for (size_t i = 0; i < poly.size(); ++i) {
      const P2& a = poly[i];
      const P2& b = poly[(i + 1) % poly.size()];
      const P2 ab = b - a;
      const double t =
          ab.squaredNorm() > 0 ? std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0) : 0.0;
      best = std::min(best, (a + t * ab - p).norm());
    }
  }
  return best;
}

}  // namespace

std::vector<int> cut_caps(const VolumeFacts& facts, const std::vector<int>& caps,
                          const geom::Vec3& down, double tolerance) {
  const geom::Vec3 d = down.normalized();
  const geom::Vec3 e = std::abs(d.x()) > 0.6 ? geom::Vec3::UnitY() : geom::Vec3::UnitX();
  const geom::Vec3 u = (e - e.dot(d) * d).normalized();
  const geom::Vec3 v = d.cross(u);
  std::map<int, std::vector<std::vector<P2>>> footprint;
  for (int c : caps) {
    for (const auto& loop : facts.face(c)->loops)
      footprint[c].push_back(project_loop(facts, loop, u, v));
  }
  std::vector<int> out;
  for (int c : caps) {
    const auto& mine = footprint.at(c);
    bool cut = false;
    for (int o : caps) {
      if (o == c || cut) continue;
      for (const auto& loop : footprint.at(o)) {
        for (const P2& p : loop) {
          if (inside(mine, p) && distance(mine, p) > tolerance) {
            cut = true;
            break;
          }
        }
        if (cut) break;
      }
    }
    if (cut) out.push_back(c);
  }
  return out;
}

// cite: Blacker 1996, sec. 3 (caps initially unmeshed) and 6.1 (a stack is
// meshed once, from its first or last cap or an existing mesh).
CapRoles cap_roles(const VolumeFacts& facts, const SweepOrder& order, const BarrelTree& tree,
                   const geom::Vec3* down, const CapSchemeOf& scheme_of, bool polygon_mesher) {
  CapRoles out;
  std::vector<int> caps;
  for (const auto& [cap, upper] : order.upper) caps.push_back(cap);
  if (down) {
    out.cut = cut_caps(facts, caps, *down, 5e-3 * facts.size());
  } else {
    for (size_t b = 0; b < tree.barrels.size(); ++b) {
      if (tree.barrels[b].lower.size() > 1) {
        out.why = "barrel " + std::to_string(b + 1) + " ends on " +
                  std::to_string(tree.barrels[b].lower.size()) +
                  " subcaps; imprinting them upwards needs a straight sweep axis";
        return out;
      }
    }
  }
  for (int c : caps) {
    const bool cut = std::binary_search(out.cut.begin(), out.cut.end(), c);
    std::string why;
    const std::string s = order.upper.at(c) && !cut ? scheme_of(c, why) : std::string();
    if (!s.empty()) {
      out.scheme[c] = s;
      continue;
    }
    // A cap shared with another volume is meshed here too (the sweep ends on
    // it, or other caps are imprinted on it): the selector then meshes this
    // volume first and hands the cap's mesh to the neighbour, if that one
    // takes it as it finds it (scheme::VolumeScheme::takes_existing_mesh).
    out.by_volume.push_back(c);
    if (order.upper.at(c)) out.needs_polygon_mesher = true;
  }
  if (out.needs_polygon_mesher && !polygon_mesher) {
    out.why = "caps ";
    for (size_t k = 0; k < out.by_volume.size(); ++k) {
      if (order.upper.at(out.by_volume[k])) out.why += std::to_string(out.by_volume[k]) + " ";
    }
    out.why +=
        "are imprinted (or have no surface scheme), and their pieces need a polygon mesher (pave's "
        "2D core), "
        "which is not available";
    return out;
  }
  out.ok = true;
  return out;
}

}  // namespace cooperage::cooper
