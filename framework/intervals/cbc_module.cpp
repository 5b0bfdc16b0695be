// The CBC module (libcooperage_cbc.so): one mixed-integer program solved by
// CBC's standard driver, loaded by ilp.cpp on the first solve instead of at
// start-up (cbc_problem.h says why). A C interface, versioned by
// cooperage_cbc_abi(); CBC's exceptions propagate to the caller.
#include "framework/intervals/cbc_problem.h"

#include <algorithm>
#include <chrono>
#include <mutex>
#include <string>

#include <coin/CbcModel.hpp>
#include <coin/CbcSolver.hpp>
#include <coin/CoinPackedMatrix.hpp>
#include <coin/OsiClpSolverInterface.hpp>

namespace {

using cooperage::intervals::detail::CbcAnswer;
using cooperage::intervals::detail::CbcProblem;
using cooperage::intervals::detail::CbcStatus;

void solve(const CbcProblem& p, CbcAnswer& answer) {
  CoinPackedMatrix matrix(false, 0, 0);  // row-ordered
  matrix.setDimensions(0, static_cast<int>(p.col_lo.size()));
  // Room for every row first: appendRow grows the storage by exactly one row
  // otherwise, copying the whole matrix each time (quadratic; a tenth of
  // gmsh_1385_Laufrad's --dim 2 run).
  size_t entries = 0;
  for (const auto& terms : p.row_terms) entries += terms.size();
  matrix.reserve(static_cast<int>(p.row_terms.size()), static_cast<CoinBigIndex>(entries));
  for (const auto& terms : p.row_terms) {
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
  solver.getModelPtr()->setRandomSeed(p.random_seed);
  solver.loadProblem(matrix, p.col_lo.data(), p.col_hi.data(), p.obj.data(), p.row_lo.data(),
                     p.row_hi.data());
  for (size_t j = 0; j < p.integer.size(); ++j) {
    solver.setColName(static_cast<int>(j), "x" + std::to_string(j));  // for the MIP start
    if (p.integer[j]) solver.setInteger(static_cast<int>(j));
  }
  // The rows named too: with named columns, Clp's presolve reads the row
  // names and crashed on an empty list (coin-or/Cbc issue 515; it did on
  // gmsh_1385_Laufrad's program once its costs were increments).
  for (size_t i = 0; i < p.row_lo.size(); ++i)
    solver.setRowName(static_cast<int>(i), "r" + std::to_string(i));

  CbcModel model(solver);  // clones the solver
  model.setLogLevel(0);
  model.messageHandler()->setLogLevel(0);
  model.solver()->messageHandler()->setLogLevel(0);
  model.solver()->setHintParam(OsiDoReducePrint, true, OsiHintTry);
  // CBC's standard driver: preprocessing, cuts and heuristics as the cbc
  // executable runs them, silenced, single-threaded, fixed seeds.
  if (!p.mip_start.empty()) model.setMIPStart(p.mip_start);
  // CBC's driver reads its arguments through process-wide state
  // (CbcOrClpRead_mode and friends in CbcSolver.cpp), so two jobs solving at
  // the same time in one process (two threads on one registry, Python with
  // the GIL released) gave each other's problems wrong answers. One solve at
  // a time; a run's own components are solved one after another anyway.
  static std::mutex cbc_driver;
  const std::lock_guard<std::mutex> lock(cbc_driver);
  CbcSolverUsefulData data;
  CbcMain0(model, data);
  const std::string seed = std::to_string(p.random_seed);
  const std::string seconds = std::to_string(p.max_seconds);
  const std::string ratio_gap = std::to_string(p.ratio_gap);
  // No probing cuts: on the cost increments probing took a third of
  // gmsh_1385_Laufrad's --dim 2 run and found little (bench/RESULTS.md,
  // session 50).
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
                                   ratio_gap.c_str(),
                                   "-allowableGap",
                                   "1e-9",
                                   "-increment",
                                   "1e-7",
                                   "-probingCuts",
                                   "off"};
  if (!p.mip_start.empty()) {
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
  if (model.solver()->isProvenPrimalInfeasible()) {
    answer.status = CbcStatus::Infeasible;
    return;
  }
  // (CbcMain1 "-solve" has run the branch and bound)
  const double* best = model.bestSolution();
  if (!best) {
    // CbcMain1 reports infeasibility found in preprocessing as "stopped on
    // time" (status 1, secondary 4); its limit is in CPU seconds, so a search
    // that ended before max_seconds of wall time was not stopped by it.
    const bool completed =
        model.isProvenInfeasible() || model.status() == 0 || elapsed < p.max_seconds;
    answer.status = completed ? CbcStatus::Infeasible : CbcStatus::NoSolution;
    return;
  }
  answer.status = model.isProvenOptimal() ? CbcStatus::Optimal : CbcStatus::Feasible;
  const size_t columns = std::min(p.col_lo.size(), static_cast<size_t>(model.getNumCols()));
  answer.x.assign(best, best + columns);
}

}  // namespace

extern "C" {

__attribute__((visibility("default"))) int cooperage_cbc_abi() {
  return cooperage::intervals::detail::kCbcModuleAbi;
}

__attribute__((visibility("default"))) void cooperage_cbc_solve(const CbcProblem* problem,
                                                                CbcAnswer* answer) {
  solve(*problem, *answer);
}

}  // extern "C"
