// Entry point of the benchmark suite; silences the CAD kernel once.
#include "framework/geometry/occ/workbench.h"

#include <benchmark/benchmark.h>

int main(int argc, char** argv) {
  cooperage::occ::silence_kernel_output();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
