#include "selector/select_schemes.h"

#include "framework/core/error.h"
#include "framework/intervals/solve.h"
#include "framework/pipeline/check_settings.h"
#include "framework/pipeline/interval_setup.h"
#include "framework/scheme/refusals.h"
#include "selector/starved_curves.h"

#include <algorithm>
#include <functional>
#include <map>
#include <set>
#include <tuple>

namespace cooperage::selector {
namespace {

template <class Setting>
const Setting* find_setting(const std::vector<Setting>& settings, int id) {
  for (const auto& s : settings) {
    if (s.id == id) return &s;
  }
  return nullptr;
}

std::string place(const io::SourceLocation& where) {
  return where.file.empty() ? std::string("the job")
                            : where.file + ":" + std::to_string(where.line);
}

std::string score_text(double score) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", score);
  return buf;
}

template <class Scheme, class View>
std::vector<Candidate> evaluate(const std::vector<const Scheme*>& schemes, const View& view) {
  std::vector<Candidate> out;
  for (const Scheme* s : schemes) out.push_back({std::string(s->name()), s->applicable(view)});
  return out;
}

// Applicable candidates, best score first; ties keep registry order.
std::vector<const Candidate*> ranked(const std::vector<Candidate>& candidates) {
  std::vector<const Candidate*> ok;
  for (const auto& c : candidates) {
    if (c.applicability.ok) ok.push_back(&c);
  }
  std::stable_sort(ok.begin(), ok.end(), [](const Candidate* a, const Candidate* b) {
    return a->applicability.score > b->applicability.score;
  });
  return ok;
}

std::string all_reasons(const std::vector<Candidate>& candidates) {
  std::vector<std::pair<std::string, std::string>> refusals;
  for (const auto& c : candidates) {
    if (!c.applicability.ok) refusals.emplace_back(c.scheme, c.applicability.why);
  }
  return refusals.empty() ? std::string("no scheme registered") : scheme::join_refusals(refusals);
}

const Candidate* find_candidate(const std::vector<Candidate>& candidates, const std::string& name) {
  for (const auto& c : candidates) {
    if (c.scheme == name) return &c;
  }
  return nullptr;
}

// " 3, 5": the surfaces of the requests made of a volume.
std::string listed(const scheme::NeighbourMeshes& n) {
  std::set<int> all = n.made;
  all.insert(n.kept.begin(), n.kept.end());
  all.insert(n.closing.begin(), n.closing.end());
  std::string out = all.size() > 1 ? "s" : "";
  for (int s : all) out += (out.size() > 1 ? ", " : " ") + std::to_string(s);
  return out;
}

struct Role {
  std::string scheme;
  int volume = 0;
  std::string volume_scheme;
  bool takes_existing = false;  ///< the volume takes whatever mesh the surface gets
};

// Whether `edges` (volume -> volumes it waits for) has a cycle.
bool has_cycle(const std::map<int, std::set<int>>& edges) {
  std::map<int, int> state;  // 1: on the path, 2: done
  std::function<bool(int)> visit = [&](int v) {
    state[v] = 1;
    const auto it = edges.find(v);
    if (it != edges.end()) {
      for (int w : it->second) {
        if (state[w] == 1 || (state[w] == 0 && visit(w))) return true;
      }
    }
    state[v] = 2;
    return false;
  };
  for (const auto& [v, targets] : edges) {
    if (state[v] == 0 && visit(v)) return true;
  }
  return false;
}

// What a volume chosen earlier is asked to plan around: to take `surface`
// as it finds it (`take`: the later volume must mesh it), or to leave it to
// its surface scheme (the later volume needs it so).
struct Request {
  int volume = 0;
  int surface = 0;
  bool take = false;
  bool pin = false;  ///< no request: the conflict is with a surface pin (the user's input)
};

constexpr int kMaxRounds = 8;  // rounds of requests before the last choice stands

class Selector {
 public:
  Selector(const geom::Model& model, const scheme::Registry& registry,
           const io::MeshSettings& settings, const SelectOptions& options)
      : model_(model),
        registry_(registry),
        settings_(settings),
        job_(scheme::Settings::of(settings, options.dim)),
        options_(options) {}

