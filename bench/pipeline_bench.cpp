// The whole pipeline (plan, intervals, curves, surfaces, volumes, inversion
// check) on a brick meshed by the volume map: hexes per second end to end,
// model already built, and peak memory.
#include "bench_models.h"
#include "peak_memory.h"

#include "framework/geometry/occ/workbench.h"
#include "framework/pipeline/mesher.h"
#include "selector/select_schemes.h"

#include <benchmark/benchmark.h>

namespace {

using namespace cooperage;

// A 1 x 1 x 1 brick at size 1/n: n^3 hexes.
void BM_VolumeMapBrick(benchmark::State& state) {
  occ::Workbench bench;
  bench.brick("b", {0, 0, 0}, {1, 1, 1});
  const geom::Model model = bench.build_model();
  io::MeshSettings settings;
  settings.size = 1.0 / static_cast<double>(state.range(0));
  const pipeline::MeshOptions options = selector::mesh_options(3, 1);
  size_t hexes = 0;
  for (auto _ : state) {
    const auto r = pipeline::mesh_model(model, settings, bench::builtin_registry(), options);
    hexes = r.mesh.hex_count();
  }
  state.counters["hexes"] = static_cast<double>(hexes);
  state.counters["hexes_per_s"] =
      benchmark::Counter(static_cast<double>(hexes), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["peak_MB"] = static_cast<double>(bench::peak_memory_bytes()) / 1e6;
}
BENCHMARK(BM_VolumeMapBrick)->Arg(20)->Arg(46)->Arg(100)->Unit(benchmark::kMillisecond);

}  // namespace
