#include "schemes/cooper/plan_volume.h"

#include "framework/core/log.h"
#include "schemes/cooper/cap_candidates.h"
#include "schemes/cooper/cap_scheme.h"
#include "schemes/cooper/coincident_curves.h"
#include "schemes/cooper/column_order.h"
#include "schemes/cooper/loop_nodes.h"
#include "schemes/cooper/side_parity.h"

#include <algorithm>
#include <iterator>
#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>
#include <tuple>

namespace cooperage::cooper {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::string volume_name(int id) { return "volume " + std::to_string(id); }

std::string join(const std::vector<int>& ids) {
  std::string s;
  for (size_t i = 0; i < ids.size(); ++i) s += (i ? ", " : "") + std::to_string(ids[i]);
  return s;
}

std::string hint_place(const SweepHints& h) {
  return h.where.empty() ? std::string() : " (" + h.where + ")";
}

// "sources 1 2 4, targets 5 7 8, direction (0, 0, 1)": what a hint asks.
std::string hint_text(const SweepHints& h) {
  std::string out;
  auto list = [&](const char* what, const std::vector<int>& ids) {
    if (ids.empty()) return;
    out += (out.empty() ? "" : ", ") + std::string(what);
    for (int id : ids) out += " " + std::to_string(id);
  };
  list("sources", h.sources);
  list("targets", h.targets);
  if (h.direction) out += (out.empty() ? "" : ", ") + std::string("direction ") + direction_text(*h.direction);
  return out;
}

// The hints a plan must honour; empty when it does, else why not.
std::string check_hints(const VolumePlan& p, const SweepHints& hints) {
  for (int s : hints.sources) {
    const auto it = p.order.upper.find(s);
    if (it == p.order.upper.end() || !it->second) {
      return "the hinted source surface " + std::to_string(s) + hint_place(hints) +
             " is not a cap the sweep starts from";
    }
  }
  for (int t : hints.targets) {
    const auto it = p.order.upper.find(t);
    if (it == p.order.upper.end() || it->second) {
      return "the hinted target surface " + std::to_string(t) + hint_place(hints) +
             " is not a cap the sweep ends on";
    }
  }
  if (hints.direction && hints.direction->norm() > 0) {
    const geom::Vec3 d = hints.direction->normalized();
    const double c = std::cos(kCapFacing * kPi / 180.0);
    for (const auto& [cap, upper] : p.order.upper) {
      if (!upper) continue;
      const double along = -p.facts.face(cap)->normal.dot(d);
      if (along < c) {
        return "the sweep would leave cap " + std::to_string(cap) + " along " +
               direction_text(-p.facts.face(cap)->normal) + ", not along the direction hint " +
               direction_text(d) + hint_place(hints);
      }
    }
  }
  return {};
}

double worst_side_score(const VolumePlan& p) {
  double worst = 1.0;
  for (int s : p.lattice.sides) worst = std::min(worst, p.facts.face(s)->submap_score);
  return std::clamp(worst, 0.0, 1.0);
}

std::string summary(const VolumePlan& p) {
  std::ostringstream w;
  w << volume_name(p.volume) << ": ";
  if (p.one_barrel()) {
    const BarrelNode& b = p.tree.barrels.front();
    std::vector<int> up, lo;
    for (const EndPiece& e : b.upper) up.push_back(e.cap);
    for (const EndPiece& e : b.lower) lo.push_back(e.cap);
    w << "one-barrel sweep from surface" << (up.size() > 1 ? "s " : " ") << join(up);
    for (int c : up) {
      const auto it = p.roles.scheme.find(c);
      if (it != p.roles.scheme.end()) w << " (" << c << ": " << it->second << ")";
    }
    w << " to surface" << (lo.size() > 1 ? "s " : " ") << join(lo) << " along "
      << p.lattice.sides.size() << " side faces";
  } else {
    w << "many-to-one sweep";
    if (p.down) w << " along " << direction_text(*p.down);
    w << " in " << p.tree.barrels.size() << " barrels, " << p.roles.scheme.size()
      << " caps meshed by their surface schemes, " << p.roles.by_volume.size() << " by the sweep";
  }
  return w.str();
}

// Footprints that share part of an edge across the volume (a boss's base
// and a foot's top along one line, with no side face joining the two
// curves): imprinting splits subcaps along such a stretch wrongly or not
// at all (issue 15), so the plan refuses, naming the curves; decompose
// "auto" may then cut along the line. Empty when there is none.
std::string shared_edge_stretch(const VolumeFacts& facts, const SweepOrder& order,
                                const geom::Vec3& down) {
  std::vector<int> caps;
  for (const auto& [cap, upper] : order.upper) caps.push_back(cap);
  auto face_of = [&](int curve, int skip) {
    std::vector<int> out;
    for (const FaceFact& f : facts.faces) {
      if (f.id == skip) continue;
      for (const auto& loop : f.loops) {
        for (const UseFact& u : loop) {
          if (u.curve == curve) out.push_back(f.id);
        }
      }
    }
    std::sort(out.begin(), out.end());
    return out;
  };
  for (const auto& [a, b] : overlapping_cap_curves(facts, caps, down)) {
    const auto fa = face_of(a, 0), fb = face_of(b, 0);
    std::vector<int> both;
    std::set_intersection(fa.begin(), fa.end(), fb.begin(), fb.end(), std::back_inserter(both));
    // Sides of one wall: the lattice ties their counts, the ribs their nodes.
    if (std::any_of(both.begin(), both.end(), [&](int f) { return !order.upper.count(f); }))
      continue;
    return "curves " + std::to_string(a) + " (surfaces " + join(fa) + ") and " + std::to_string(b) +
           " (surfaces " + join(fb) +
           ") run on one line along the sweep over part of their length; imprinting cannot yet "
           "split the subcaps along a shared stretch of edge, not supported (decompose along "
           "that line, e.g. with <webcut>)";
  }
  return {};
}

// A side face on both sides of one barrel end: a notch whose floor is a cap
// of the same end as the face's own rim (a lug's cone swept up with the
// bottom, in one barrel or under a blind hole's floor). The end is one row
// of the face's lattice, so the face between them folds onto it. Empty when
// there is none.
std::string side_on_both_sides_of_an_end(const SideLattice& lattice, const BarrelTree& tree) {
  std::map<int, std::pair<size_t, int>> end_of;  // cap -> (barrel, 0 upper / 1 lower)
  for (size_t b = 0; b < tree.barrels.size(); ++b) {
    for (const EndPiece& e : tree.barrels[b].upper) {
      if (e.cap) end_of[e.cap] = {b, 0};
    }
    for (const EndPiece& e : tree.barrels[b].lower) {
      if (e.cap) end_of[e.cap] = {b, 1};
    }
  }
  std::map<std::tuple<int, size_t, int>, int> side_of;  // (face, barrel, end) -> leaving sign
  for (const CapContact& c : lattice.contacts) {
    const auto it = end_of.find(c.cap);
    if (it == end_of.end()) continue;
    const auto key = std::make_tuple(c.face, it->second.first, it->second.second);
    const auto [seen, added] = side_of.emplace(key, c.leaving_sign);
    if (added || seen->second == c.leaving_sign) continue;
    return "side surface " + std::to_string(c.face) + " lies on both sides of the " +
           (it->second.second ? "lower" : "upper") + " end of barrel " +
           std::to_string(it->second.first + 1) + " (cap " + std::to_string(c.cap) +
           " is the floor of a notch in it): its lattice folds";
  }
  return {};
}

// Diagonal of the box of a face's boundary curves.
double rim_extent(const VolumeFacts& facts, int face) {
  std::vector<int> rims;
  for (const auto& loop : facts.face(face)->loops) {
    for (const UseFact& u : loop) rims.push_back(u.curve);
  }
  return facts.extent(rims);
}

// A seamed cap the sweep meshes (a band on a periodic face) gets its nodes
// from the least-squares projection of its source, and then must meet its
// seam curve's nodes (weld_seams.cpp). From a source of a very different
// size (a dome swept along its meridian, from a cone ring round the flange
// to the apex hole: 8 times smaller) the projection places them too poorly
// for that: refused at plan time (the decomposition then cuts further).
std::string seamed_target_from_far_source(const geom::Model& model, const VolumePlan& p) {
  if (!p.one_barrel()) return {};
  constexpr double kMaxRatio = 3.0;
  for (int cap : p.roles.by_volume) {
    const auto& loops = model.surface(cap).loops;
    if (std::all_of(loops.begin(), loops.end(),
                    [](const geom::Loop& l) { return seam_curves(l).empty(); }))
      continue;
    for (const EndPiece& e : p.tree.barrels.front().upper) {
      if (!e.cap || e.cap == cap) continue;
      const double a = rim_extent(p.facts, e.cap), b = rim_extent(p.facts, cap);
      if (a > kMaxRatio * b || b > kMaxRatio * a) {
        char ratio[32];
        std::snprintf(ratio, sizeof ratio, "%.1f", std::max(a, b) / std::min(a, b));
        return "surface " + std::to_string(cap) +
               ", a band on a periodic face the sweep would mesh, differs in size from its "
               "source surface " +
               std::to_string(e.cap) + " by a factor of " + ratio +
               " (more than 3): the projection cannot place its nodes on its seam";
      }
    }
  }
  return {};
}

// A ring of sweeps closing (NeighbourMeshes::closing): a one-to-one sweep
// ends on its target as the ring meshed it, matched node for node to the
// source's mesh (cap_stacks.cpp), instead of meshing it itself. Only a
// match: the target's mesh is one piece, the image of the one source.
void end_on_existing_mesh(const BarrelTree& tree, const std::set<int>& closing,
                          const CapSchemeOf& scheme_of, CapRoles& roles) {
  const auto [upper, lower] = one_to_one_caps(tree);
  if (!upper || !closing.count(lower) || !roles.scheme.count(upper)) return;
  std::string why;
  const std::string s = scheme_of(lower, why);
  if (s.empty()) return;
  roles.scheme[lower] = s;
  roles.by_volume.erase(std::remove(roles.by_volume.begin(), roles.by_volume.end(), lower),
                        roles.by_volume.end());
}

// Runs the steps for one sorting of the faces.
VolumePlan evaluate(const geom::Model& model, const scheme::Registry& registry,
                    const VolumeFacts& facts, const PlanInputs& in, const CapCandidate& cand) {
  VolumePlan p;
  p.volume = facts.volume;
  p.elements = in.elements;
  p.candidate = cand.label;
  // Most sortings are refused, many by their first step: a refusal moves
  // the plan out instead of copying it, and the facts (the volume's maps of
  // faces and curves, most of a plan's size) are copied in only once the
  // sorting has its barrels and cap roles (a search of decompositions
  // evaluates thousands of sortings, issue 17).
  auto fail = [&](int stage, const std::string& why) {
    p.why = cand.label + ": " + why;
    p.stage = stage;
    return std::move(p);
  };
  p.lattice = side_lattice(facts, cand.caps);
  if (!p.lattice.ok) return fail(1, p.lattice.why);
  p.order = sweep_order(facts, p.lattice, cand.anchor);
  if (!p.order.ok) return fail(2, p.order.why);
  p.slabs = slab_regions(facts, p.lattice, p.order);
  if (!p.slabs.ok) return fail(3, p.slabs.why);
  p.tree = form_barrel_tree(facts, p.lattice, p.order, p.slabs);
  if (!p.tree.ok) return fail(4, p.tree.why);
  // A knife edge between sides: the barrels' cap outlines fold back on
  // themselves along it, and imprinting cannot resolve the slivers (the
  // lever occt_bm2_ec_lever-A: a cylinder tangent to a wall at a cusp, a
  // slot wall 0.1 mm beside it). One barrel has nothing to imprint.
  if (p.tree.barrels.size() > 1 && !p.lattice.knife_edge.empty())
    return fail(4, p.lattice.knife_edge + "; a many-to-one sweep cannot imprint subcaps there");
  if (const std::string why = side_on_both_sides_of_an_end(p.lattice, p.tree); !why.empty())
    return fail(4, why);
  if (cand.anchor.down) p.down = cand.anchor.down->normalized();
  const CapSchemeOf scheme_of = [&](int cap, std::string& why) {
    return cap_scheme(model, registry, cap, why, in.elements, in.settings);
  };
  p.roles =
      cap_roles(facts, p.order, p.tree, p.down ? &*p.down : nullptr, scheme_of, in.polygon_mesher);
  if (!p.roles.ok) return fail(5, p.roles.why);
  end_on_existing_mesh(p.tree, in.neighbours.closing, scheme_of, p.roles);
  p.facts = facts;
  if (const std::string why = seamed_target_from_far_source(model, p); !why.empty())
    return fail(5, why);
  if (p.down) {
    if (const std::string why = shared_edge_stretch(facts, p.order, *p.down); !why.empty())
      return fail(5, why);
  }
  if (const std::string h = check_hints(p, in.hints); !h.empty()) return fail(6, h);
  std::set<int> even;
  for (const auto& [cap, upper] : p.order.upper) {
    const auto it = p.roles.scheme.find(cap);
    const bool paved =
        it != p.roles.scheme.end() && (it->second == "pave" || it->second == "quad_dominant");
    const bool imprinted = p.roles.needs_polygon_mesher && in.elements != Elements::Wedge;
    if (imprinted || (paved && facts.face(cap)->loops.size() > 1)) even.insert(cap);
  }
  // The volume's element size (its own, else the job's; none without a job).
  double layer_size = 0;
  if (in.settings) {
    const io::VolumeSetting* own = in.settings->volume(p.volume);
    layer_size = own && own->sizing.size ? *own->sizing.size : in.settings->size;
  }
  p.rows = barrel_constraints(facts, p.lattice, p.order, p.tree, even,
                              volume_name(p.volume) + " (cooper)", layer_size);
  if (p.down) {
    std::vector<int> caps;
    for (const auto& [cap, upper] : p.order.upper) caps.push_back(cap);
    for (IntervalRow& r : coincident_curve_rows(coincident_cap_curves(facts, caps, *p.down),
                                                volume_name(p.volume) + " (cooper)"))
      p.rows.push_back(std::move(r));
    for (IntervalRow& r :
         column_order_rows(facts, p.lattice, *p.down, volume_name(p.volume) + " (cooper)"))
      p.rows.push_back(std::move(r));
  }
  p.along_pairs = side_along_pairs(facts, p.lattice);
  if (p.one_barrel()) {
    p.source = cand.source;
    p.target = cand.target;
    for (const EndPiece& e : p.tree.barrels.front().upper) {
      if (!p.source && e.cap) p.source = e.cap;
    }
    for (const EndPiece& e : p.tree.barrels.front().lower) {
      if (!p.target && e.cap) p.target = e.cap;
    }
  }
  if (p.one_barrel() && p.source && p.target &&
      std::binary_search(p.roles.by_volume.begin(), p.roles.by_volume.end(), p.target)) {
    // The swept target's seam takes the swept nodes (weld_seams.cpp): as
    // many intervals as the source's seam, whose nodes project onto it.
    const int a = single_seam(model.surface(p.source)), b = single_seam(model.surface(p.target));
    if (a && b && a != b) {
      IntervalRow r;
      r.terms = {{a, 1}, {b, -1}};
      r.label = volume_name(p.volume) + " (cooper): the seams of its caps, curves " +
                std::to_string(a) + " and " + std::to_string(b) + ", project onto each other";
      p.rows.push_back(std::move(r));
    }
  }
  const double worst = worst_side_score(p);
  p.score = p.one_barrel() ? 0.5 + 0.4 * worst : 0.3 + 0.15 * worst;
  p.ok = true;
  p.why = summary(p);
  return p;
}

// Shared surfaces the plan contradicts the neighbours on: one a neighbour
// meshes itself that this plan does not take as a cap meshed beforehand
// (weight 2: that neighbour usually has no other way), or one a neighbour
// keeps for its surface scheme that this plan meshes, or gives another
// surface scheme as a cap (weight 1: the selector may ask that neighbour
// to take the mesh instead; a wedge sweep's triangle cap on a neighbour's
// quad side has no such way out, but another sweep direction may). The selector
// refuses such a plan as it stands (docs/design.md, "Volumes that wait for
// a neighbour"); 0 when nothing is known of the neighbours.
int neighbour_conflicts(const VolumePlan& p, const scheme::NeighbourMeshes& n) {
  int count = 0;
  for (int s : n.made) count += p.facts.face(s) && !p.roles.scheme.count(s) ? 2 : 0;
  for (const std::set<int>* list : {&n.kept, &n.closing}) {
    for (int s : *list)
      count += std::binary_search(p.roles.by_volume.begin(), p.roles.by_volume.end(), s) ? 1 : 0;
  }
  for (const auto& [s, theirs] : n.kept_schemes) {
    const auto mine = p.roles.scheme.find(s);
    if (mine == p.roles.scheme.end() || mine->second == theirs) continue;
    // A mappable surface is the same mesh either way (the selector checks).
    const bool mapped = (mine->second == "map" && theirs == "submap") ||
                        (mine->second == "submap" && theirs == "map");
    count += mapped ? 0 : 1;
  }
  return count;
}

// Of two plans for one sorting, the one leaving fewer shared caps to the
// sweep, then meshing more caps by their surface schemes, then the first.
bool better(const VolumePlan& a, const VolumePlan& b) {
  auto shared_here = [](const VolumePlan& p) {
    int n = 0;
    for (int c : p.roles.by_volume) n += p.facts.face(c)->other_volumes > 0 ? 1 : 0;
    return n;
  };
  if (shared_here(a) != shared_here(b)) return shared_here(a) < shared_here(b);
  return a.roles.scheme.size() > b.roles.scheme.size();
}

// How well the linking chains follow a straight sweep: their chords'
// |cos| with the axis, weighted by length (1: every chain along it).
double alignment(const VolumePlan& p) {
  if (!p.down) return 0;
  double sum = 0, total = 0;
  for (const LinkChain& c : p.lattice.chains) {
    const geom::Vec3 chord = p.facts.vertices.at(c.to_vertex) - p.facts.vertices.at(c.from_vertex);
    if (!(chord.norm() > 0)) continue;
    sum += c.length * std::abs(chord.normalized().dot(*p.down));
    total += c.length;
  }
  return total > 0 ? sum / total : 0;
}

// The paper's Fig. 3a: virtual faces (where parts of the volume meet)
// projecting in directions no single sweep holds.
std::string fig3a(const VolumeFacts& facts) {
  const auto dirs = virtual_face_directions(facts);
  const double c = std::cos(kCapFacing * kPi / 180.0);
  for (size_t i = 0; i < dirs.size(); ++i) {
    for (size_t j = i + 1; j < dirs.size(); ++j) {
      if (std::abs(dirs[i].second.dot(dirs[j].second)) >= c) continue;
      return volume_name(facts.volume) +
             " is not cooperable: the virtual faces in the hole loops of surfaces " +
             std::to_string(dirs[i].first) + " (projecting along " +
             direction_text(dirs[i].second) + ") and " + std::to_string(dirs[j].first) +
             " (along " + direction_text(dirs[j].second) +
             ") project in different directions (Blacker 1996, sec. 3, Fig. 3a); decompose it, "
             "e.g. with "
             "<webcut>, into pieces that sweep in one direction each";
    }
  }
  return {};
}

}  // namespace

