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

// How far segment k of a sampled closed loop (from point k to k + 1) may
// lie inside the curve it stands for: the sagitta of an arc through its
// ends, L * turn / 8, with the turn the smaller of the polyline's turns at
// its two ends (a corner at one end is the loop's, not the arc's), at most
// 25 degrees (16 samples of a full circle turn by 22.5).
std::vector<double> chord_sagittas(const std::vector<P2>& poly) {
  const size_t n = poly.size();
  std::vector<double> turn(n, 0.0), out(n, 0.0);
  for (size_t k = 0; k < n; ++k) {
    const P2 in = poly[k] - poly[(k + n - 1) % n];
    const P2 on = poly[(k + 1) % n] - poly[k];
    if (in.norm() > 0 && on.norm() > 0) {
      const double c = std::clamp(in.normalized().dot(on.normalized()), -1.0, 1.0);
      turn[k] = std::min(std::acos(c), 25.0 * 3.14159265358979323846 / 180.0);
    }
  }
  for (size_t k = 0; k < n; ++k) {
    const double len = (poly[(k + 1) % n] - poly[k]).norm();
    out[k] = len * std::min(turn[k], turn[(k + 1) % n]) / 8.0;
  }
  return out;
}

// A cap's loops projected along the sweep, with their bounding box.
struct Footprint {
  std::vector<std::vector<P2>> loops;
  std::vector<std::vector<double>> sagittas;  ///< per segment: chord_sagittas()
  Eigen::AlignedBox2d box;
  double width = 0;  ///< twice the area over the perimeter: a strip's width, a disc's radius
};

double signed_area(const std::vector<P2>& poly) {
  double a = 0;
  for (size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    a += poly[j].x() * poly[i].y() - poly[i].x() * poly[j].y();
  }
  return 0.5 * a;
}

Footprint footprint_of(const VolumeFacts& facts, int cap, const geom::Vec3& u,
                       const geom::Vec3& v) {
  Footprint f;
  double largest = 0, others = 0, perimeter = 0;
  for (const auto& loop : facts.face(cap)->loops) {
    f.loops.push_back(project_loop(facts, loop, u, v));
    const auto& poly = f.loops.back();
    f.sagittas.push_back(chord_sagittas(poly));
    for (size_t i = 0; i < poly.size(); ++i) {
      f.box.extend(poly[i]);
      perimeter += (poly[(i + 1) % poly.size()] - poly[i]).norm();
    }
    const double a = std::abs(signed_area(poly));
    others += std::min(a, largest);
    largest = std::max(a, largest);
  }
  f.width = perimeter > 0 ? 2 * std::max(largest - others, 0.0) / perimeter : 0;
  return f;
}