  Selection run() {
    if (options_.dim == 3) {
      // A conflict over a shared surface with a volume chosen earlier asks
      // that volume to plan around the surface (yield_), and the volumes
      // are chosen again; the requests only grow, so this ends.
      for (int round = 0;; ++round) {
        restart_ = false;
        roles_.clear();
        imposed_.clear();
        volume_types_.clear();
        waits_for_.clear();
        sweep_source_.clear();
        selection_.volumes.clear();
        selection_.refused.clear();
        selection_.ring_closers.clear();
        for (const geom::Volume& v : model_.volumes()) {
          try {
            choose_volume(v.id);
          } catch (const MeshingError& e) {
            if (!options_.refuse_per_volume || e.entity().dim != 3) {
              if (restart_ && round < kMaxRounds) break;  // the next round may fit it
              throw;
            }
            selection_.refused[v.id] = {e.code(), e.message(), e.hint()};
          }
        }
        if (!restart_ || round >= kMaxRounds) break;
      }
    }
    for (const auto& [v, types] : volume_types_)
      planned_types_.insert(planned_types_.end(), types.begin(), types.end());
    job_.planned_vertex_types = &planned_types_;
    for (const geom::Surface& s : model_.surfaces()) choose_surface(s.id);
    if (options_.check_intervals) relax_until_feasible();
    for (const auto& [v, targets] : waits_for_) {
      if (!targets.empty()) selection_.waits_for[v].assign(targets.begin(), targets.end());
    }
    return selection_;
  }

 private:
  // A surface pin that contradicts a role: the message names both.
  const io::SurfaceSetting* surface_pin(int surface) const {
    const auto* pin = find_setting(settings_.surfaces, surface);
    return pin && pin->scheme != "auto" ? pin : nullptr;
  }

  // A mappable surface (4 END corners, map applies) meshed by map is the
  // mesh submap makes of it (one lattice rectangle: the same constraints,
  // opposite sides equal), so a volume that needs map and one that needs
  // submap on it agree: the surface is mapped (issue 16, item 6). A pin is
  // the user's word and is not reinterpreted.
  bool compatible(int surface, const std::string& a, const std::string& b) const {
    if (a == b) return true;
    const bool pair = (a == "map" && b == "submap") || (a == "submap" && b == "map");
    if (!pair) return false;
    const scheme::SurfaceScheme* map = registry_.surface_scheme("map");
    return map != nullptr &&
           map->applicable(scheme::SurfaceView{model_, surface, nullptr, &job_}).ok;
  }

  // The waits of `volume` taking `roles` (a volume that meshes a shared
  // surface itself is meshed before the neighbour that takes its mesh).
  std::map<int, std::set<int>> waits_with(int volume, const scheme::SurfaceRoles& roles) const {
    std::map<int, std::set<int>> waits = waits_for_;
    for (const auto& [surface, role] : roles) {
      const auto it = roles_.find(surface);
      if (it == roles_.end()) continue;
      const bool mine = role == scheme::kMeshedByVolume;
      const bool theirs = it->second.scheme == scheme::kMeshedByVolume;
      if (theirs && !mine) waits[volume].insert(it->second.volume);
      if (mine && !theirs) waits[it->second.volume].insert(volume);
    }
    return waits;
  }

