// Internal: a mixed-integer program as plain arrays, what ilp.cpp hands to
// CBC in its module (libcooperage_cbc.so, cbc_module.cpp). CBC's libraries
// are loaded on the first solve instead of at start-up: ~12,700 symbol
// relocations that a `--version`, a report or a Python import never need
// (issue 20). Both sides are built together, so C++ types cross the
// boundary; the module's version is checked (kCbcModuleAbi).
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace cooperage::intervals::detail {

/// Raised when this header changes the layout of what crosses the module.
constexpr int kCbcModuleAbi = 2;

struct CbcProblem {
  /// Columns: bounds (+-std::numeric_limits<double>::max() for none, which
  /// is CBC's infinity), objective coefficients, integrality.
  std::vector<double> col_lo, col_hi, obj;
  std::vector<char> integer;
  /// Rows: (column, coefficient) terms between their bounds.
  std::vector<std::vector<std::pair<int, double>>> row_terms;
  std::vector<double> row_lo, row_hi;
  /// A MIP start by column name ("x<j>"); empty: none.
  std::vector<std::pair<std::string, double>> mip_start;
  int random_seed = 0;
  double max_seconds = 60.0;
  /// CBC stops once its answer is proven this close to the optimum (relative).
  double ratio_gap = 0.02;
};

enum class CbcStatus { Optimal = 0, Feasible = 1, Infeasible = 2, NoSolution = 3 };

struct CbcAnswer {
  CbcStatus status = CbcStatus::NoSolution;
  std::vector<double> x;  ///< every column's value when a solution was found
};

/// The module's entry point (cooperage_cbc_solve).
using CbcSolveFn = void (*)(const CbcProblem*, CbcAnswer*);

}  // namespace cooperage::intervals::detail
