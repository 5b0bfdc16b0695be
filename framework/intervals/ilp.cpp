#include "framework/intervals/ilp.h"

#include <cmath>
#include <limits>
#include <mutex>
#include <string>

#include <dlfcn.h>

#include "framework/core/error.h"
#include "framework/core/lazy_module.h"
#include "framework/intervals/cbc_problem.h"
#include "framework/intervals/deviation.h"
#include "framework/intervals/separable_optimum.h"

namespace cooperage::intervals::detail {
namespace {

/// Column-wise sparse model under construction.
struct Builder {
  CbcProblem p;

  int add_column(double lo, double hi, double cost, bool is_integer) {
    p.col_lo.push_back(lo);
    p.col_hi.push_back(hi);
    p.obj.push_back(cost);
    p.integer.push_back(is_integer ? 1 : 0);
    return static_cast<int>(p.col_lo.size()) - 1;
  }
  void add_row(std::vector<std::pair<int, double>> terms, double lo, double hi) {
    p.row_terms.push_back(std::move(terms));
    p.row_lo.push_back(lo);
    p.row_hi.push_back(hi);
  }
};

CbcSolveFn cbc_solver() {
  static CbcSolveFn solve = nullptr;
  static std::once_flag once;
  std::call_once(once, [] {
    void* handle = open_module("libcooperage_cbc.so", "cooperage_cbc_abi", kCbcModuleAbi);
    solve = reinterpret_cast<CbcSolveFn>(dlsym(handle, "cooperage_cbc_solve"));
    if (solve == nullptr)
      throw MeshingError(ErrorCode::Internal, "libcooperage_cbc.so lacks its solve function");
  });
  return solve;
}

}  // namespace

void load_solver() { cbc_solver(); }

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
  if (std::optional<std::vector<int>> x = separable_optimum(columns, rows))
    return IlpResult{IlpStatus::Optimal, std::move(*x)};
  const double inf = std::numeric_limits<double>::max();  // CBC's infinity
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

  b.p.mip_start = std::move(mip_start);
  b.p.random_seed = options.random_seed;
  b.p.max_seconds = options.max_seconds;
  CbcAnswer answer;
  cbc_solver()(&b.p, &answer);
  IlpResult result;
  switch (answer.status) {
    case CbcStatus::Optimal: result.status = IlpStatus::Optimal; break;
    case CbcStatus::Feasible: result.status = IlpStatus::Feasible; break;
    case CbcStatus::Infeasible: result.status = IlpStatus::Infeasible; return result;
    case CbcStatus::NoSolution: result.status = IlpStatus::NoSolution; return result;
  }
  result.x.reserve(columns.size());
  for (size_t j = 0; j < columns.size(); ++j)
    result.x.push_back(static_cast<int>(std::lround(answer.x[j])));
  return result;
}

}  // namespace cooperage::intervals::detail