  // Why `roles` cannot be taken by `volume`, or "" when they fit. A
  // conflict over who meshes a shared surface says in `ask` what the
  // neighbour chosen earlier could do instead.
  std::string role_conflict(int volume, const std::string& scheme_name,
                            const scheme::SurfaceRoles& roles, const std::set<int>& takes,
                            Request* ask = nullptr) const {
    for (const auto& [surface, role] : roles) {
      auto it = roles_.find(surface);
      const bool mine = role == scheme::kMeshedByVolume;
      const bool theirs = it != roles_.end() && it->second.scheme == scheme::kMeshedByVolume;
      if (it != roles_.end() && (mine || theirs)) {
        // One volume meshes the surface itself; the other must take that mesh.
        const bool taken =
            mine ? !theirs && it->second.takes_existing : !mine && takes.count(surface) > 0;
        // What the neighbour could do: take the mesh this volume makes, or
        // leave the surface to its surface scheme.
        if (ask && !taken) *ask = {it->second.volume, surface, mine};
        if (mine && theirs) {
          return "surface " + std::to_string(surface) + " would be meshed by both volume " +
                 std::to_string(it->second.volume) + " (" + it->second.volume_scheme +
                 ") and volume " + std::to_string(volume) + " (" + scheme_name +
                 "), each sweep ending on it or imprinting it";
        }
        if (!taken) {
          return "surface " + std::to_string(surface) + " is meshed by " +
                 (theirs ? "volume " + std::to_string(it->second.volume) + " (" +
                               it->second.volume_scheme + ")"
                         : "volume " + std::to_string(volume) + " (" + scheme_name + ")") +
                 " itself, and volume " +
                 (theirs ? std::to_string(volume) + " (" + scheme_name + ") needs " + role
                         : std::to_string(it->second.volume) + " (" + it->second.volume_scheme +
                               ") needs " + it->second.scheme) +
                 " on it";
        }
        continue;
      }
      if (it != roles_.end() && !compatible(surface, it->second.scheme, role)) {
        return "surface " + std::to_string(surface) + " needs " + role + " for volume " +
               std::to_string(volume) + " (" + scheme_name + ") but " + it->second.scheme +
               " for volume " + std::to_string(it->second.volume) + " (" +
               it->second.volume_scheme + ")";
      }
      if (const auto* pin = surface_pin(surface); pin && pin->scheme != role) {
        if (ask) ask->pin = true;
        return "surface " + std::to_string(surface) + " is pinned to " + pin->scheme + " at " +
               place(pin->where) + " but volume " + std::to_string(volume) + " (" + scheme_name +
               ") needs " + role;
      }
    }
    return {};
  }

  // The shared surfaces `volume` taking `roles` would mesh itself that a
  // neighbour chosen earlier takes as it finds them: the neighbour waits for
  // this volume there, which closes a cycle when this volume waits for it
  // elsewhere (the second half of a ring of sweeps round an axis).
  std::set<int> closing_surfaces(int volume, const scheme::SurfaceRoles& roles) const {
    std::set<int> out;
    for (const auto& [surface, role] : roles) {
      if (role != scheme::kMeshedByVolume) continue;
      const auto it = roles_.find(surface);
      if (it != roles_.end() && it->second.volume != volume &&
          it->second.scheme != scheme::kMeshedByVolume && it->second.takes_existing)
        out.insert(surface);
    }
    return out;
  }

  // The surface whose mesh `surface` gets: itself when a surface scheme
  // meshes it, else the origin of the surface the sweep that meshes it
  // starts from; 0 when unknown (a sweep that is not one-to-one).
  int origin(int surface) const {
    for (size_t hop = 0; hop <= roles_.size(); ++hop) {
      const auto it = roles_.find(surface);
      if (it == roles_.end() || it->second.scheme != scheme::kMeshedByVolume) return surface;
      const auto from = sweep_source_.find(it->second.volume);
      if (from == sweep_source_.end() || from->second == 0) return 0;
      surface = from->second;
    }
    return 0;  // a cycle of sweeps, each meshing the next one's source
  }

  // The neighbour chosen earlier may plan around the surface (a sweep the
  // other way round): it is asked once, and the volumes are chosen again.
  void request(const Request& ask) {
    if (ask.volume == 0) return;
    scheme::NeighbourMeshes& y = yield_[ask.volume];
    std::set<int>& list = ask.take ? y.made : y.kept;
    if (list.insert(ask.surface).second) restart_ = true;
  }

