#include "selector/starved_curves.h"

#include "framework/pipeline/interval_setup.h"

#include <algorithm>
#include <cstdio>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace cooperage::selector {
namespace {

struct Context {
  const geom::Model& model;
  const scheme::Registry& registry;
  const io::MeshSettings& settings;
  Selection& selection;
  intervals::SolveMemo& memo;
  const intervals::IntervalProblem& problem;  ///< goals and size functions
  int solves = 0;
};

constexpr int kMaxSolves = 12;  // each one more interval solve
// Fewer wanted: one interval short is not worth a pave (nor a solve with its
// parity rows, which CBC takes longer over).
constexpr double kLeastStarvedGoal = 4;

bool touches(const geom::Model& model, int surface, int curve) {
  for (const auto& loop : model.surface(surface).loops) {
    for (const auto& use : loop.uses) {
      if (use.curve == curve) return true;
    }
  }
  return false;
}

bool applicable_candidate(const Choice& c, const std::string& scheme) {
  return std::any_of(c.candidates.begin(), c.candidates.end(),
                     [&](const Candidate& k) { return k.scheme == scheme && k.applicability.ok; });
}

// A face narrower than its element size (mean width 2 area / perimeter):
// one row of mapped quads across it is the best it can get, and paved
// between sides of different counts it gets slivers (real-cad OCC2368: a
// conical band 0.1 wide at size 4 went from quads of 0.66 to triangles of
// 0.13). Such a face is not paved to free a curve.
bool narrow(const Context& x, int surface) {
  double perimeter = 0, size = 0;
  for (const auto& loop : x.model.surface(surface).loops) {
    for (const auto& use : loop.uses) {
      perimeter += x.model.curve(use.curve).length;
      size = std::max(size, pipeline::curve_target_size(x.model, x.settings, use.curve));
    }
  }
  return perimeter > 0 && 2 * x.model.surface(surface).area / perimeter < size;
}

// A curve on a narrow face that map or submap meshes: its small goal is
// (likely) that face's width, which the map's rows resolve at any count
// along it (real-cad OCC2368: a circle asked 225 intervals for the 0.1 band
// beside it at size 4, and freeing it lowered the face beyond).
bool across_mapped_strip(const Context& x, int curve) {
  for (const Choice& c : x.selection.surfaces) {
    if ((c.scheme == "map" || c.scheme == "submap") && touches(x.model, c.id, curve) &&
        narrow(x, c.id))
      return true;
  }
  return false;
}

// The shares of their goals the graded curves get (capped at 1), ascending:
// a change is better when this is lexicographically larger (leximin), so
// freeing one curve must not starve another one more (real-cad OCC2368: two
// rims freed to their goal left the chain of circles they held up at 41 %
// of its own, where all had had 49 %).
std::vector<double> shares(const intervals::IntervalProblem& problem,
                           const intervals::IntervalSolution& solution) {
  std::vector<double> out;
  for (const auto& entry : problem.size_functions()) {
    const double goal = problem.curves().at(entry.first).target();
    out.push_back(std::min(1.0, solution.intervals.at(entry.first) / goal));
  }
  std::sort(out.begin(), out.end());
  return out;
}

// One starved curve: every automatic map/submap choice on it paved, kept if
// the curve gets more intervals and the shares improve; then each paved
// choice given back its scheme where the curve and the shares do as well
// without the pave.
bool pave_to_free(Context& x, int curve) {
  if (x.solves >= kMaxSolves) return false;
  Selection& selection = x.selection;
  // A trial only relaxes constraints (a paved loop keeps the parity its map
  // gave it): the current solution is CBC's first one.
  const std::map<int, int> start = selection.intervals->intervals;
  const auto solve = [&]() -> std::optional<intervals::IntervalSolution> {
    ++x.solves;
    intervals::SolveOptions options;
    options.memo = &x.memo;
    options.start = &start;
    try {
      return intervals::solve(
          pipeline::build_interval_problem(x.model, x.registry, selection.plan(), x.settings),
          options);
    } catch (const intervals::IntervalConflict&) {
      return std::nullopt;
    }
  };
  std::vector<std::pair<Choice*, std::string>> paved;  // ascending id, scheme before
  for (Choice& c : selection.surfaces) {
    if (c.pinned || c.fixed_by_volume || (c.scheme != "map" && c.scheme != "submap")) continue;
    if (!touches(x.model, c.id, curve) || !applicable_candidate(c, "pave") || narrow(x, c.id))
      continue;
    paved.emplace_back(&c, c.scheme);
    c.scheme = "pave";
  }
  if (paved.empty()) return false;
  const int held = selection.intervals->intervals.at(curve);
  std::optional<intervals::IntervalSolution> best = solve();
  if (!best || best->intervals.at(curve) <= held ||
      shares(x.problem, *best) <= shares(x.problem, *selection.intervals)) {
    for (const auto& [c, was] : paved) c->scheme = was;
    return false;
  }
  for (auto it = paved.begin(); it != paved.end() && paved.size() > 1 && x.solves < kMaxSolves;) {
    it->first->scheme = it->second;
    auto without = solve();
    if (without && without->intervals.at(curve) >= best->intervals.at(curve) &&
        shares(x.problem, *without) >= shares(x.problem, *best)) {
      best = std::move(without);
      it = paved.erase(it);
    } else {
      it->first->scheme = "pave";
      ++it;
    }
  }
  const double goal = x.problem.curves().at(curve).target();
  for (const auto& [c, was] : paved) {
    char why[160];
    std::snprintf(why, sizeof why, "curve %d wants %.0f intervals; %s held it at %d", curve, goal,
                  was.c_str(), held);
    selection.relaxations.push_back("surface " + std::to_string(c->id) + ": " + was + " -> pave (" +
                                    why + ")");
    c->reason = "paved instead of " + was + ": " + why;
  }
  selection.intervals = std::move(best);
  return true;
}

}  // namespace

void pave_where_curves_starve(const geom::Model& model, const scheme::Registry& registry,
                              const io::MeshSettings& settings, Selection& selection,
                              intervals::SolveMemo& memo) {
  const intervals::IntervalProblem problem =
      pipeline::build_interval_problem(model, registry, selection.plan(), settings);
  Context x{model, registry, settings, selection, memo, problem};
  std::set<int> attempted;  // starved curves tried since the last change
  for (bool changed = true; changed;) {
    changed = false;
    for (const auto& entry : problem.size_functions()) {
      const int curve = entry.first;
      const double goal = problem.curves().at(curve).target();
      if (goal < kLeastStarvedGoal || 2 * selection.intervals->intervals.at(curve) > goal ||
          across_mapped_strip(x, curve))
        continue;
      if (!attempted.insert(curve).second) continue;
      if (pave_to_free(x, curve)) {
        changed = true;
        attempted.clear();
      }
    }
  }
}

}  // namespace cooperage::selector
