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

/// Components with fewer columns are solved to a proven optimum; larger ones
/// stop within CBC's ratio gap (solve.h). A 10-column component stopped
/// within the gap at a 1.9 % dearer answer than the optimum, whose mesh was
/// worse (a lug over a cone: minimum scaled Jacobian 0.047 against 0.071);
/// proving the optimum of a 98-column one (occt_CrankArm --dim 2) took 2.2 s
/// instead of 0.1 (bench/RESULTS.md, session 50).
constexpr size_t kProvenColumns = 50;

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
  // The piecewise-linear cost by increments from the breakpoint p nearest
  // the goal: x = p + sum up_k - sum down_k, each increment bounded by its
  // segment and costing the secant's slope (negated going down). The cost is
  // convex, so a cheaper increment always fills first and at integer x the
  // cost is the secants' value there (up to the constant h(p), left out).
  // One row per cost instead of one per secant (~15): CBC's LPs and cuts
  // work on a tenth of the rows (bench/RESULTS.md, session 50).
  for (size_t j = 0; j < columns.size(); ++j) {
    const Column& c = columns[j];
    if (c.hi && *c.hi == c.lo) continue;  // a constant costs nothing to optimise
    for (const Cost& cost : c.costs) {
      const std::vector<int> points = cost_breakpoints(cost.target, c.lo, c.hi);
      if (points.size() < 2) continue;
      const auto lines = cost_lines(cost.target, points);
      size_t mid = 0;
      for (size_t k = 1; k < points.size(); ++k)
        if (std::abs(points[k] - cost.target) < std::abs(points[mid] - cost.target)) mid = k;
      const double weight = options.objective_scale * cost.weight;
      std::vector<std::pair<int, double>> terms{{static_cast<int>(j), 1.0}};
      for (size_t k = 0; k < lines.size(); ++k) {
        const bool up = k >= mid;
        double width = points[k + 1] - points[k];
        if (up && k + 1 == lines.size())  // the last secant, extended
          width = c.hi ? static_cast<double>(*c.hi - points[k]) : inf;
        const double slope = lines[k].first;
        terms.emplace_back(b.add_column(0.0, width, up ? weight * slope : -weight * slope, false),
                           up ? -1.0 : 1.0);
      }
      b.add_row(std::move(terms), points[mid], points[mid]);
    }
  }

  b.p.mip_start = std::move(mip_start);
  b.p.random_seed = options.random_seed;
  b.p.max_seconds = options.max_seconds;
  if (columns.size() < kProvenColumns) b.p.ratio_gap = 0.0;
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