  // Whether candidate `c` for a volume takes every surface in `n.made` as
  // it finds it and meshes none of `n.kept` itself.
  bool honours(const Candidate& c, const scheme::VolumeView& view,
               const scheme::NeighbourMeshes& n) const {
    const scheme::VolumeScheme* vs = registry_.volume_scheme(c.scheme);
    scheme::VolumeView planned = view;
    planned.plan = c.applicability.plan.get();
    const scheme::SurfaceRoles roles = vs->roles(planned);
    const std::vector<int> taken = vs->takes_existing_mesh(planned);
    for (int s : n.made) {
      const auto it = roles.find(s);
      if (it != roles.end() && (it->second == scheme::kMeshedByVolume ||
                                std::find(taken.begin(), taken.end(), s) == taken.end()))
        return false;
    }
    for (const std::set<int>* list : {&n.kept, &n.closing}) {
      for (int s : *list) {
        const auto it = roles.find(s);
        if (it != roles.end() && it->second == scheme::kMeshedByVolume) return false;
      }
    }
    return true;
  }

  // The shared surfaces of `id` the choices so far fix, with the requests
  // made of it in earlier rounds.
  scheme::NeighbourMeshes neighbours_of(int id) const {
    scheme::NeighbourMeshes n;
    if (const auto it = yield_.find(id); it != yield_.end()) n = it->second;
    for (const auto& shell : model_.volume(id).shells) {
      for (const auto& use : shell) {
        const auto it = roles_.find(use.surface);
        if (it == roles_.end() || it->second.volume == id) continue;
        if (it->second.scheme == scheme::kMeshedByVolume) {
          n.made.insert(use.surface);
        } else if (!it->second.takes_existing) {
          n.kept.insert(use.surface);
          n.kept_schemes[use.surface] = it->second.scheme;
        }
      }
    }
    return n;
  }

