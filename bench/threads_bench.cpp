// One volume on one and two threads (issue 20): the plate with three round
// holes of bench/e2e (10 x 6 x 1, holes r 0.8), built in memory, meshed by
// cooper through mesh_model (plan, surfaces, the sweep, quality, the volume
// check) and written as .exo beside the checks, at ~0.1 M and ~1 M hexes. Arguments: ten
// times the size's inverse (10 / size), the thread count. hexes_per_s is what the
// whole of that took per hex, by wall time.
#include "bench_models.h"
#include "peak_memory.h"

#include "framework/geometry/occ/workbench.h"
#include "framework/io/export/write_mesh.h"
#include "framework/pipeline/mesher.h"
#include "selector/select_schemes.h"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <filesystem>
#include <unistd.h>

namespace {

using namespace cooperage;

geom::Model plate_with_round_holes() {
  occ::Workbench wb;
  wb.brick("b", {0, 0, 0}, {10, 6, 1});
  wb.cylinder("h1", {2.5, 3, -0.5}, {0, 0, 1}, 0.8, 2);
  wb.cylinder("h2", {5.0, 3, -0.5}, {0, 0, 1}, 0.8, 2);
  wb.cylinder("h3", {7.5, 3, -0.5}, {0, 0, 1}, 0.8, 2);
  wb.cut("plate", {"b", "h1", "h2", "h3"});
  return wb.build_model();
}

void BM_PlateThreads(benchmark::State& state) {
  const geom::Model model = plate_with_round_holes();
  io::MeshSettings settings;
  settings.size = 10.0 / static_cast<double>(state.range(0));
  pipeline::MeshOptions options = selector::mesh_options(3, static_cast<int>(state.range(1)));
  const std::string exo = (std::filesystem::temp_directory_path() /
                           ("cooperage-threads-" + std::to_string(::getpid()) + ".exo"))
                              .string();
  // As `cooperage mesh` does: the file is written beside the quality and
  // volume checks.
  options.beside_checks = [&](const mesh::MeshDB& db) { io::write_mesh(exo, db, model); };
  size_t hexes = 0;
  for (auto _ : state) {
    const auto r = pipeline::mesh_model(model, settings, bench::builtin_registry(), options);
    hexes = r.mesh.hex_count();
  }
  std::remove(exo.c_str());
  state.counters["hexes"] = static_cast<double>(hexes);
  state.counters["hexes_per_s"] =
      benchmark::Counter(static_cast<double>(hexes), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["peak_MB"] = static_cast<double>(bench::peak_memory_bytes()) / 1e6;
}
// Sizes 0.0813 and 0.0377: the e2e run's 0.1 M and 1 M hexes.
BENCHMARK(BM_PlateThreads)
    ->Args({123, 1})
    ->Args({123, 2})
    ->Args({265, 1})
    ->Args({265, 2})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace
