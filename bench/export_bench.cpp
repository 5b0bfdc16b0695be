// Export alone: one mesh of the plate with three holes (cooper, ~0.1 / 1 M
// hexes, meshed once per process) written in every format and encoding,
// Exodus as classic netCDF and as netCDF-4 (HDF5). Time is the write call
// only; one thread.
//   build/bin/cooperage_bench --benchmark_filter='BM_Export'
#include "bench_models.h"

#include "framework/geometry/occ/workbench.h"
#include "framework/io/export/write_mesh.h"
#include "framework/pipeline/mesher.h"
#include "selector/select_schemes.h"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <unistd.h>

namespace {

using namespace cooperage;

struct Meshed {
  geom::Model model;
  mesh::MeshDB mesh;
};

// The plate of bench/peers/models/plate_three_holes.xml at `size`.
const Meshed& plate(double size) {
  static std::map<double, std::unique_ptr<Meshed>> cache;
  auto& slot = cache[size];
  if (!slot) {
    occ::Workbench wb;
    wb.brick("plate", {0, 0, 0}, {10, 6, 1});
    std::vector<std::string> inputs{"plate"};
    for (double x : {2.5, 5.0, 7.5}) {
      inputs.push_back("hole" + std::to_string(inputs.size()));
      wb.cylinder(inputs.back(), {x, 3, -0.5}, {0, 0, 1}, 0.8, 2);
    }
    wb.cut("part", inputs);
    geom::Model model = wb.build_model();
    io::MeshSettings settings;
    settings.size = size;
    auto r = pipeline::mesh_model(model, settings, bench::builtin_registry(),
                                  selector::mesh_options(3, 1));
    slot = std::make_unique<Meshed>(Meshed{std::move(model), std::move(r.mesh)});
  }
  return *slot;
}

// range(0): 0 = size 0.08 (~0.1 M hexes), 1 = 0.0375 (~1 M).
// range(1): 0 .exo classic, 1 .exo netCDF-4, 2 .vtu ascii, 3 .vtu binary,
//           4 .msh ascii, 5 .msh binary, 6 .inp.
void BM_Export(benchmark::State& state) {
  const Meshed& m = plate(state.range(0) == 0 ? 0.08 : 0.0375);
  static const char* const kExt[] = {".exo", ".exo", ".vtu", ".vtu", ".msh", ".msh", ".inp"};
  static const char* const kLabel[] = {"exo classic", "exo netCDF-4", "vtu ascii", "vtu binary",
                                       "msh ascii",   "msh binary",   "inp"};
  const int k = static_cast<int>(state.range(1));
  io::ExportOptions options;
  options.exodus_netcdf4 = k == 1;
  options.binary = k == 3 || k == 5;
  const std::string file = (std::filesystem::temp_directory_path() /
                            ("cooperage-export-" + std::to_string(::getpid()) + kExt[k]))
                               .string();
  for (auto _ : state) io::write_mesh(file, m.mesh, m.model, options);
  state.counters["MB"] = static_cast<double>(std::filesystem::file_size(file)) / 1e6;
  std::remove(file.c_str());
  const double hexes = static_cast<double>(m.mesh.hex_count());
  state.counters["hexes"] = hexes;
  state.counters["hexes_per_s"] =
      benchmark::Counter(hexes, benchmark::Counter::kIsIterationInvariantRate);
  state.SetLabel(kLabel[k]);
}
BENCHMARK(BM_Export)
    ->ArgsProduct({{0, 1}, {0, 1, 2, 3, 4, 5, 6}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