  void choose_volume(int id) {
    const scheme::NeighbourMeshes neighbours = neighbours_of(id);
    const scheme::VolumeView view{model_, id, nullptr, &job_, nullptr, &neighbours};
    const auto* pin = find_setting(settings_.volumes, id);
    // elements="wedge" / "mixed": only schemes that make wedges are candidates.
    const io::ElementKind elements = job_.elements(id);
    const bool wedge = elements != io::ElementKind::Hex;
    const std::string kind = elements == io::ElementKind::Mixed ? "mixed" : "wedge";
    std::vector<const scheme::VolumeScheme*> schemes;
    for (const scheme::VolumeScheme* s : registry_.volume_schemes()) {
      if (!wedge || s->makes_wedges()) {
        schemes.push_back(s);
      } else if (pin && pin->scheme == s->name()) {
        throw MeshingError(ErrorCode::InvalidInput, EntityRef::volume(id),
                           "volume scheme \"" + pin->scheme + "\" (" + place(pin->where) +
                               ") makes hexes only, but elements=\"" + kind + "\"");
      }
    }
    // A round after a request asks every volume again; an answer depends
    // only on the volume and what its neighbours fix.
    auto& known = evaluated_[{id, neighbours.made, neighbours.kept, neighbours.closing,
                              neighbours.kept_schemes}];
    if (known.empty()) known = evaluate(schemes, view);
    Choice choice{3, id, known, {}, {}, false, false};
    std::vector<const Candidate*> order;
    if (pin && pin->scheme != "auto") {
      const Candidate* c = find_candidate(choice.candidates, pin->scheme);
      if (!c) {
        throw MeshingError(ErrorCode::NotSupported, EntityRef::volume(id),
                           "volume scheme \"" + pin->scheme + "\" (" + place(pin->where) +
                               ") is not available in this release");
      }
      if (!c->applicability.ok) {
        throw MeshingError(ErrorCode::NotApplicable, EntityRef::volume(id),
                           pin->scheme + " pinned at " + place(pin->where) +
                               " does not apply: " + c->applicability.why);
      }
      order.push_back(c);
      choice.pinned = true;
    } else {
      order = ranked(choice.candidates);
      if (order.empty()) {
        throw MeshingError(
            ErrorCode::NotApplicable, EntityRef::volume(id),
            job_.no_scheme_applies(id) + " (" + all_reasons(choice.candidates) + ")");
      }
    }
    // Requests made of this volume in an earlier round (a later neighbour
    // cannot do without meshing a shared surface, or without its surface
    // scheme): the candidates that honour them come first.
    if (const auto it = yield_.find(id); it != yield_.end() && !choice.pinned) {
      std::stable_partition(order.begin(), order.end(),
                            [&](const Candidate* c) { return honours(*c, view, it->second); });
    }
    std::string conflicts;
    std::vector<Request> asks;  // from the conflicts of the candidates passed over
    std::set<int> closing;      // surfaces whose meshing here closed a cycle of waits, or another
                                // sweep of the same origin ends on too
    for (const Candidate* c : order) {
      const scheme::VolumeScheme* vs = registry_.volume_scheme(c->scheme);
      // The scheme's own plan from its applicable(), handed back.
      scheme::VolumeView planned = view;
      planned.plan = c->applicability.plan.get();
      const scheme::SurfaceRoles roles = vs->roles(planned);
      const std::vector<int> taken = vs->takes_existing_mesh(planned);
      const std::set<int> takes(taken.begin(), taken.end());
      Request ask;
      std::string conflict = role_conflict(id, c->scheme, roles, takes, &ask);
      std::map<int, std::set<int>> waits = waits_with(id, roles);
      if (conflict.empty() && has_cycle(waits)) {
        conflict = "volume " + std::to_string(id) + " (" + c->scheme +
                   ") and its neighbours would each wait for the other's mesh of a shared surface";
        const std::set<int> more = closing_surfaces(id, roles);
        closing.insert(more.begin(), more.end());
      }
      if (!conflict.empty()) {
        conflicts += (conflicts.empty() ? "" : "; ") + conflict;
        asks.push_back(ask);
        // Two sweeps ending on one surface: this one may end on the mesh
        // the other leaves there, as a ring's last piece does, when both
        // meshes come from one surface's mesh (torus quarters: two sweep
        // away from one cut face, two into the opposite one).
        const auto mine = roles.find(ask.surface);
        const auto theirs = roles_.find(ask.surface);
        if (ask.volume && mine != roles.end() && mine->second == scheme::kMeshedByVolume &&
            theirs != roles_.end() && theirs->second.scheme == scheme::kMeshedByVolume) {
          const int from = vs->sweep_source(planned);
          if (from && origin(from) && origin(from) == origin(ask.surface))
            closing.insert(ask.surface);
        }
        continue;
      }
      waits_for_ = std::move(waits);
      for (const auto& [surface, role] : roles) {
        if (role != scheme::kMeshedByVolume && takes.count(surface) == 0) imposed_.insert(surface);
        auto it = roles_.find(surface);
        if (it != roles_.end() &&
            (role == scheme::kMeshedByVolume) != (it->second.scheme == scheme::kMeshedByVolume)) {
          // The volume that meshes it itself keeps (or takes) the surface.
          if (role == scheme::kMeshedByVolume) it->second = {role, id, c->scheme, false};
          continue;
        }
        // map and submap on one mappable surface: mapped (compatible()).
        if (it != roles_.end() && it->second.scheme != role) {
          if (role == "map")
            it->second = {role, id, c->scheme,
                          takes.count(surface) > 0 && it->second.takes_existing};
          continue;
        }
        roles_[surface] = {role, id, c->scheme, takes.count(surface) > 0};
      }
      // A request this volume cannot honour without a neighbour's help (the
      // candidate that honours it conflicts): passed on to that neighbour.
      if (c != order.front() && yield_.count(id)) {
        for (const Request& a : asks) request(a);
      }
      volume_types_[id] = vs->vertex_types(planned);
      sweep_source_[id] = vs->sweep_source(planned);
      choice.scheme = c->scheme;
      choice.reason = choice.pinned
                          ? "pinned at " + place(pin->where)
                          : "best applicable, score " + score_text(c->applicability.score);
      if (const auto it = yield_.find(id); it != yield_.end() && honours(*c, view, it->second)) {
        choice.reason +=
            " (planned around shared surface" + listed(it->second) + " for its neighbours)";
        if (!it->second.closing.empty()) selection_.ring_closers.insert(id);
      }
      if (!choice.pinned && c != order.front())
        choice.reason += " (better ones conflict: " + conflicts + ")";
      selection_.volumes.push_back(std::move(choice));
      return;
    }
    for (const Request& a : asks) request(a);
    // A ring of sweeps: the next round asks this volume to end on the meshes
    // its neighbours take as found (only when nothing else fits: a sweep
    // onto an existing mesh needs that mesh to be its source's image).
    std::set<int>& close = yield_[id].closing;
    for (int s : closing) {
      if (close.insert(s).second) restart_ = true;
    }
    // A pin that contradicts every candidate is the input's fault; else the
    // volume is refused like one no scheme applies to (plan lists it).
    const bool pinned =
        std::any_of(asks.begin(), asks.end(), [](const Request& a) { return a.pin; });
    // Two sweeps ending on one shared surface from its two sides (a
    // bracket's foot swept down onto a plate swept up): a cut or another
    // scheme for this volume does not help, so the hint says what does.
    const bool both_sweep = conflicts.find("would be meshed by both") != std::string::npos;
    throw MeshingError(
        pinned ? ErrorCode::InvalidInput : ErrorCode::NotApplicable, EntityRef::volume(id),
        "no applicable scheme fits its neighbours: " + conflicts,
        both_sweep ? "one surface cannot yet take the imprints of two sweeps (README, Limits); a "
                     "sweep hint that starts one of them from that surface (<volume sources>) "
                     "may fit, else --allow-partial writes the volumes that mesh"
                   : "");
  }

