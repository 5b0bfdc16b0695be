// The CBC module itself (libcooperage_cbc.so, cbc_module.cpp), given a
// program directly rather than through solve().
#include "framework/intervals/cbc_problem.h"

#include <gtest/gtest.h>

#include <dlfcn.h>

#include <cmath>
#include <limits>
#include <string>

#include "framework/core/lazy_module.h"

namespace cooperage::intervals::detail {
namespace {

CbcSolveFn module_solve() {
  void* handle = open_module("libcooperage_cbc.so", "cooperage_cbc_abi", kCbcModuleAbi);
  return reinterpret_cast<CbcSolveFn>(dlsym(handle, "cooperage_cbc_solve"));
}

// The program of coin-or/Cbc issue 515 (10 columns, 7 rows, two integers,
// a MIP start): with named columns and unnamed rows, Clp's presolve read
// the missing row names and the process died (SIGSEGV, checked with the
// module before its rows were named). The answer must satisfy every row
// and bound.
TEST(CbcModule, AProgramWhosePresolveReadsRowNamesIsSolved) {
  const double inf = std::numeric_limits<double>::max();
  CbcProblem p;
  p.col_lo.assign(10, 0.0);
  p.col_hi = {inf, inf, inf, inf, 1, 1, 1, 1, 1, 1};
  p.obj = {0, 1, 0, 0, 1, 1.8, 2.2, 10, 0, 0};
  p.integer = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1};
  // Column-wise in the issue; here row by row.
  p.row_terms = {{{0, -1}, {1, -1}},
                 {{0, 1}, {2, -1}},
                 {{1, 1}, {3, -1}},
                 {{2, 1}, {3, 1}},
                 {{0, -1}, {4, 1}, {5, 3}, {6, 5}},
                 {{4, 1}, {5, 1}, {6, 1}, {7, 1}, {8, -1}},
                 {{8, 1}, {9, 1}}};
  p.row_lo = {-10, 0, 0, 5, 0, 0, 1};
  p.row_hi = {0, 0, 0, 5, 0, 0, 1};
  const double start[] = {5, 0, 5, 0, 0, 0, 1, 0, 1, 0};
  for (int j = 0; j < 10; ++j) p.mip_start.emplace_back("x" + std::to_string(j), start[j]);
  p.random_seed = 12345;
  CbcAnswer answer;
  module_solve()(&p, &answer);
  ASSERT_EQ(answer.status, CbcStatus::Optimal);
  ASSERT_EQ(answer.x.size(), 10u);
  const double tol = 1e-7;
  for (size_t j = 0; j < 10; ++j) {
    EXPECT_GE(answer.x[j], p.col_lo[j] - tol) << "column " << j;
    EXPECT_LE(answer.x[j], p.col_hi[j] + tol) << "column " << j;
  }
  for (size_t i = 0; i < p.row_terms.size(); ++i) {
    double sum = 0;
    for (auto [col, coeff] : p.row_terms[i]) sum += coeff * answer.x[static_cast<size_t>(col)];
    EXPECT_GE(sum, p.row_lo[i] - tol) << "row " << i;
    EXPECT_LE(sum, p.row_hi[i] + tol) << "row " << i;
  }
  for (int j : {8, 9}) EXPECT_NEAR(answer.x[static_cast<size_t>(j)], std::round(answer.x[j]), tol);
}

}  // namespace
}  // namespace cooperage::intervals::detail
