#include "schemes/cooper/side_lattice.h"

#include "framework/scheme/vertex_angles.h"
#include "schemes/cooper/side_corner_types.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

namespace cooperage::cooper {
namespace {

using scheme::VertexType;

struct UnionFind {
  std::map<int, int> parent;
  int find(int x) {
    auto it = parent.find(x);
    if (it == parent.end()) {
      parent[x] = x;
      return x;
    }
    if (it->second == x) return x;
    const int r = find(it->second);
    parent[x] = r;
    return r;
  }
  void unite(int a, int b) {
    a = find(a);
    b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

std::string text(double d) {
  std::ostringstream s;
  s.precision(4);
  s << d;
  return s.str();
}

// A side meeting a cap tangentially (issue 16: a fillet, a dome's rim) is
// swept when every rib leaving the cap there bends into the volume (the
// contact is then an end, convex) and rises kTangentLiftDeg off the cap
// within its first curve; the rib's first interval is made at least that
// long (SideLattice::graded, tangent_grading.h). Else refused, with the
// rise found.
bool tangent_contact(const VolumeFacts& facts, double angle, CapContact contact, SideLattice& out) {
  const std::string what = "side surface " + std::to_string(contact.face) + " meets cap " +
                           std::to_string(contact.cap) + " at " + text(angle) +
                           " degrees along curve " + std::to_string(contact.curve) + " (tangent";
  std::set<int> chain_curves;
  for (const LinkChain& c : out.chains) {
    if (c.face == contact.face) chain_curves.insert(c.curves.begin(), c.curves.end());
  }
  std::vector<TangentDeparture> ribs;
  for (const TangentDeparture& d : facts.departures) {
    if (d.curve == contact.curve && d.face == contact.face && d.other == contact.cap &&
        chain_curves.count(d.along))
      ribs.push_back(d);
  }
  if (ribs.empty()) {
    out.why = what + ": no curve of the side leaves it toward another level)";
    return false;
  }
  for (const TangentDeparture& d : ribs) {
    if (d.first_size <= 0) {
      out.why = what + ", and curve " + std::to_string(d.along) + " leaving it rises at most " +
                text(d.max_lift) + " degrees off the cap; a hex there needs " +
                text(kTangentLiftDeg) + ")";
      return false;
    }
    // A rib bending out of the volume (a concave blend, a groove) would
    // make a re-entrant shoulder whose virtual cap continues the side
    // tangentially; not swept yet (occt_OCC2368's half-round grooves
    // planned and then inverted a hex at D/40).
    if (!d.into_volume) {
      out.why = what + ", and curve " + std::to_string(d.along) +
                " leaving it bends out of the volume: a concave blend is not swept yet)";
      return false;
    }
  }
  contact.convex = true;
  out.contacts.push_back(contact);
  out.graded.insert(out.graded.end(), ribs.begin(), ribs.end());
  return true;
}

int vertex_at_start(const VolumeFacts& facts, const UseFact& u) {
  const CurveFact& c = facts.curves.at(u.curve);
  return u.forward ? c.start : c.end;
}
int vertex_at_end(const VolumeFacts& facts, const UseFact& u) {
  const CurveFact& c = facts.curves.at(u.curve);
  return u.forward ? c.end : c.start;
}

// Lattice directions of a single loop: d_0 = 0, d_k = d_{k-1} + t_k (mod 4),
// t = END 1, SIDE 0, CORNER -1 (ALGORITHMS.md sec. 1). Empty with `why`
// when a corner has no type, is a REVERSAL, or the turns do not close.
std::vector<int> loop_directions(const FaceFact& f, std::string& why) {
  const size_t n = f.loops.front().size();
  if (f.angles.size() != n) {
    why = "surface " + std::to_string(f.id) + " has no corner angles";
    return {};
  }
  std::vector<int> turn(n);
  int sum = 0;
  for (size_t k = 0; k < n; ++k) {
    const auto type = scheme::classify_angle(f.angles[k]);
    if (!type || *type == VertexType::Reversal) {
      why = "surface " + std::to_string(f.id) + " has a corner of " + text(f.angles[k]) +
            " degrees before curve " + std::to_string(f.loops.front()[k].curve) +
            (type ? " (a REVERSAL)"
                  : " (no vertex type below " + text(scheme::kMinEndAngle) + " degrees)");
      return {};
    }
    turn[k] = static_cast<int>(*type);
    sum += turn[k];
  }
  if (sum != 4) {
    why = "the corners of surface " + std::to_string(f.id) + " turn by " + std::to_string(sum) +
          " quarter turns, not 4 (no lattice)";
    return {};
  }
  std::vector<int> d(n);
  d[0] = 0;
  for (size_t k = 1; k < n; ++k) d[k] = ((d[k - 1] + turn[k]) % 4 + 4) % 4;
  return d;
}

// The knife edge at a chain curve between two sides, as a sentence; empty
// when the faces meet at least kMinSideDihedral from folding flat.
std::string knife_edge_text(const VolumeFacts& facts, int curve) {
  const auto dh = facts.dihedral.find(curve);
  if (dh == facts.dihedral.end()) return "";
  const double fold = std::min(dh->second, 360.0 - dh->second);
  if (fold >= kMinSideDihedral) return "";
  const auto faces = facts.faces_of_curve(curve);
  const std::string pair =
      "side surfaces " + std::to_string(faces.front()) + " and " + std::to_string(faces.back());
  if (fold < 0.5)
    return pair + " meet tangentially along curve " + std::to_string(curve) +
           " (a cusp: a knife edge no hexahedron can follow)";
  return pair + " meet at " + text(dh->second) + " degrees along curve " + std::to_string(curve) +
         " (a knife edge: hexahedra along it have a scaled Jacobian of at most " +
         text(std::sin(fold * M_PI / 180.0)) + ")";
}

}  // namespace

void type_corners(FaceFact& f) {
  f.directions.clear();
  f.directions_why.clear();
  f.ambiguous_corners = false;
  if (f.loops.size() != 1) return;
  f.directions = loop_directions(f, f.directions_why);
  // Corners between two types wait for the neighbours (side_corner_types.h).
  f.ambiguous_corners = has_ambiguous_corner(f.angles) &&
                        f.angles.size() == f.loops.front().size() && can_turn_four(f.angles);
}

bool cannot_be_side(const FaceFact& f) {
  return f.loops.size() != 1 || !f.submappable || (!f.ambiguous_corners && f.directions.empty());
}

// cite: Blacker 1996, sec. 3 (side faces jointly submappable, Fig. 4/5).
SideLattice side_lattice(const VolumeFacts& facts, const std::set<int>& caps) {
  SideLattice out;
  std::vector<std::pair<CapContact, double>> tangent;  // contacts at ~180 degrees, and the angle
  out.caps.assign(caps.begin(), caps.end());
  for (int c : caps) {
    if (!facts.face(c)) {
      out.why =
          "surface " + std::to_string(c) + " does not bound volume " + std::to_string(facts.volume);
      return out;
    }
  }
  // Side face -> lattice direction per use: the face's own (FaceFact), or
  // its typing with the neighbours (`retyped`).
  std::map<int, const std::vector<int>*> dirs;
  std::map<int, std::vector<int>> retyped;
  std::set<int> ambiguous;               // sides typed once their neighbours are
  for (const FaceFact& f : facts.faces) {
    if (caps.count(f.id)) continue;
    if (cannot_be_side(f)) {
      out.why = f.loops.size() != 1 || !f.submappable
                    ? "surface " + std::to_string(f.id) + " cannot be a side (" + f.submap_why + ")"
                    : f.directions_why;
      return out;
    }
    if (f.ambiguous_corners) ambiguous.insert(f.id);
    dirs[f.id] = &f.directions;
    out.sides.push_back(f.id);
  }
  // Cap curves: (curve -> (cap, loop index)); after the sides, which refuse
  // most sortings (a face of several loops that is not a cap).
  std::map<int, std::vector<std::pair<int, int>>> cap_curves;
  for (int c : caps) {
    const FaceFact* f = facts.face(c);
    for (size_t l = 0; l < f->loops.size(); ++l) {
      for (const UseFact& u : f->loops[l]) cap_curves[u.curve].push_back({c, static_cast<int>(l)});
    }
  }
  // Roles: parity of the lattice direction that runs along, per face.
  std::map<int, int> along_parity;  // face -> 0 or 1
  std::map<int, bool> curve_along;  // decided curves
  for (const auto& [curve, list] : cap_curves) curve_along[curve] = true;
  // Sides whose corners fit one typing first; then one with a corner between
  // two types, typed to agree with its neighbours, and the rigid ones again.
  for (bool progress = true; progress;) {
    progress = false;
    for (int pass = 0; pass < 2 && !progress; ++pass) {
      for (int s : out.sides) {
        if (along_parity.count(s) || (pass == 0 && ambiguous.count(s))) continue;
        const auto& loop = facts.face(s)->loops.front();
        std::vector<int> decided(loop.size(), -1);
        bool any = false;
        for (size_t k = 0; k < loop.size(); ++k) {
          const auto it = curve_along.find(loop[k].curve);
          if (it == curve_along.end()) continue;
          decided[k] = it->second ? 1 : 0;
          any = true;
        }
        if (!any) continue;
        int parity = -1;
        if (ambiguous.count(s)) {
          if (const auto t = type_side_corners(facts.face(s)->angles, decided)) {
            dirs[s] = &(retyped[s] = t->directions);
            parity = t->parity;
            for (size_t k = 0; k < loop.size(); ++k) {
              const auto own = scheme::classify_angle(facts.face(s)->angles[k]);
              if (own && static_cast<int>(*own) == t->turns[k]) continue;
              out.retyped.push_back({s, vertex_at_start(facts, loop[k]), t->turns[k]});
            }
          }
        }
        const std::vector<int>& d = *dirs.at(s);
        if (parity < 0) {
          if (d.empty()) {
            out.why = "the corners of side surface " + std::to_string(s) +
                      " take no types that agree with its neighbours (no lattice)";
            return out;
          }
          for (size_t k = 0; k < loop.size() && parity < 0; ++k) {
            if (decided[k] >= 0) parity = (d[k] + (decided[k] ? 0 : 1)) % 2;
          }
        }
        for (size_t k = 0; k < loop.size(); ++k) {
          const bool along = d[k] % 2 == parity;
          const auto [it, added] = curve_along.emplace(loop[k].curve, along);
          if (!added && it->second != along) {
            out.why =
                "curve " + std::to_string(loop[k].curve) + " runs " +
                (it->second ? "along the caps" : "between the caps") +
                " for a neighbour of side surface " + std::to_string(s) + " but " +
                (along ? "along" : "between") +
                " them in its lattice; the sides are not jointly submappable (Blacker 1996, "
                "Fig. 5)";
            return out;
          }
        }
        along_parity[s] = parity;
        progress = true;
        if (pass == 1) break;  // the rigid sides again first
      }
    }
  }
  for (int s : out.sides) {
    if (!along_parity.count(s)) {
      out.why = "side surface " + std::to_string(s) +
                " touches no cap and no oriented side, so its sweep direction is unknown";
      return out;
    }
  }
  for (const auto& [curve, along] : curve_along) {
    if (along) out.along.insert(curve);
  }
  // Level classes: the ends of every curve running along, and every cap.
  UnionFind uf;
  for (const auto& [id, p] : facts.vertices) uf.find(id);
  for (int curve : out.along) {
    const CurveFact& c = facts.curves.at(curve);
    uf.unite(c.start, c.end);
  }
  for (int c : caps) {
    int first = -1;
    for (const auto& loop : facts.face(c)->loops) {
      for (const UseFact& u : loop) {
        const int v = facts.curves.at(u.curve).start;
        if (first < 0) first = v;
        uf.unite(first, v);
      }
    }
  }
  std::map<int, int> dense;
  for (const auto& [id, p] : facts.vertices) {
    const int r = uf.find(id);
    const auto [it, added] = dense.emplace(r, static_cast<int>(dense.size()));
    out.vertex_class[id] = it->second;
  }
  out.classes = static_cast<int>(dense.size());
  for (int c : caps) {
    out.cap_class[c] =
        out.vertex_class.at(facts.curves.at(facts.face(c)->loops.front().front().curve).start);
  }
  // Chains, contacts, stacked curves.
  for (int s : out.sides) {
    const auto& loop = facts.face(s)->loops.front();
    const std::vector<int>& d = *dirs.at(s);
    const int parity = along_parity.at(s);
    const size_t n = loop.size();
    auto along_at = [&](size_t k) { return d[k % n] % 2 == parity; };
    auto sign_of = [&](size_t k) { return d[k % n] == (parity + 1) % 4 ? 1 : -1; };
    size_t start = n;
    for (size_t k = 0; k < n && start == n; ++k) {
      if (along_at(k) && !along_at(k + n - 1)) start = k;  // first use of a run along
    }
    if (start == n) {
      out.why = "side surface " + std::to_string(s) + " has no curve running along the caps";
      return out;
    }
    std::set<int> classes;
    for (size_t i = 0; i < n; ++i) {
      const size_t k = (start + i) % n;
      const UseFact& u = loop[k];
      if (along_at(k)) {
        classes.insert(out.vertex_class.at(vertex_at_start(facts, u)));
        // The face lies on the left of the loop: on the +j side of a run
        // walked along +i (the lattice direction `parity`), else on -j.
        const int leaving = d[k] == parity ? 1 : -1;
        const auto cc = cap_curves.find(u.curve);
        const int cls = out.vertex_class.at(vertex_at_start(facts, u));
        if (cc == cap_curves.end()) {
          out.stacked.push_back({u.curve, s, leaving, cls});
          continue;
        }
        const auto dh = facts.dihedral.find(u.curve);
        for (const auto& [cap, cap_loop] : cc->second) {
          if (dh == facts.dihedral.end()) {
            out.why = "curve " + std::to_string(u.curve) + " between side surface " +
                      std::to_string(s) + " and cap " + std::to_string(cap) +
                      " has no dihedral angle";
            return out;
          }
          const double a = dh->second;
          if (a >= kMaxCapDihedral && a <= kReentrantMin) {  // decided once the chains are known
            tangent.push_back({{s, cap, cap_loop, u.curve, true, leaving, cls}, a});
            continue;
          }
          out.contacts.push_back({s, cap, cap_loop, u.curve, a < kMaxCapDihedral, leaving, cls});
        }
        continue;
      }
      if (along_at(k + n - 1)) {  // a chain starts here
        LinkChain chain;
        chain.face = s;
        chain.lattice_sign = sign_of(k);
        chain.from_vertex = vertex_at_start(facts, u);
        for (size_t m = k; !along_at(m) && m < k + n; ++m) {
          chain.curves.push_back(loop[m % n].curve);
          chain.forward.push_back(loop[m % n].forward);
          chain.to_vertex = vertex_at_end(facts, loop[m % n]);
          chain.length += facts.curves.at(loop[m % n].curve).length;
        }
        for (int curve : chain.curves) {
          if (out.knife_edge.empty()) out.knife_edge = knife_edge_text(facts, curve);
        }
        chain.from_class = out.vertex_class.at(chain.from_vertex);
        chain.to_class = out.vertex_class.at(chain.to_vertex);
        if (chain.from_class == chain.to_class) {
          out.why =
              "side surface " + std::to_string(s) + ": the curves " +
              std::to_string(chain.curves.front()) + (chain.curves.size() > 1 ? "..." : "") +
              " link one level to itself (both ends lie on one cap or on one run along the caps)";
          return out;
        }
        out.chains.push_back(std::move(chain));
      }
    }
    out.face_classes[s].assign(classes.begin(), classes.end());
  }
  for (auto& [contact, angle] : tangent) {
    if (!tangent_contact(facts, angle, contact, out)) return out;
  }
  out.ok = true;
  return out;
}

std::vector<AlongPair> side_along_pairs(const VolumeFacts& facts, const SideLattice& lattice) {
  std::vector<AlongPair> out;
  for (int s : lattice.sides) {
    std::vector<std::pair<size_t, UseFact>> along;  // (loop, use)
    const auto& loops = facts.face(s)->loops;
    for (size_t l = 0; l < loops.size(); ++l) {
      for (const UseFact& u : loops[l]) {
        if (lattice.along.count(u.curve)) along.emplace_back(l, u);
      }
    }
    if (along.size() != 2 || along[0].second.curve == along[1].second.curve) continue;
    AlongPair pair{along[0].second.curve, along[1].second.curve, 0};
    const auto open = [&](int c) {
      const auto it = facts.curves.find(c);
      return it != facts.curves.end() && it->second.start != it->second.end;
    };
    if (along[0].first == along[1].first && open(pair.a) && open(pair.b))
      pair.orientation = along[0].second.forward != along[1].second.forward ? 1 : -1;
    for (int c : {pair.a, pair.b}) {
      for (int f : facts.faces_of_curve(c)) {
        const FaceFact* face = facts.face(f);
        if (f == s || face->loops.size() != 1 || face->angles.size() != face->loops[0].size())
          continue;
        const auto& uses = face->loops[0];
        for (size_t k = 0; k < uses.size(); ++k) {
          if (uses[k].curve != c) continue;
          const double before = face->angles[k];
          const double after = face->angles[(k + 1) % uses.size()];
          if (std::min(before, after) < kSliverRingCorner) pair.sliver_end = true;
        }
      }
    }
    out.push_back(pair);
  }
  return out;
}

}  // namespace cooperage::cooper