  void choose_surface(int id) {
    const scheme::SurfaceView view{model_, id, nullptr, &job_};
    Choice choice{2, id, {}, {}, {}, false, false};
    const io::SurfaceSetting* pin = surface_pin(id);
    auto role = roles_.find(id);
    if (role != roles_.end() && role->second.scheme == scheme::kMeshedByVolume) {
      choice.scheme = scheme::kMeshedByVolume;
      choice.reason = "meshed by volume " + std::to_string(role->second.volume) + " (" +
                      role->second.volume_scheme + ")";
      choice.fixed_by_volume = true;
      selection_.surfaces.push_back(std::move(choice));
      return;
    }
    choice.candidates = evaluate(registry_.surface_schemes(), view);
    if (role != roles_.end()) {
      const Candidate* c = find_candidate(choice.candidates, role->second.scheme);
      if (!c || !c->applicability.ok) {
        throw MeshingError(
            ErrorCode::NotApplicable, EntityRef::surface(id),
            "volume " + std::to_string(role->second.volume) + " (" + role->second.volume_scheme +
                ") needs " + role->second.scheme + ", which " +
                (c ? "does not apply: " + c->applicability.why : std::string("is not available")));
      }
      choice.scheme = role->second.scheme;
      choice.reason = "role from volume " + std::to_string(role->second.volume) + " (" +
                      role->second.volume_scheme + ")";
      choice.fixed_by_volume = true;
      choice.pinned = pin != nullptr;
      choice.any_quad_mesh = !choice.pinned && imposed_.count(id) == 0;
    } else if (pin) {
      const Candidate* c = find_candidate(choice.candidates, pin->scheme);
      if (!c) {
        throw MeshingError(ErrorCode::NotSupported, EntityRef::surface(id),
                           "surface scheme \"" + pin->scheme + "\" (" + place(pin->where) +
                               ") is not available in this release");
      }
      if (!c->applicability.ok) {
        throw MeshingError(ErrorCode::NotApplicable, EntityRef::surface(id),
                           pin->scheme + " pinned at " + place(pin->where) +
                               " does not apply: " + c->applicability.why);
      }
      choice.scheme = pin->scheme;
      choice.reason = "pinned at " + place(pin->where);
      choice.pinned = true;
    } else {
      const auto order = ranked(choice.candidates);
      if (order.empty()) {
        throw MeshingError(ErrorCode::NotApplicable, EntityRef::surface(id),
                           "no surface scheme applies (" + all_reasons(choice.candidates) + ")");
      }
      choice.scheme = order.front()->scheme;
      choice.reason = "best applicable, score " + score_text(order.front()->applicability.score);
    }
    selection_.surfaces.push_back(std::move(choice));
  }

