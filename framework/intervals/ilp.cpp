#include "framework/intervals/ilp.h"

#include <chrono>
#include <cmath>
#include <mutex>
#include <string>

#include <coin/CbcModel.hpp>
#include <coin/CbcSolver.hpp>
#include <coin/CoinPackedMatrix.hpp>
#include <coin/OsiClpSolverInterface.hpp>

#include "framework/intervals/deviation.h"

namespace cooperage::intervals::detail {
namespace {

/// Column-wise sparse model under construction.
struct Builder {
  std::vector<double> col_lo, col_hi, obj;
  std::vector<bool> integer;
  std::vector<std::vector<std::pair<int, double>>> row_terms;
  std::vector<double> row_lo, row_hi;

  int add_column(double lo, double hi, double cost, bool is_integer) {
    col_lo.push_back(lo);
    col_hi.push_back(hi);
    obj.push_back(cost);
    integer.push_back(is_integer);
    return static_cast<int>(col_lo.size()) - 1;
  }
  void add_row(std::vector<std::pair<int, double>> terms, double lo, double hi) {
    row_terms.push_back(std::move(terms));
    row_lo.push_back(lo);
    row_hi.push_back(hi);
  }
};

}  // namespace

bool satisfies(const std::vector<Column>& columns, const std::vector<Row>& rows,
               const std::vector<int>& x) {
  for (size_t j = 0; j < columns.size(); ++j)
    if (x[j] < columns[j].lo || (columns[j].hi && x[j] > *columns[j].hi)) return false;
  for (const Row& row : rows) {
    long sum = 0;
    for (auto [col, coeff] : row.terms) sum += static_cast<long>(coeff) * x[col];
    if (row.kind == Constraint::Kind::Even) {
      if (sum % 2 != 0) return false;
    } else if ((row.sense == Sense::LessEqual && sum > row.rhs) ||
               (row.sense == Sense::Equal && sum != row.rhs) ||
               (row.sense == Sense::GreaterEqual && sum < row.rhs)) {
      return false;
    }
  }
  return true;
}

IlpResult solve_ilp(const std::vector<Column>& columns, const std::vector<Row>& rows,
                    const SolveOptions& options, const std::vector<int>* start) {
  const double inf = COIN_DBL_MAX;
  Builder b;
  // x columns first, so column j of the result is curve column j.
  for (const Column& c : columns)
    b.add_column(c.lo, c.hi ? static_cast<double>(*c.hi) : inf, 0.0, true);
  std::vector<std::pair<std::string, double>> mip_start;
  if (start)
    for (size_t j = 0; j < columns.size(); ++j)
      mip_start.emplace_back("x" + std::to_string(j), (*start)[j]);
  for (const Row& row : rows) {
    std::vector<std::pair<int, double>> terms;
    for (auto [col, coeff] : row.terms) terms.emplace_back(col, coeff);
    if (row.kind == Constraint::Kind::Even) {
      const int m = b.add_column(-inf, inf, 0.0, true);  // sum x - 2 m = 0
      if (start) {
        long sum = 0;
        for (auto [col, coeff] : row.terms) sum += static_cast<long>(coeff) * (*start)[col];
        mip_start.emplace_back("x" + std::to_string(m), static_cast<double>(sum / 2));
      }
      terms.emplace_back(m, -2.0);
      b.add_row(std::move(terms), 0.0, 0.0);
      continue;
    }
    const double rhs = row.rhs;
    switch (row.sense) {
      case Sense::LessEqual: b.add_row(std::move(terms), -inf, rhs); break;
      case Sense::Equal: b.add_row(std::move(terms), rhs, rhs); break;
      case Sense::GreaterEqual: b.add_row(std::move(terms), rhs, inf); break;
    }
  }
  // Epigraph of the piecewise-linear cost: t >= slope x + intercept.
  for (size_t j = 0; j < columns.size(); ++j) {
    const Column& c = columns[j];
    if (c.hi && *c.hi == c.lo) continue;  // a constant costs nothing to optimise
    for (const Cost& cost : c.costs) {
      const int t = b.add_column(0.0, inf, options.objective_scale * cost.weight, false);
      const auto points = cost_breakpoints(cost.target, c.lo, c.hi);
      for (auto [slope, intercept] : cost_lines(cost.target, points)) {
        // t - slope x >= intercept
        b.add_row({{t, 1.0}, {static_cast<int>(j), -slope}}, intercept, inf);
      }
    }
  }

  CoinPackedMatrix matrix(false, 0, 0);  // row-ordered
  matrix.setDimensions(0, static_cast<int>(b.col_lo.size()));
  // Room for every row first: appendRow grows the storage by exactly one row
  // otherwise, copying the whole matrix each time (quadratic; a tenth of
  // gmsh_1385_Laufrad's --dim 2 run).
  size_t entries = 0;
  for (const auto& terms : b.row_terms) entries += terms.size();
  matrix.reserve(static_cast<int>(b.row_terms.size()), static_cast<CoinBigIndex>(entries));
  for (const auto& terms : b.row_terms) {
    std::vector<int> idx;
    std::vector<double> val;
    for (auto [col, v] : terms) {
      idx.push_back(col);
      val.push_back(v);
    }
    matrix.appendRow(static_cast<int>(idx.size()), idx.data(), val.data());
  }

  OsiClpSolverInterface solver;
  solver.messageHandler()->setLogLevel(0);
  solver.getModelPtr()->setRandomSeed(options.random_seed);
  solver.loadProblem(matrix, b.col_lo.data(), b.col_hi.data(), b.obj.data(), b.row_lo.data(),
                     b.row_hi.data());
  for (size_t j = 0; j < b.integer.size(); ++j) {
    solver.setColName(static_cast<int>(j), "x" + std::to_string(j));  // for the MIP start
    if (b.integer[j]) solver.setInteger(static_cast<int>(j));
  }

  CbcModel model(solver);  // clones the solver
  model.setLogLevel(0);
  model.messageHandler()->setLogLevel(0);
  model.solver()->messageHandler()->setLogLevel(0);
  model.solver()->setHintParam(OsiDoReducePrint, true, OsiHintTry);
  // CBC's standard driver: preprocessing, cuts and heuristics as the cbc
  // executable runs them, silenced, single-threaded, fixed seeds.
  if (!mip_start.empty()) model.setMIPStart(mip_start);
  // CBC's driver reads its arguments through process-wide state
  // (CbcOrClpRead_mode and friends in CbcSolver.cpp), so two jobs solving at
  // the same time in one process (two threads on one registry, Python with
  // the GIL released) gave each other's problems wrong answers. One solve at
  // a time; a run's own components are solved one after another anyway.
  static std::mutex cbc_driver;
  const std::lock_guard<std::mutex> lock(cbc_driver);
  CbcSolverUsefulData data;
  CbcMain0(model, data);
  const std::string seed = std::to_string(options.random_seed);
  const std::string seconds = std::to_string(options.max_seconds);
  std::vector<const char*> argv = {"cooperage",
                                   "-log",
                                   "0",
                                   "-slog",
                                   "0",
                                   "-threads",
                                   "0",
                                   "-randomSeed",
                                   seed.c_str(),
                                   "-randomCbcSeed",
                                   seed.c_str(),
                                   "-seconds",
                                   seconds.c_str(),
                                   "-ratioGap",
                                   "0.02",
                                   "-allowableGap",
                                   "1e-9",
                                   "-increment",
                                   "1e-7"};
  if (!mip_start.empty()) {
    // From a start (the selector's trial solves start from the answer
    // before), "-passCuts -20" (CBC: at most 20 rounds of cuts at the root,
    // fewer once a round gains little): the time went to the later rounds
    // (gmsh_part --dim 2 at D/40, its solves from a start: 1.26 -> 0.47 s
    // of CBC) and the real-CAD meshes stayed as good (bench/RESULTS.md,
    // session 28). A fixed 5 was as fast on most files but 3x slower on one
    // (CrankArm at D/80). The search for any feasible point keeps CBC's
    // default: limited, gmsh_Zylkopf's found none within its time.
    argv.push_back("-passCuts");
    argv.push_back("-20");
  }
  argv.push_back("-solve");
  argv.push_back("-quit");
  const auto started = std::chrono::steady_clock::now();
  CbcMain1(static_cast<int>(argv.size()), argv.data(), model, nullptr, data);
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  IlpResult result;
  if (model.solver()->isProvenPrimalInfeasible()) {
    result.status = IlpStatus::Infeasible;
    return result;
  }
  // (CbcMain1 "-solve" has run the branch and bound)
  const double* best = model.bestSolution();
  if (!best) {
    // CbcMain1 reports infeasibility found in preprocessing as "stopped on
    // time" (status 1, secondary 4); its limit is in CPU seconds, so a search
    // that ended before max_seconds of wall time was not stopped by it.
    const bool completed =
        model.isProvenInfeasible() || model.status() == 0 || elapsed < options.max_seconds;
    result.status = completed ? IlpStatus::Infeasible : IlpStatus::NoSolution;
    return result;
  }
  result.status = model.isProvenOptimal() ? IlpStatus::Optimal : IlpStatus::Feasible;
  result.x.reserve(columns.size());
  for (size_t j = 0; j < columns.size(); ++j)
    result.x.push_back(static_cast<int>(std::lround(best[j])));
  return result;
}

}  // namespace cooperage::intervals::detail
