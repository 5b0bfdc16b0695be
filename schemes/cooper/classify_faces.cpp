#include "schemes/cooper/classify_faces.h"

#include "framework/scheme/vertex_angles.h"
#include "schemes/cooper/cap_dihedral.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

namespace cooperage::cooper {
namespace {

using scheme::VertexType;

std::string volume_name(int id) { return "volume " + std::to_string(id); }

std::string join(const std::vector<int>& ids) {
  std::string s;
  for (size_t i = 0; i < ids.size(); ++i) s += (i ? ", " : "") + std::to_string(ids[i]);
  return s;
}

// What a face brings to the classification, computed once per call.
struct FaceInfo {
  int id = 0;
  int loops = 0;
  int curves = 0;
  double area = 0;
  std::set<int> curve_set;
  bool side_ok = false;       // submappable with one loop
  double side_score = 0;
  std::string side_why;
  std::vector<scheme::LoopCorner> corners;  // outer loop
  // Composite cap: faces filling hole loops of this one (subcaps), and the
  // indices of this face's loops that remain the cap boundary.
  std::vector<int> subcaps;
  std::vector<int> boundary_loops;
};

// Largest deviation from 180 degrees tolerated between a cap and a subcap
// filling one of its hole loops (coplanar, or nearly so).
constexpr double kSubcapFlatness = 15.0;

enum class Role { Source, Target, Link };

// Empty when surface f_id can be a side between caps a (upper) and b (lower), else why.
std::string check_side_impl(const geom::Model& model, int f_id,
                            const std::vector<scheme::LoopCorner>& corners, int a_id,
                            const std::set<int>& a_curves, int b_id, const std::set<int>& b_curves,
                            SideFace& side) {
  const std::string name = "surface " + std::to_string(f_id);
  const auto& uses = model.surface(f_id).loops.front().uses;
  const size_t n = uses.size();
  std::vector<Role> role(n);
  side = SideFace{};
  side.surface = f_id;
  for (size_t k = 0; k < n; ++k) {
    const int c = uses[k].curve;
    role[k] = a_curves.count(c) ? Role::Source : b_curves.count(c) ? Role::Target : Role::Link;
    if (role[k] == Role::Source) side.source_curves.push_back(c);
    if (role[k] == Role::Target) side.target_curves.push_back(c);
  }
  if (side.source_curves.empty() || side.target_curves.empty()) {
    return name + " does not link caps " + std::to_string(a_id) + " and " + std::to_string(b_id) +
           " (it touches " + (side.source_curves.empty() ? "not the first" : "not the second") +
           " cap); a one-barrel side runs from cap to cap";
  }
  // Junction rules: cap/link turns are END or CORNER, inside a linking chain
  // or along a cap boundary SIDE (the side's lattice directions, sec. 3).
  int cap_runs[2] = {0, 0};
  for (size_t k = 0; k < n; ++k) {
    const Role prev = role[(k + n - 1) % n];
    const Role cur = role[k];
    const auto& corner = corners[k];
    const std::string at = name + ": the junction at vertex " + std::to_string(corner.vertex) +
                           " between curves " + std::to_string(uses[(k + n - 1) % n].curve) +
                           " and " + std::to_string(uses[k].curve);
    if (!corner.type) return at + " has no vertex type (angle below 45 degrees)";
    const VertexType t = *corner.type;
    if ((prev == Role::Source && cur == Role::Target) ||
        (prev == Role::Target && cur == Role::Source)) {
      return at + " joins the two caps directly; a side needs linking curves between them";
    }
    if (prev == cur) {
      if (t != VertexType::Side) {
        return at + " is " + scheme::to_string(t) + " inside a " +
               (cur == Role::Link ? "linking chain" : "cap boundary") + "; it must be SIDE";
      }
    } else if (t != VertexType::End && t != VertexType::Corner) {
      return at + " is " + scheme::to_string(t) +
             " between a cap boundary and a linking curve; it must be END or CORNER";
    }
    if (cur != Role::Link && prev != cur) ++cap_runs[cur == Role::Source ? 0 : 1];
  }
  if (cap_runs[0] != 1 || cap_runs[1] != 1) {
    return name + " meets the caps in " + std::to_string(cap_runs[0]) + " and " +
           std::to_string(cap_runs[1]) + " separate runs; a one-barrel side meets each once";
  }
  // Linking chains: maximal runs of linking uses, starting after a cap run.
  for (size_t k = 0; k < n; ++k) {
    if (role[k] != Role::Link || role[(k + n - 1) % n] == Role::Link) continue;
    std::vector<int> chain;
    for (size_t m = k; role[m % n] == Role::Link && chain.size() < n; ++m) {
      chain.push_back(uses[m % n].curve);
    }
    side.linking_chains.push_back(chain);
  }
  return {};
}

// Empty when `f` can be a side between caps a (upper) and b (lower), else why.
std::string check_side(const geom::Model& model, const FaceInfo& f, const FaceInfo& a,
                       const FaceInfo& b, SideFace& side) {
  if (!f.side_ok) return "surface " + std::to_string(f.id) + " cannot be a side: " + f.side_why;
  return check_side_impl(model, f.id, f.corners, a.id, a.curve_set, b.id, b.curve_set, side);
}

// Empty when (a, b) are the two caps of a one-barrel sweep, else why.
std::string check_pair(const geom::Model& model, int volume_id, const std::vector<FaceInfo>& faces,
                       const FaceInfo& a, const FaceInfo& b, std::vector<SideFace>& sides) {
  const std::string pair = "caps " + std::to_string(a.id) + " and " + std::to_string(b.id);
  for (int c : a.curve_set) {
    if (b.curve_set.count(c)) return pair + " share curve " + std::to_string(c);
  }
  if (a.loops != b.loops) {
    return pair + " have " + std::to_string(a.loops) + " and " + std::to_string(b.loops) +
           " loops; a one-to-one sweep needs the same number";
  }
  sides.clear();
  for (const FaceInfo& f : faces) {
    if (f.id == a.id || f.id == b.id) continue;
    SideFace side;
    const std::string why = check_side(model, f, a, b, side);
    if (!why.empty()) return pair + ": " + why;
    sides.push_back(std::move(side));
  }
  // Every cap curve borders exactly one side; the end caps are convex to it.
  for (const FaceInfo* cap : {&a, &b}) {
    for (int c : cap->curve_set) {
      int side_id = 0;
      int count = 0;
      for (const SideFace& s : sides) {
        const auto& own = cap == &a ? s.source_curves : s.target_curves;
        if (std::find(own.begin(), own.end(), c) != own.end()) {
          side_id = s.surface;
          ++count;
        }
      }
      if (count != 1) {
        return pair + ": curve " + std::to_string(c) + " of cap " + std::to_string(cap->id) +
               " borders " + std::to_string(count) + " side faces; it must border one";
      }
      const double angle = cap_dihedral_degrees(model, volume_id, cap->id, side_id, c);
      if (!(angle < kMaxCapDihedral)) {
        std::ostringstream s;
        s.precision(4);
        s << "surface " << cap->id << " cannot be an end cap: its dihedral angle with side "
          << "surface " << side_id << " along curve " << c << " is " << angle
          << " degrees (an end cap needs less than 180)";
        return s.str();
      }
    }
  }
  return {};
}

// The cap schemes are asked of the registry by role (scheme::Role), never
// by name, so a plug-in scheme serving the role competes on its score.

// Wedge mode: the best tri-cap scheme ("tri"), or why none applies.
std::string tri_cap_scheme(const geom::Model& model, const scheme::Registry& registry,
                           int surface, std::string& why) {
  const scheme::RoleChoice c = scheme::best_surface_scheme(
      registry, scheme::Role::TriCap, scheme::SurfaceView{model, surface, nullptr});
  if (c.scheme) return std::string(c.scheme->name());
  why = "no triangle scheme meshes source cap surface " + std::to_string(surface) +
        " for wedges (" + c.reasons + ")";
  return {};
}

// Mixed mode: the best-scoring scheme serving mixed caps, where an all-quad
// one (map, submap: it also serves quad caps; its score is the scaled
// Jacobian it reaches) counts only at kMixedMinQuadQuality or more, so a
// face where it would squash a corner goes to quad_dominant (pave with its
// quads below that quality split into triangles). Plain pave does not serve
// mixed caps: it keeps a poor quad where mixed mode wants two triangles.
std::string mixed_cap_scheme(const geom::Model& model, const scheme::Registry& registry,
                             int surface, std::string& why) {
  const scheme::SurfaceView view{model, surface, nullptr};
  const scheme::SurfaceScheme* best = nullptr;
  double best_score = -1.0;
  std::string reasons;
  for (const scheme::SurfaceScheme* s : registry.surface_schemes(scheme::Role::MixedCap)) {
    const scheme::Applicability a = s->applicable(view);
    const bool quads_only = scheme::serves(s->serves(), scheme::Role::QuadCap);
    if (a.ok && quads_only && a.score < kMixedMinQuadQuality) continue;
    if (!a.ok) reasons += (reasons.empty() ? "" : "; ") + std::string(s->name()) + ": " + a.why;
    if (a.ok && a.score > best_score) {
      best = s;
      best_score = a.score;
    }
  }
  if (best) return std::string(best->name());
  why = "no mixed-cap scheme meshes source cap surface " + std::to_string(surface) +
        " for a wedge/hex mix (" +
        (reasons.empty() ? std::string("no registered surface scheme serves mixed caps")
                         : reasons) +
        ")";
  return {};
}

// The cap scheme of an element kind: hex mode the best-scoring quad-cap
// scheme (scores are the scaled Jacobian each can reach, so a corner
// map/submap would squash goes to pave; ties keep the registration order
// map, submap, pave, then plug-ins); wedge mode tri_cap_scheme; mixed mode
// mixed_cap_scheme.
std::string cap_scheme_impl(const geom::Model& model, const scheme::Registry& registry, int surface,
                            std::string& why, Elements elements = Elements::Hex) {
  if (elements == Elements::Wedge) return tri_cap_scheme(model, registry, surface, why);
  if (elements == Elements::Mixed) return mixed_cap_scheme(model, registry, surface, why);
  const scheme::RoleChoice c = scheme::best_surface_scheme(
      registry, scheme::Role::QuadCap, scheme::SurfaceView{model, surface, nullptr});
  if (c.scheme) return std::string(c.scheme->name());
  why = "no surface scheme meshes source cap surface " + std::to_string(surface) + " (" +
        c.reasons + ")";
  return {};
}

// True when single-loop surface `face` of `volume_id` also bounds another
// volume in which it fills a hole loop of another face: a subcap there,
// meshed by its own surface scheme as part of that volume's composite
// source cap, so it should not be this volume's (volume-meshed) target.
bool subcap_elsewhere(const geom::Model& model, int volume_id, int face) {
  const geom::Surface& s = model.surface(face);
  if (s.loops.size() != 1) return false;
  std::set<int> own;
  for (const auto& use : s.loops.front().uses) own.insert(use.curve);
  for (int w : s.volumes) {
    if (w == volume_id) continue;
    for (int h : model.surfaces_of(w)) {
      if (h == face) continue;
      const auto& loops = model.surface(h).loops;
      for (size_t l = 1; l < loops.size(); ++l) {
        std::set<int> hole;
        for (const auto& use : loops[l].uses) hole.insert(use.curve);
        if (hole == own) return true;
      }
    }
  }
  return false;
}

// -1, 0, 1: areas equal within a relative tolerance count as equal, so that
// round-off (e.g. after a rigid transform) never decides.
int compare_area(double x, double y) {
  if (std::abs(x - y) <= 1e-6 * std::max(std::abs(x), std::abs(y))) return 0;
  return x < y ? -1 : 1;
}

// Larger is preferred as the source: loops, curves, area, then the lower id.
bool better_source(const FaceInfo& x, const FaceInfo& y) {
  if (x.loops != y.loops) return x.loops > y.loops;
  if (x.curves != y.curves) return x.curves > y.curves;
  if (const int c = compare_area(x.area, y.area)) return c > 0;
  return x.id < y.id;
}

}  // namespace

// cite: Blacker 1996, sec. 3 (volume classification into sides and caps).
Classification classify_faces(const geom::Model& model, int volume_id,
                              const scheme::Registry& registry, const SweepHints& hints,
                              Elements elements) {
  Classification out;
  const std::string vname = volume_name(volume_id);
  std::vector<int> ids = model.surfaces_of(volume_id);
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  if (ids.size() < 3) {
    out.why = vname + ": " + std::to_string(ids.size()) + " surface" +
              (ids.size() == 1 ? "" : "s") + ", a sweep needs at least 3";
    return out;
  }
  if (model.volume(volume_id).shells.size() != 1) {
    out.why = vname + " has " + std::to_string(model.volume(volume_id).shells.size()) +
              " shells; a sweep needs one (no internal voids)";
    return out;
  }
  if (registry.surface_schemes(scheme::Role::SweepSide).empty()) {
    out.why = vname + ": no registered surface scheme serves sweep sides (submap does); cooper "
                      "needs one for the sides";
    return out;
  }
  std::vector<FaceInfo> faces;
  for (int id : ids) {
    const geom::Surface& s = model.surface(id);
    FaceInfo f;
    f.id = id;
    f.loops = static_cast<int>(s.loops.size());
    f.area = s.area;
    for (const auto& loop : s.loops) {
      for (const auto& use : loop.uses) f.curve_set.insert(use.curve);
      f.curves += static_cast<int>(loop.uses.size());
    }
    if (f.loops != 1) {
      f.side_why = "it has " + std::to_string(f.loops) + " loops; a side face needs one";
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
  auto info = [&](int id) -> const FaceInfo* {
    for (const auto& f : faces) {
      if (f.id == id) return &f;
    }
    return nullptr;
  };
  for (const auto* list : {&hints.sources, &hints.targets}) {
    if (list->size() > 1) {
      out.why = vname + ": the hints name " + std::to_string(list->size()) + " " +
                (list == &hints.sources ? "sources" : "targets") +
                " (" + join(*list) + "); a one-to-one sweep has one (many-to-one is part II)";
      return out;
    }
    for (int id : *list) {
      if (!info(id)) {
        out.why = vname + ": hinted surface " + std::to_string(id) + " does not bound the volume";
        return out;
      }
    }
  }

  // Composite caps (Blacker 1996, sec. 4-5: a cap made of subcaps): a face
  // with hole loops each filled by one face of the volume (one loop, exactly
  // the hole's curves, coplanar across them) becomes one cap whose boundary
  // is its unfilled loops; the subcaps touch no side.
  SweepHints local_hints = hints;
  {
    std::set<int> absorbed;
    for (FaceInfo& host : faces) {
      if (host.loops < 2 || absorbed.count(host.id)) continue;
      const auto& loops = model.surface(host.id).loops;
      std::vector<int> keep;
      std::vector<int> subcaps;
      for (size_t l = 0; l < loops.size(); ++l) {
        int filler = 0;
        if (l > 0) {
          std::set<int> hole;
          for (const auto& use : loops[l].uses) hole.insert(use.curve);
          for (const FaceInfo& g : faces) {
            if (g.id == host.id || g.loops != 1 || !g.subcaps.empty() || g.curve_set != hole ||
                absorbed.count(g.id)) {
              continue;
            }
            bool flat = true;
            for (int c : hole) {
              const double a = cap_dihedral_degrees(model, volume_id, host.id, g.id, c);
              flat = flat && std::abs(a - 180.0) <= kSubcapFlatness;
            }
            if (flat) {
              filler = g.id;
              break;
            }
          }
        }
        if (filler) {
          subcaps.push_back(filler);
        } else {
          keep.push_back(static_cast<int>(l));
        }
      }
      if (subcaps.empty()) continue;
      host.subcaps = subcaps;
      host.boundary_loops = keep;
      host.loops = static_cast<int>(keep.size());
      host.curves = 0;
      host.curve_set.clear();
      for (int l : keep) {
        for (const auto& use : loops[static_cast<size_t>(l)].uses) host.curve_set.insert(use.curve);
        host.curves += static_cast<int>(loops[static_cast<size_t>(l)].uses.size());
      }
      for (int g : subcaps) absorbed.insert(g);
      for (int g : subcaps) {
        // A hint naming a subcap names its composite cap.
        for (int& id : local_hints.sources) id = id == g ? host.id : id;
        if (std::find(hints.targets.begin(), hints.targets.end(), g) != hints.targets.end()) {
          out.why = vname + ": hinted target surface " + std::to_string(g) +
                    " is a subcap of surface " + std::to_string(host.id) +
                    "; a composite cap can only be the source";
          return out;
        }
      }
    }
    faces.erase(std::remove_if(faces.begin(), faces.end(),
                               [&](const FaceInfo& f) { return absorbed.count(f.id) > 0; }),
                faces.end());
  }
  std::vector<int> forced;  // faces that cannot be sides are caps
  std::string forced_why;
  for (const auto& f : faces) {
    if (!f.side_ok) {
      forced.push_back(f.id);
      forced_why += std::string(forced_why.empty() ? "" : "; ") + "surface " +
                    std::to_string(f.id) + ": " + f.side_why;
    }
  }
  if (forced.size() > 2) {
    out.why = vname + ": surfaces " + join(forced) + " cannot be sides (" + forced_why +
              "), and a one-barrel sweep has exactly two caps";
    return out;
  }

  // Candidate cap pairs, ranked (deterministic, independent of face order).
  struct Pair {
    const FaceInfo* a;
    const FaceInfo* b;
    double align;
  };
  std::vector<Pair> pairs;
  for (size_t i = 0; i < faces.size(); ++i) {
    for (size_t j = i + 1; j < faces.size(); ++j) {
      const FaceInfo& a = faces[i];
      const FaceInfo& b = faces[j];
      bool ok = true;
      for (int id : forced) ok = ok && (id == a.id || id == b.id);
      for (int id : local_hints.sources) ok = ok && (id == a.id || id == b.id);
      for (int id : local_hints.targets) ok = ok && (id == a.id || id == b.id);
      if (!ok) continue;
      double align = 0;
      if (local_hints.direction && local_hints.direction->norm() > 0) {
        const geom::Vec3 d = local_hints.direction->normalized();
        for (const FaceInfo* f : {&a, &b}) {
          const geom::Surface& s = model.surface(f->id);
          const geom::Vec3 centre = 0.5 * (s.box.min + s.box.max);
          align += std::abs(s.geometry->project(centre).normal.dot(d));
        }
      }
      pairs.push_back({&a, &b, align});
    }
  }
  std::sort(pairs.begin(), pairs.end(), [](const Pair& x, const Pair& y) {
    if (std::abs(x.align - y.align) > 1e-6) return x.align > y.align;
    const int lx = x.a->loops + x.b->loops, ly = y.a->loops + y.b->loops;
    if (lx != ly) return lx > ly;
    const int cx = x.a->curves + x.b->curves, cy = y.a->curves + y.b->curves;
    if (cx != cy) return cx > cy;
    if (const int c = compare_area(x.a->area + x.b->area, y.a->area + y.b->area)) return c > 0;
    return std::make_pair(x.a->id, x.b->id) < std::make_pair(y.a->id, y.b->id);
  });
  if (pairs.empty()) {
    out.why = vname + ": no pair of caps fits the hints and the faces that cannot be sides (" +
              (forced_why.empty() ? std::string("none") : forced_why) + ")";
    return out;
  }
  std::string first_failure;
  for (const Pair& p : pairs) {
    std::vector<SideFace> sides;
    const std::string why = check_pair(model, volume_id, faces, *p.a, *p.b, sides);
    if (!why.empty()) {
      if (first_failure.empty()) first_failure = why;
      continue;
    }
    // Source: the hinted one, else the cap not better left to the other.
    const FaceInfo* src = better_source(*p.a, *p.b) ? p.a : p.b;
    const FaceInfo* tgt = src == p.a ? p.b : p.a;
    const bool hinted = !local_hints.sources.empty() || !local_hints.targets.empty();
    // A face that is a subcap of a neighbour's composite cap is meshed by its
    // surface scheme there: make it this volume's source, not its target.
    if (subcap_elsewhere(model, volume_id, tgt->id) &&
        !subcap_elsewhere(model, volume_id, src->id)) {
      std::swap(src, tgt);
    }
    if ((!local_hints.sources.empty() && local_hints.sources.front() != src->id) ||
        (!local_hints.targets.empty() && local_hints.targets.front() == src->id)) {
      std::swap(src, tgt);
    }
    // A composite cap is always the source: the target's mesh is the swept
    // one, a single face (its subcaps are meshed by their own schemes, e.g.
    // a face shared with a neighbouring volume).
    if (!p.a->subcaps.empty() && !p.b->subcaps.empty()) {
      if (first_failure.empty()) {
        first_failure = "caps " + std::to_string(p.a->id) + " and " + std::to_string(p.b->id) +
                        " both have subcaps; the target cap must be a single face";
      }
      continue;
    }
    const bool composite = !p.a->subcaps.empty() || !p.b->subcaps.empty();
    if (composite) {
      const FaceInfo* host = p.a->subcaps.empty() ? p.b : p.a;
      if (src != host) {
        if (!local_hints.targets.empty() && local_hints.targets.front() == host->id) {
          if (first_failure.empty()) {
            first_failure = "hinted target surface " + std::to_string(host->id) +
                            " has subcaps; a composite cap can only be the source";
          }
          continue;
        }
        std::swap(src, tgt);
      }
    }
    std::string scheme_why;
    std::string scheme = cap_scheme_impl(model, registry, src->id, scheme_why, elements);
    std::vector<std::string> subcap_schemes;
    for (int g : src->subcaps) {
      if (scheme.empty()) break;
      std::string why_g;
      const std::string sg = cap_scheme_impl(model, registry, g, why_g, elements);
      if (sg.empty()) {
        scheme.clear();
        scheme_why = "subcap " + std::to_string(g) + " of source cap " + std::to_string(src->id) +
                     ": " + why_g;
      }
      subcap_schemes.push_back(sg);
    }
    if (scheme.empty() && !hinted && !composite) {
      std::string other_why;
      const std::string other = cap_scheme_impl(model, registry, tgt->id, other_why, elements);
      if (!other.empty()) {
        std::swap(src, tgt);
        scheme = other;
      }
    }
    if (scheme.empty()) {
      if (first_failure.empty()) first_failure = scheme_why;
      continue;
    }
    out.ok = true;
    out.source = src->id;
    out.target = tgt->id;
    out.source_scheme = scheme;
    out.source_subcaps = src->subcaps;
    out.source_subcap_schemes = subcap_schemes;
    out.source_loops = src->boundary_loops;
    // Swap the side curve roles when the source is the second cap.
    if (src != p.a) {
      for (auto& s : sides) std::swap(s.source_curves, s.target_curves);
    }
    double worst = 1.0;
    for (const auto& s : sides) worst = std::min(worst, info(s.surface)->side_score);
    out.score = 0.5 + 0.4 * std::clamp(worst, 0.0, 1.0);
    out.sides = std::move(sides);
    std::ostringstream w;
    w << vname << ": one-barrel sweep from surface " << out.source << " (" << scheme << ")";
    for (size_t k = 0; k < out.source_subcaps.size(); ++k) {
      w << (k ? ", " : " with subcaps ") << out.source_subcaps[k] << " ("
        << out.source_subcap_schemes[k] << ")";
    }
    w << " to surface " << out.target << " along " << out.sides.size() << " side faces";
    out.why = w.str();
    return out;
  }
  out.why = vname + ": no pair of caps gives a one-barrel sweep (" +
            std::to_string(pairs.size()) + " pair" + (pairs.size() == 1 ? "" : "s") +
            " tried; the best ranked fails: " + first_failure + ")";
  return out;
}

namespace detail {

std::string check_side(const geom::Model& model, int side,
                       const std::vector<scheme::LoopCorner>& corners, int upper,
                       const std::set<int>& upper_curves, int lower,
                       const std::set<int>& lower_curves, SideFace& out) {
  return check_side_impl(model, side, corners, upper, upper_curves, lower, lower_curves, out);
}

std::string side_scheme(const geom::Model& model, const scheme::Registry& registry,
                        int surface) {
  const scheme::RoleChoice c = scheme::best_surface_scheme(
      registry, scheme::Role::SweepSide, scheme::SurfaceView{model, surface, nullptr});
  return c.scheme ? std::string(c.scheme->name()) : std::string();
}

std::string cap_scheme(const geom::Model& model, const scheme::Registry& registry, int surface,
                       std::string& why) {
  return cap_scheme_impl(model, registry, surface, why);
}

std::string cap_scheme(const geom::Model& model, const scheme::Registry& registry, int surface,
                       std::string& why, Elements elements) {
  return cap_scheme_impl(model, registry, surface, why, elements);
}

}  // namespace detail

}  // namespace cooperage::cooper
