// The whole pipeline (plan, intervals, curves, surfaces, volumes, inversion
// check) on a brick, by the volume map and by the cooper sweep: hexes per
// second end to end (model already built), quality, peak memory.
#include "bench_models.h"
#include "peak_memory.h"

#include "framework/geometry/occ/workbench.h"
#include "framework/pipeline/mesher.h"
#include "selector/select_schemes.h"

#include <benchmark/benchmark.h>

namespace {

using namespace cooperage;

// A 1 x 1 x 1 brick at size 1/n (n^3 hexes) meshed by `scheme` (pinned):
// the volume map and the cooper sweep on the same piece.
void run_brick(benchmark::State& state, const char* scheme_name) {
  occ::Workbench bench;
  bench.brick("b", {0, 0, 0}, {1, 1, 1});
  const geom::Model model = bench.build_model();
  io::MeshSettings settings;
  settings.size = 1.0 / static_cast<double>(state.range(0));
  io::VolumeSetting pin;
  pin.id = 1;
  pin.scheme = scheme_name;
  settings.volumes.push_back(pin);
  const pipeline::MeshOptions options = selector::mesh_options(3, 1);
  size_t hexes = 0;
  double min_sj = 0, median_sj = 0;
  for (auto _ : state) {
    const auto r = pipeline::mesh_model(model, settings, bench::builtin_registry(), options);
    hexes = r.mesh.hex_count();
    const auto* sj = r.quality.blocks.front().find("scaled_jacobian");
    min_sj = sj->min;
    median_sj = sj->median;
  }
  state.counters["hexes"] = static_cast<double>(hexes);
  state.counters["hexes_per_s"] =
      benchmark::Counter(static_cast<double>(hexes), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["min_SJ"] = min_sj;
  state.counters["median_SJ"] = median_sj;
  state.counters["peak_MB"] = static_cast<double>(bench::peak_memory_bytes()) / 1e6;
}

void BM_VolumeMapBrick(benchmark::State& state) { run_brick(state, "map"); }
BENCHMARK(BM_VolumeMapBrick)->Arg(20)->Arg(46)->Arg(100)->Unit(benchmark::kMillisecond);

void BM_CooperBrick(benchmark::State& state) { run_brick(state, "cooper"); }
BENCHMARK(BM_CooperBrick)->Arg(20)->Arg(46)->Arg(100)->Unit(benchmark::kMillisecond);

}  // namespace

// Campaign case 3468 (docs/reliability.md): a 1 x L x 1 brick with a unit
// brick against one end, size 0.25, so the long brick is swept by cooper
// with 4 x 4L-quad caps and 4L x 4 sides. Submap's lattice walk and the
// sweep's residual interpolation were quadratic in L (L = 10,000: 84 s);
// hexes per second must not fall as L grows.
void BM_LongBrickWithNeighbour(benchmark::State& state) {
  const double length = static_cast<double>(state.range(0));
  occ::Workbench bench;
  bench.brick("long", {0, 0, 0}, {1, length, 1});
  bench.brick("short", {1, 0, 0}, {2, 1, 1});  // build_model imprints and merges
  const geom::Model model = bench.build_model();
  io::MeshSettings settings;
  settings.size = 0.25;
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
BENCHMARK(BM_LongBrickWithNeighbour)->Arg(500)->Arg(2000)->Arg(8000)->Unit(benchmark::kMillisecond);
