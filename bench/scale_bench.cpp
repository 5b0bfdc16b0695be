// Scale: a one-to-one sweep (cooper pinned on a unit brick) of ~1, 3 and 10
// million hexes, end to end from the model to an Exodus file on disk:
// seconds, hexes per second and peak bytes per hex. Run each size in its own
// process so the peak memory belongs to that size:
//   build/bin/cooperage_bench --benchmark_filter='BM_SweepScale/216/'
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

void BM_SweepScale(benchmark::State& state) {
  occ::Workbench bench;
  bench.brick("b", {0, 0, 0}, {1, 1, 1});
  const geom::Model model = bench.build_model();
  io::MeshSettings settings;
  settings.size = 1.0 / static_cast<double>(state.range(0));
  io::VolumeSetting sweep;
  sweep.id = 1;
  sweep.scheme = "cooper";
  settings.volumes.push_back(sweep);
  const pipeline::MeshOptions options = selector::mesh_options(3, 1);
  const std::string file = (std::filesystem::temp_directory_path() /
                            ("cooperage-scale-" + std::to_string(::getpid()) + ".exo"))
                               .string();
  size_t hexes = 0;
  for (auto _ : state) {
    const auto r = pipeline::mesh_model(model, settings, bench::builtin_registry(), options);
    io::write_mesh(file, r.mesh, model);
    hexes = r.mesh.hex_count();
  }
  std::remove(file.c_str());
  state.counters["hexes"] = static_cast<double>(hexes);
  state.counters["hexes_per_s"] =
      benchmark::Counter(static_cast<double>(hexes), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["peak_bytes_per_hex"] =
      static_cast<double>(bench::peak_memory_bytes()) / static_cast<double>(hexes);
}
BENCHMARK(BM_SweepScale)->Arg(100)->Arg(144)->Arg(216)->Iterations(1)->Unit(benchmark::kSecond);

}  // namespace
