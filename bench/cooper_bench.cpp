// cooper one-to-one sweeps: the sweep step alone (layer nodes + elements +
// inversion check, on a synthetic barrel) and end to end (a STEP file in, the
// mesh in memory), at ~10k, ~100k and ~1M hexes, with peak memory.
#include "bench_models.h"
#include "peak_memory.h"

#include "framework/geometry/occ/workbench.h"
#include "framework/pipeline/mesher.h"
#include "schemes/cooper/sweep_barrel.h"
#include "selector/select_schemes.h"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <filesystem>
#include <unistd.h>

namespace {

using namespace cooperage;
using geom::Vec3;

// An n x n quad cap on the unit square swept straight up through n layers
// with a slight taper (so the least-squares maps are not the identity).
cooper::SweepInput grid_barrel(int n) {
  cooper::SweepInput in;
  const int side = n + 1;
  std::vector<int> local(static_cast<size_t>(side * side), -1);
  auto at = [&](int i, int j) -> int& { return local[static_cast<size_t>(j * side + i)]; };
  // Boundary ring first (rib order), counter-clockwise, then the interior.
  std::vector<std::pair<int, int>> ring;
  for (int i = 0; i < n; ++i) ring.push_back({i, 0});
  for (int j = 0; j < n; ++j) ring.push_back({n, j});
  for (int i = n; i > 0; --i) ring.push_back({i, n});
  for (int j = n; j > 0; --j) ring.push_back({0, j});
  for (const auto& [i, j] : ring) {
    at(i, j) = static_cast<int>(in.source.size());
    in.source.push_back(Vec3(i / double(n), j / double(n), 0));
  }
  in.boundary = static_cast<int>(ring.size());
  in.loop_starts = {0};
  for (int j = 1; j < n; ++j) {
    for (int i = 1; i < n; ++i) {
      at(i, j) = static_cast<int>(in.source.size());
      in.source.push_back(Vec3(i / double(n), j / double(n), 0));
    }
  }
  in.cap_nodes = static_cast<int>(in.source.size());
  in.layers = n;
  for (int r = 0; r < in.boundary; ++r) {
    for (int k = 0; k <= n; ++k) {
      const double z = k / double(n), shrink = 1.0 - 0.2 * z;
      const Vec3& p = in.source[static_cast<size_t>(r)];
      in.ribs.push_back(Vec3(0.5 + (p.x() - 0.5) * shrink, 0.5 + (p.y() - 0.5) * shrink, z));
    }
  }
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i)
      in.quads.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
  }
  return in;
}

void BM_SweepStep(benchmark::State& state) {
  const cooper::SweepInput in = grid_barrel(static_cast<int>(state.range(0)));
  size_t hexes = 0;
  double min_sj = 0;
  for (auto _ : state) {
    const cooper::SweepResult r = cooper::sweep_barrel(in);
    if (!r.ok) state.SkipWithError(r.why.c_str());
    hexes = r.hexes.size();
    min_sj = r.min_scaled_jacobian;
  }
  state.counters["hexes"] = static_cast<double>(hexes);
  state.counters["hexes_per_s"] =
      benchmark::Counter(static_cast<double>(hexes), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["min_SJ"] = min_sj;
  state.counters["peak_MB"] = static_cast<double>(bench::peak_memory_bytes()) / 1e6;
}
BENCHMARK(BM_SweepStep)->Arg(22)->Arg(46)->Arg(100)->Unit(benchmark::kMillisecond);

// A 10 x 6 x 1 plate with three square holes written as STEP, read back and
// swept by cooper at sizes 1/n giving 57 n^3 hexes: ~12k, ~98k and ~1M.
void BM_SweepEndToEnd(benchmark::State& state) {
  const std::string step = (std::filesystem::temp_directory_path() /
                            ("cooperage-sweep-" + std::to_string(::getpid()) + ".step"))
                               .string();
  {
    occ::Workbench bench;
    std::vector<std::vector<Vec3>> holes;
    for (double x : {2.0, 5.0, 8.0}) {
      holes.push_back({{x - 0.5, 2.5, 0}, {x - 0.5, 3.5, 0}, {x + 0.5, 3.5, 0}, {x + 0.5, 2.5, 0}});
    }
    bench.prism("plate", {{0, 0, 0}, {10, 0, 0}, {10, 6, 0}, {0, 6, 0}}, holes, {0, 0, 1});
    bench.write(step);
  }
  io::MeshSettings settings;
  settings.size = 1.0 / static_cast<double>(state.range(0));
  const pipeline::MeshOptions options = selector::mesh_options(3, 1);
  size_t hexes = 0;
  for (auto _ : state) {
    const geom::Model model = occ::load_model(step);
    const auto r = pipeline::mesh_model(model, settings, bench::builtin_registry(), options);
    hexes = r.mesh.hex_count();
  }
  std::remove(step.c_str());
  state.counters["hexes"] = static_cast<double>(hexes);
  state.counters["hexes_per_s"] =
      benchmark::Counter(static_cast<double>(hexes), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["peak_MB"] = static_cast<double>(bench::peak_memory_bytes()) / 1e6;
}
BENCHMARK(BM_SweepEndToEnd)->Arg(6)->Arg(12)->Arg(26)->Unit(benchmark::kMillisecond);

}  // namespace
