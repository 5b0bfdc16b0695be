// Internal: one component of the interval problem as a mixed-integer program,
// built here and solved with CBC (CbcModel over OsiClpSolverInterface) in
// the module cbc_module.cpp. The formulation is documented in solve.h.
#pragma once

#include <optional>
#include <vector>

#include "framework/intervals/interval_problem.h"
#include "framework/intervals/solve.h"

namespace cooperage::intervals::detail {

/// A constraint in canonical form over component-local columns 0..n-1:
/// terms merged, sorted by column, zero coefficients dropped, the first
/// coefficient positive (the sense flipped when negated).
struct Row {
  Constraint::Kind kind = Constraint::Kind::Linear;
  std::vector<std::pair<int, int>> terms;  ///< (column, coefficient)
  Sense sense = Sense::Equal;
  int rhs = 0;
};

/// One cost term of a column: weight * h(x; target).
struct Cost {
  double target = 1.0;
  double weight = 1.0;
};

/// One integer column: bounds and the costs of the curves it stands for
/// (several when curves forced equal were merged; none for hard curves and
/// feasibility checks).
struct Column {
  int lo = 1;
  std::optional<int> hi;
  std::vector<Cost> costs;
};

enum class IlpStatus { Optimal, Feasible, Infeasible, NoSolution };

struct IlpResult {
  IlpStatus status = IlpStatus::NoSolution;
  std::vector<int> x;  ///< one value per column when a solution was found
};

/// Solves min sum w h(x) subject to the rows and column bounds.
/// \param[in] start optional feasible values of the columns, given to CBC as
///                  a MIP start (CBC finds no first solution on its own in
///                  some large, equality-dense components)
IlpResult solve_ilp(const std::vector<Column>& columns, const std::vector<Row>& rows,
                    const SolveOptions& options, const std::vector<int>* start = nullptr);

/// Opens the CBC module now (it is opened on the first solve otherwise).
/// @throws MeshingError(Internal) when it cannot be loaded
void load_solver();

/// True when the values satisfy every row and column bound.
bool satisfies(const std::vector<Column>& columns, const std::vector<Row>& rows,
               const std::vector<int>& x);

}  // namespace cooperage::intervals::detail