bool inside(const Footprint& f, const P2& p) {
  bool in = false;
  for (const auto& poly : f.loops) {
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

// Whether p lies farther than `allowed` from the footprint's curves, not
// from their chords: each segment's distance less its sagitta (a lower
// bound) must exceed it; the first that does not decides.
bool farther_than(const Footprint& f, const P2& p, double allowed) {
  for (size_t l = 0; l < f.loops.size(); ++l) {
    const auto& poly = f.loops[l];
    for (size_t i = 0; i < poly.size(); ++i) {
      const P2& a = poly[i];
      const P2& b = poly[(i + 1) % poly.size()];
      const P2 ab = b - a;
      const double t =
          ab.squaredNorm() > 0 ? std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0) : 0.0;
      if (!((a + t * ab - p).norm() - f.sagittas[l][i] > allowed)) return false;
    }
  }
  return true;
}

// Whether the segment ab runs inside the footprint deeper than `tol`: its
// ends, and the middles of its pieces between crossings of the footprint's
// boundary (a long edge can cross a narrow cap between its two ends).
// `slack` (the segment's own sagitta) is allowed on top, except for a piece
// that crosses the cap from one side to the opposite one, steeply (the
// boundary edges it crosses run against each other): a chord sampling a
// curve of the cap's boundary runs along it, not across it. A foot's
// circle crossed a pocket floor's leg 0.15 wide, less than twice its
// chords' sagitta (0.085), and the plan took the floor as uncut (campaign
// seed 7 case 50).
bool reaches_inside(const Footprint& f, const P2& a, const P2& b, double tol, double slack) {
  Eigen::AlignedBox2d seg(a);
  seg.extend(b);
  if (!f.box.intersects(seg)) return false;
  struct Crossing {
    double t;
    P2 along;  // the crossed boundary edge, unit
  };
  std::vector<Crossing> ts{{0.0, P2::Zero()}, {1.0, P2::Zero()}};
  const P2 ab = b - a;
  for (const auto& poly : f.loops) {
    for (size_t i = 0; i < poly.size(); ++i) {
      const P2& p = poly[i];
      const P2 pq = poly[(i + 1) % poly.size()] - p;
      const double den = ab.x() * pq.y() - ab.y() * pq.x();
      if (den == 0) continue;  // parallel: its ends are tested as points
      const P2 ap = p - a;
      const double t = (ap.x() * pq.y() - ap.y() * pq.x()) / den;
      const double s = (ap.x() * ab.y() - ap.y() * ab.x()) / den;
      if (t > 0 && t < 1 && s >= 0 && s <= 1) ts.push_back({t, pq.normalized()});
    }
  }
  std::sort(ts.begin(), ts.end(), [](const Crossing& x, const Crossing& y) { return x.t < y.t; });
  auto deep = [&](double t, double allowed) {
    const P2 x = a + t * ab;
    return inside(f, x) && farther_than(f, x, allowed);
  };
  if (deep(0.0, tol + slack)) return true;
  // Steeper than two samplings of one curve can cross (chord_sagittas()'s 25
  // degrees): a chord of a boss's rim crossed the corner of its overhang's
  // underside, bounded by the same circle, from one edge to the other.
  const P2 dir = ab.normalized();
  auto steep = [&](const P2& e) { return std::abs(dir.x() * e.y() - dir.y() * e.x()) > 0.42; };
  for (size_t k = 0; k + 1 < ts.size(); ++k) {
    const bool across =
        ts[k].along.dot(ts[k + 1].along) < -0.5 && steep(ts[k].along) && steep(ts[k + 1].along);
    if (deep(0.5 * (ts[k].t + ts[k + 1].t), across ? tol : tol + slack)) return true;
  }
  return false;
}

}  // namespace

std::vector<int> cut_caps(const VolumeFacts& facts, const std::vector<int>& caps,
                          const geom::Vec3& down, double relative) {
  const geom::Vec3 d = down.normalized();
  const geom::Vec3 e = std::abs(d.x()) > 0.6 ? geom::Vec3::UnitY() : geom::Vec3::UnitX();
  const geom::Vec3 u = (e - e.dot(d) * d).normalized();
  const geom::Vec3 v = d.cross(u);
  std::map<int, Footprint> footprint;
  for (int c : caps) footprint[c] = footprint_of(facts, c, u, v);
  std::vector<int> out;
  for (int c : caps) {
    const Footprint& mine = footprint.at(c);
    // Relative to the cap's own width, not only the volume's size: a long
    // boss overhanging its block by less than 0.5 % of the whole part still
    // has its top cut by the block's edge (issue 15).
    const double tol = relative * std::min(facts.size(), mine.width);
    bool cut = false;
    for (int o : caps) {
      if (o == c || cut) continue;
      // Two samplings of one circle (a rim split into two curves on one cap,
      // three on the other, where a neighbour's edge ends on it) differ by
      // their chords' sagittas, 0.036 on a radius of 7.5: not a cut.
      const Footprint& other = footprint.at(o);
      for (size_t l = 0; l < other.loops.size() && !cut; ++l) {
        const auto& loop = other.loops[l];
        for (size_t k = 0; k < loop.size() && !cut; ++k)
          cut =
              reaches_inside(mine, loop[k], loop[(k + 1) % loop.size()], tol, other.sagittas[l][k]);
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
    // Anything deeper than sampling noise is a cut: imprinting cuts a cap at
    // any depth, and a cap meshed beforehand cannot be cut then (a boss
    // overhanging its block by 0.02, 0.2 % of its top's width, at size 3.6:
    // with 0.5 % here the plan took the top as it was and the run failed).
    out.cut = cut_caps(facts, caps, *down, 1e-4);
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