// cite: Blacker 1996, sec. 3 (classification), sec. 4 (barrel formation).
VolumePlan plan_volume(const geom::Model& model, int volume_id, const scheme::Registry& registry,
                       const PlanInputs& in) {
  VolumePlan refused;
  refused.volume = volume_id;
  refused.elements = in.elements;
  const std::string vname = volume_name(volume_id);
  if (model.volume(volume_id).shells.size() != 1) {
    refused.why = vname + " has " + std::to_string(model.volume(volume_id).shells.size()) +
                  " shells; a sweep needs one (no internal voids)";
    return refused;
  }
  if (!registry.surface_scheme("submap")) {
    refused.why = vname + ": the submap scheme is not registered; cooper needs it for the sides";
    return refused;
  }
  const VolumeFacts facts = gather_facts(model, volume_id, registry, in.settings);
  if (facts.faces.size() < 3) {
    refused.why =
        vname + ": " + std::to_string(facts.faces.size()) + " surfaces, a sweep needs at least 3";
    return refused;
  }
  for (const auto* list : {&in.hints.sources, &in.hints.targets}) {
    for (int id : *list) {
      if (!facts.face(id)) {
        refused.why = vname + ": hinted surface " + std::to_string(id) + hint_place(in.hints) +
                      " does not bound the volume";
        return refused;
      }
    }
  }
  // The refusal reported: the candidate that got furthest (the first of them).
  std::string first_failure;
  int deepest = -1;
  auto note = [&](const VolumePlan& p) {
    log::debug("cooper, volume " + std::to_string(volume_id) + ", candidate refused: " + p.why);
    if (p.stage > deepest) {
      deepest = p.stage;
      first_failure = p.why;
    }
  };
  const auto conflicts = [&](const VolumePlan& p) { return neighbour_conflicts(p, in.neighbours); };
  // Sortings with no lattice are skipped unplanned once a refusal of that
  // stage is noted (the one reported stays the first).
  const SideParity parity(facts);
  const auto hopeless = [&](const CapCandidate& c) {
    return deepest >= 1 && !parity.can_agree(c.caps);
  };
  // 1. One barrel between a pair of caps: the first that fits the
  // neighbours (a shared cap they mesh is the source, whichever way the
  // sorting alone would sweep), else the first with the fewest conflicts.
  std::string pair_why;
  std::optional<VolumePlan> pair;
  for (const CapCandidate& c :
       pair_candidates(facts, in.hints.sources, in.hints.targets, pair_why)) {
    if (hopeless(c)) continue;
    VolumePlan p = evaluate(model, registry, facts, in, c);
    if (p.ok && p.one_barrel()) {
      if (conflicts(p) == 0) return p;
      if (!pair || conflicts(p) < conflicts(*pair)) pair = std::move(p);
      continue;
    }
    if (!p.ok) note(p);
  }
  if (!pair_why.empty() && deepest < 1) {
    deepest = 0;
    first_failure = pair_why;
  }
  // 2. A straight axis, both directions along it (the hint's only); of the
  // axes that work, the one the linking curves follow best.
  {
    std::optional<VolumePlan> best;
    double best_alignment = -1;
    for (const geom::Vec3& axis : candidate_axes(facts, in.hints.direction)) {
      CapCandidate c;
      c.kind = CapCandidate::Kind::Axis;
      c.caps = caps_facing(facts, axis);
      for (int sign : {-1, 1}) {
        if (in.hints.direction && sign < 0) continue;
        c.anchor.down = sign * axis;
        c.label = "along " + direction_text(sign * axis);
        if (hopeless(c)) continue;
        VolumePlan p = evaluate(model, registry, facts, in, c);
        if (!p.ok) {
          note(p);
          continue;
        }
        const double a = alignment(p);
        const bool clearly_better = a > best_alignment + 1e-6;
        const bool tie = std::abs(a - best_alignment) <= 1e-6;
        const int k = conflicts(p), best_k = best ? conflicts(*best) : 0;
        if (!best || k < best_k || (k == best_k && (clearly_better || (tie && better(p, *best))))) {
          best_alignment = k < best_k ? a : std::max(a, best_alignment);
          best = std::move(p);
        }
      }
    }
    if (best && (!pair || conflicts(*best) < conflicts(*pair))) return *best;
    if (pair) return *pair;
  }
  // 3. A curved sweep with several barrels.
  if (!in.hints.direction) {
    std::optional<VolumePlan> best;
    std::string last_label;
    for (const CapCandidate& c : curved_candidates(facts)) {
      if (best && c.label != last_label) break;  // both orientations of one sorting tried
      // Most of these sortings have no lattice; this finds nearly all of
      // them at a fraction of the cost (their refusals are not reported).
      if (!parity.can_agree(c.caps)) continue;
      VolumePlan p = evaluate(model, registry, facts, in, c);
      last_label = c.label;
      if (!p.ok) continue;
      if (!best || conflicts(p) < conflicts(*best) ||
          (conflicts(p) == conflicts(*best) && better(p, *best)))
        best = std::move(p);
    }
    if (best) return *best;
  }
  if (const std::string f = fig3a(facts); !f.empty()) {
    refused.needs_decomposition = true;
    refused.why = f;
    return refused;
  }
  if (in.hints.direction && in.hints.sources.empty() && in.hints.targets.empty()) {
    refused.why = vname + ": the direction hint " + direction_text(*in.hints.direction) +
                  hint_place(in.hints) + " cannot be honoured: " +
                  (first_failure.empty() ? "no sorting fits it" : first_failure);
  } else if (!in.hints.sources.empty() || !in.hints.targets.empty()) {
    // A hint is honoured or named in the refusal (issue 15 item 7), also when
    // no sorting got as far as checking it.
    refused.why = vname + ": the sweep hint (" + hint_text(in.hints) + ")" + hint_place(in.hints) +
                  " cannot be honoured: " +
                  (first_failure.empty() ? "no sorting fits it" : first_failure);
    if (!pair_why.empty() && pair_why != first_failure) refused.why += "; " + pair_why;
  } else {
    refused.why =
        vname +
        ": no sorting of its faces into caps and sides gives barrels (the one that got furthest: " +
        (first_failure.empty() ? std::string("none") : first_failure) + ")";
  }
  return refused;
}