  // The automatic surface choice to relax for a conflict on `curves`: the
  // lowest-scoring one that has a next candidate; nullptr when none.
  Choice* relaxable(const std::set<int>& curves) {
    Choice* best = nullptr;
    double best_score = 2;
    for (Choice& c : selection_.surfaces) {
      if (c.pinned || c.fixed_by_volume) continue;
      bool touches = curves.empty();
      for (const auto& loop : model_.surface(c.id).loops) {
        for (const auto& use : loop.uses) touches = touches || curves.count(use.curve) > 0;
      }
      if (!touches) continue;
      const auto order = ranked(c.candidates);
      auto it = std::find_if(order.begin(), order.end(),
                             [&](const Candidate* k) { return k->scheme == c.scheme; });
      if (it == order.end() || it + 1 == order.end()) continue;
      const double score = (*it)->applicability.score;
      if (score < best_score) {
        best = &c;
        best_score = score;
      }
    }
    return best;
  }

  void relax_until_feasible() {
    for (int round = 0;; ++round) {
      try {
        selection_.intervals = intervals::solve(
            pipeline::build_interval_problem(model_, registry_, selection_.plan(), settings_),
            memoised());
        if (options_.pave_starved_curves)
          pave_where_curves_starve(model_, registry_, settings_, selection_, memo_);
        return;
      } catch (const intervals::IntervalConflict& e) {
        Choice* c = round < options_.max_relaxations ? relaxable(e.curves()) : nullptr;
        if (!c) throw_conflict(e);
        const auto order = ranked(c->candidates);
        auto it = std::find_if(order.begin(), order.end(),
                               [&](const Candidate* k) { return k->scheme == c->scheme; });
        const std::string next = (*(it + 1))->scheme;
        selection_.relaxations.push_back("surface " + std::to_string(c->id) + ": " + c->scheme +
                                         " -> " + next + " (" + e.message() + ")");
        c->reason = "relaxed from " + c->scheme + ": interval conflict";
        c->scheme = next;
      }
    }
  }

  // Whether `choice`'s surface (or one of its volume's) uses one of `curves`.
  bool touches(const Choice& choice, const std::set<int>& curves) const {
    std::vector<int> surfaces;
    if (choice.dim == 2) {
      surfaces.push_back(choice.id);
    } else {
      for (const auto& shell : model_.volume(choice.id).shells)
        for (const auto& use : shell) surfaces.push_back(use.surface);
    }
    for (int sid : surfaces)
      for (const auto& loop : model_.surface(sid).loops)
        for (const auto& use : loop.uses)
          if (curves.count(use.curve)) return true;
    return false;
  }

  // An interval conflict nothing automatic can relax, as an error a person
  // can act on (issue 16 item 5): the first volume it involves, the
  // conflicting constraints as details (the command line puts them on a line
  // of their own), and what to change: the pins it involves, if any; else
  // the counts follow from the schemes' own structure (a sweep's layers and
  // its sides' lattices), which a cut or another sweep direction changes.
  [[noreturn]] void throw_conflict(const intervals::IntervalConflict& e) const {
    const std::set<int>& curves = e.curves();
    std::vector<std::string> pins;
    for (const io::CurveSetting& c : settings_.curves) {
      const bool hard = c.sizing.intervals || c.sizing.firmness == io::Firmness::Hard;
      if (hard && curves.count(c.id))
        pins.push_back("curve " + std::to_string(c.id) + " (" + place(c.where) + ")");
    }
    int volume = 0;
    for (const Choice& c : selection_.volumes) {
      if (!touches(c, curves)) continue;
      if (volume == 0) volume = c.id;
      if (c.pinned) pins.push_back("volume " + std::to_string(c.id) + " (" + c.reason + ")");
    }
    for (const Choice& c : selection_.surfaces) {
      if (c.pinned && touches(c, curves))
        pins.push_back("surface " + std::to_string(c.id) + " (" + c.reason + ")");
    }
    std::string list;
    for (size_t k = 0; k < pins.size() && k < 4; ++k) list += (k ? ", " : "") + pins[k];
    if (pins.size() > 4) list += " and " + std::to_string(pins.size() - 4) + " more";
    const std::string hint =
        pins.empty()
            ? "the counts follow from the schemes' structure (a sweep's layers, its sides' "
              "lattices); a <webcut> between the features these curves bound, or a sweep "
              "direction hint, changes them"
            : "change or drop one of the pins it involves: " + list;
    // The solver's message ends with "(curves ...)"; the constraints go to
    // the details.
    std::string what = e.message();
    const std::string prefix = "interval constraints cannot all hold: ";
    if (what.rfind(prefix, 0) == 0) what = what.substr(prefix.size());
    throw MeshingError(ErrorCode::Infeasible, volume > 0 ? EntityRef::volume(volume) : e.entity(),
                       "no interval counts satisfy all of its constraints, and no automatic "
                       "scheme choice is left to relax (" +
                           what + ")",
                       hint);
  }

