// Global interval assignment: the integer program of an IntervalProblem,
// split into independent components, each solved by COIN-OR CBC.
//
// Formulation (one mixed-integer program per connected component; curves are
// connected when a constraint names both; ALGORITHMS.md sec. 2, Mitchell 1997,
// 2013):
//
//   variables   x_c integer, min_c <= x_c <= max_c   (Hard: x_c = fixed_c)
//               u_ck, d_ck continuous in [0, width of segment k], the
//               increments of x_c above and below its cost's centre p_c
//               m_e integer, free, one per Even constraint
//   minimise    sum_c w_c (sum_k s_k u_ck - sum_k s_k d_ck)
//               w = 1 (Default), soft_weight (Soft)
//   subject to  sum a_i x_i  <=|=|>=  b            (Linear: map, submap, ...)
//               sum x_i - 2 m_e = 0                 (Even: pave loops)
//               x_c - sum_k u_ck + sum_k d_ck = p_c (non-hard curves)
//
// The cost of curve c is h(x) = f + f^3 with Mitchell's relative deviation
// f(x) = (x - g)/g above the goal g and (g - x)/x below it (deviation.h).
// h is convex, so its secants between consecutive integer breakpoints
// (every integer within 4 of g, then 6, 8, 12, 16, ... away; p_c is the one
// nearest g) form a convex piecewise-linear function equal to h at the
// breakpoints, the last secant extended. Their slopes s_k increase away from
// p_c (the cost of a down increment is -s_k), so the cheaper increments fill
// first and at the optimum the objective is that function less the constant
// h(p_c); near the goal the integer optimum minimises sum w h exactly. The cubic term makes large deviations cost more than
// several small ones (Mitchell's min sum f^3, close to lexicographic max-min).
// A non-hard curve with a `fixed` count aims at that count instead of g.
//
// A curve named by no constraint takes the better of floor/ceil of its goal
// under h (this is round(goal) except in a sliver just below k + 1/2),
// clamped to its bounds; a hard one takes its fixed count.
//
// Model reductions and safeguards: curves tied by a plain equality x_a = x_b
// (map faces) share one column carrying all their costs; every column gets a
// finite box (twice the sum of all targets, minima and fixed counts of the
// component plus the constraint constants) so branch and bound always ends;
// equality and parity rows are checked for divisibility (gcd) before CBC,
// which does not always prove such integer infeasibility; and a uniform
// count (every free column at the same even value near the median target,
// if that satisfies the component) is passed to CBC as a MIP start. CBC runs
// through its standard driver (CbcMain0/CbcMain1: preprocessing, cuts,
// heuristics), silenced, and stops once its solution is proven within 2 %
// of the optimum's cost (CBC's ratio gap): on the 290-column component of a
// 137-face cylinder head, proving 1 % took twice as long (4.7 s of CPU
// against 2.5) for a solution 0.27 % cheaper, a difference of one interval
// on a few curves. A component of fewer than 50 columns is solved to its
// proven optimum instead (ilp.cpp says why). When CBC hits max_seconds with
// a solution, that solution is used and a warning logged; without one,
// solve() throws Infeasible saying the limit was reached.
//
// Determinism: constraints are put into a canonical form (terms merged and
// sorted by curve id, first coefficient positive) and sorted before the model
// is built, CBC runs single-threaded with fixed seeds, and components are
// solved independently in ascending order of their smallest curve id, so the
// answer does not depend on the order in which curves or constraints were
// added. (A run cut short by the time limit depends on machine speed.)
//
// Preferences (Constraint::preferred) take no part in the components: the
// needs are solved first, and only where their answer breaks a preference
// are the components it touches solved again as one, with the needs and the
// preferences among their curves; where that cannot hold, the needs' answer
// stays. A preference the answer keeps anyway changes nothing (an extra row
// moves CBC's answer within its optimality gap, and a part that meshed
// failed so).
//
// Infeasibility: the component's constraints and bound items (hard counts,
// minima > 1, maxima) are reduced by a deletion filter (Chinneck) to an
// irreducible infeasible subset when there are fewer than `iis_item_limit`
// items (each check limited to iis_check_seconds; an unproven check keeps
// its item); the error names those items and the curves they involve.
#pragma once

#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "framework/core/error.h"
#include "framework/intervals/interval_problem.h"

namespace cooperage::intervals {

/// The Infeasible error of solve(), carrying the curves of the irreducible
/// conflict as data, so callers (the selector's relaxation) need not read the
/// message text.
class IntervalConflict : public MeshingError {
 public:
  IntervalConflict(const std::string& message, std::set<int> curves)
      : MeshingError(ErrorCode::Infeasible, message), curves_(std::move(curves)) {}
  /// Ids of the curves the conflicting constraints and bounds involve.
  const std::set<int>& curves() const { return curves_; }

 private:
  std::set<int> curves_;
};

/// Counts of components solved before, keyed by everything that defines a
/// component (its curves' ids, goals, firmness and bounds, its canonical
/// constraints with their labels). A caller that solves many problems
/// differing in a few constraints (the selector's relaxations and trials)
/// passes one memo and solves only the components that changed; an
/// unchanged component gets the counts it got before. Not thread-safe.
struct SolveMemo {
  std::map<std::string, std::vector<int>> counts;
};

struct SolveOptions {
  double soft_weight = 10.0;     ///< objective weight of Soft curves (Default = 1)
  double objective_scale = 100;  ///< multiplies the costs for CBC's tolerances
  double max_seconds = 60.0;     ///< CBC time limit per component [s]
  int iis_item_limit = 50;       ///< narrow infeasible components below this many items
  double iis_check_seconds =
      2;                    ///< CBC time limit per narrowing check [s]; unproven keeps the item
  int random_seed = 12345;  ///< CBC/CLP seed (fixed: deterministic)
  SolveMemo* memo = nullptr;  ///< reuse components solved before (nullptr: none)
  /// Counts per curve to give CBC as its first solution where they satisfy
  /// a component (a caller re-solving after relaxing constraints: the old
  /// answer still holds and spares the search for a feasible start).
  const std::map<int, int>* start = nullptr;
};

struct IntervalSolution {
  std::map<int, int> intervals;     ///< curve id -> interval count
  std::map<int, double> deviation;  ///< curve id -> relative deviation f from its target
  double objective = 0.0;           ///< sum of w_c * h_c(x_c) over all curves (unscaled)
  /// The problem's size functions (IntervalProblem::set_size_function), for
  /// placing the nodes of graded curves.
  std::map<int, mesh::SizeFunction> sizes;
};

/// Assigns an interval count to every curve of the problem.
/// \param[in] problem curves with goals and the schemes' constraints
/// \param[in] options weights and solver limits
/// \return counts satisfying every constraint, minimising the cost above
/// \throws MeshingError(InvalidInput) for a constraint naming an unknown curve;
///         IntervalConflict (code Infeasible) naming the curves and
///         constraints of an infeasible component (the first one, by
///         smallest curve id); Infeasible also when CBC's time limit ends
///         without a solution.
IntervalSolution solve(const IntervalProblem& problem, const SolveOptions& options = {});

/// Loads the solver (CBC, a module opened on the first solve otherwise) now:
/// a caller with a moment to spare, the import waiting for its child,
/// hides the ~10 ms of linking there. A failure is left for the first solve
/// to report.
void preload_solver() noexcept;

}  // namespace cooperage::intervals