geom::Vec3 sweep_direction(const VolumePlan& p) {
  if (p.down) return *p.down;
  if (p.source && p.facts.face(p.source)) return -p.facts.face(p.source)->normal;
  return geom::Vec3::Zero();
}

std::string imprint_operation(const BarrelNode& barrel) {
  const size_t u = barrel.upper.size(), l = barrel.lower.size();
  if (u == 1 && l == 1) return "match";
  if (u == 1 || l == 1) return "subtract";
  return "imprint";
}

std::string describe_plan(const VolumePlan& p) {
  std::ostringstream s;
  if (!p.ok) {
    s << p.why << "\n";
    return s.str();
  }
  s << "cooper plan of " << volume_name(p.volume) << ": " << p.tree.barrels.size() << " barrel"
    << (p.tree.barrels.size() == 1 ? "" : "s");
  if (p.down) {
    s << ", straight along " << direction_text(*p.down);
  } else if (p.source) {
    s << ", leaving surface " << p.source << " along " << direction_text(sweep_direction(p));
  }
  s << (p.down ? "" : " (" + p.candidate + ")") << "\n";
  auto piece = [&](const EndPiece& e, bool upper_end, size_t self) {
    std::ostringstream t;
    if (e.cap) {
      const auto it = p.roles.scheme.find(e.cap);
      t << "surface " << e.cap << " ("
        << (it != p.roles.scheme.end() ? it->second : std::string("by the sweep")) << ")";
    } else {
      const BarrelInterface& v = p.tree.interfaces[static_cast<size_t>(e.interface)];
      const int other = upper_end ? v.above : v.below;
      (void)self;
      t << "virtual cap " << (upper_end ? "from" : "into") << " barrel " << other + 1;
    }
    return t.str();
  };
  for (size_t b = 0; b < p.tree.barrels.size(); ++b) {
    const BarrelNode& n = p.tree.barrels[b];
    s << "  barrel " << b + 1 << ": sides " << join(n.sides) << "; " << imprint_operation(n)
      << "\n";
    s << "    upper:";
    for (const EndPiece& e : n.upper)
      s << " " << piece(e, true, b) << (&e == &n.upper.back() ? "" : ",");
    s << "\n    lower:";
    for (const EndPiece& e : n.lower)
      s << " " << piece(e, false, b) << (&e == &n.lower.back() ? "" : ",");
    s << "\n";
  }
  return s.str();
}

}  // namespace cooperage::cooper