  // Relaxations change a few surfaces' constraints: only the components
  // they touch are solved again.
  intervals::SolveOptions memoised() {
    intervals::SolveOptions options;
    options.memo = &memo_;
    return options;
  }

  const geom::Model& model_;
  const scheme::Registry& registry_;
  const io::MeshSettings& settings_;
  scheme::Settings job_;  ///< what every scheme is asked with
  /// Per volume: the vertex types its chosen plan relies on; flattened into
  /// planned_types_ (job_.planned_vertex_types) before the surfaces.
  std::map<int, std::vector<io::VertexTypeSetting>> volume_types_;
  std::vector<io::VertexTypeSetting> planned_types_;
  SelectOptions options_;
  std::map<int, Role> roles_;
  /// Surfaces some chosen volume needs meshed by its role's scheme (not
  /// taken as found): no fallback there (Choice::any_quad_mesh).
  std::set<int> imposed_;
  std::map<int, std::set<int>> waits_for_;        // volume -> volumes meshed before it
  std::map<int, scheme::NeighbourMeshes> yield_;  // requests made of a volume
  std::map<int, int> sweep_source_;  // chosen volume -> the surface it sweeps from (0: none)
  bool restart_ = false;             // a request was added this round
  std::map<std::tuple<int, std::set<int>, std::set<int>, std::set<int>, std::map<int, std::string>>,
           std::vector<Candidate>>
      evaluated_;
  Selection selection_;
  intervals::SolveMemo memo_;
};

}  // namespace

std::string describe(const Candidate& c) {
  std::string line = (c.applicability.ok ? "+ " : "- ") + c.scheme;
  if (c.applicability.ok) line += " score " + score_text(c.applicability.score);
  if (!c.applicability.why.empty()) line += ": " + c.applicability.why;
  return line;
}

pipeline::SchemePlan Selection::plan() const {
  const auto entry = [](const Choice& c) {
    pipeline::PlanEntry e{c.scheme, c.reason, {}, nullptr, c.any_quad_mesh};
    for (const Candidate& k : c.candidates) {
      e.details.push_back(describe(k));
      if (k.scheme == c.scheme) e.data = k.applicability.plan;  // carried to constrain() and mesh()
    }
    return e;
  };
  pipeline::SchemePlan plan;
  for (const Choice& c : volumes) plan.volumes[c.id] = entry(c);
  for (const Choice& c : surfaces) plan.surfaces[c.id] = entry(c);
  plan.refused_volumes = refused;
  plan.waits_for = waits_for;
  plan.ring_closers = ring_closers;
  plan.intervals = intervals;
  return plan;
}

Selection select_schemes(const geom::Model& model, const scheme::Registry& registry,
                         const io::MeshSettings& settings, const SelectOptions& options) {
  pipeline::check_scheme_names(settings, registry);  // a typo lists the registered names
  return Selector(model, registry, settings, options).run();
}

pipeline::Planner planner() {
  return [](const geom::Model& model, const scheme::Registry& registry,
            const io::MeshSettings& settings, int dim) {
    SelectOptions options;
    options.dim = dim;
    options.refuse_per_volume = true;
    return select_schemes(model, registry, settings, options).plan();
  };
}

pipeline::MeshOptions mesh_options(int dim, int threads) {
  pipeline::MeshOptions options;
  options.planner = planner();
  options.dim = dim;
  options.threads = threads;
  return options;
}

}  // namespace cooperage::selector
