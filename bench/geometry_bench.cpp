// Geometry layer throughput: building models from primitives and booleans
// (imprint and merge included), and surface projection, which every scheme
// calls once per node.
#include "peak_memory.h"

#include "framework/geometry/occ/workbench.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <string>

namespace {

using cooperage::geom::Vec3;

// A plate 10 x 6 x 1 with n x 1 cylindrical through holes.
cooperage::geom::Model plate_with_holes(int n) {
  cooperage::occ::Workbench bench;
  bench.brick("plate", {0, 0, 0}, {10, 6, 1});
  std::vector<std::string> inputs{"plate"};
  for (int i = 0; i < n; ++i) {
    const std::string name = "hole" + std::to_string(i);
    bench.cylinder(name, {10.0 * (i + 0.5) / n, 3, -1}, {0, 0, 1}, 0.3 * 3 / std::max(n, 3), 3);
    inputs.push_back(name);
  }
  bench.cut("part", inputs);
  return bench.build_model();
}

void BM_BuildPlateWithHoles(benchmark::State& state) {
  const int holes = static_cast<int>(state.range(0));
  size_t surfaces = 0;
  for (auto _ : state) {
    const auto model = plate_with_holes(holes);
    surfaces = model.surfaces().size();
    benchmark::DoNotOptimize(surfaces);
  }
  state.counters["surfaces"] = static_cast<double>(surfaces);
  state.counters["surfaces_per_s"] = benchmark::Counter(
      static_cast<double>(surfaces), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["peak_MB"] = static_cast<double>(cooperage::bench::peak_memory_bytes()) / 1e6;
}
BENCHMARK(BM_BuildPlateWithHoles)->Arg(3)->Arg(12)->Arg(48)->Unit(benchmark::kMillisecond);

void BM_ImprintMergeBrickStack(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  for (auto _ : state) {
    cooperage::occ::Workbench bench;
    for (int i = 0; i < n; ++i) bench.brick("b" + std::to_string(i), {0, 0, 1.0 * i}, {1, 1, 1});
    const auto model = bench.build_model();
    benchmark::DoNotOptimize(model.surfaces().size());
  }
  state.counters["volumes_per_s"] =
      benchmark::Counter(static_cast<double>(n), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["peak_MB"] = static_cast<double>(cooperage::bench::peak_memory_bytes()) / 1e6;
}
BENCHMARK(BM_ImprintMergeBrickStack)->Arg(2)->Arg(8)->Arg(32)->Unit(benchmark::kMillisecond);

void BM_ProjectOnCylinder(benchmark::State& state) {
  cooperage::occ::Workbench bench;
  bench.cylinder("c", {0, 0, 0}, {0, 0, 1}, 2.0, 3.0);
  const auto model = bench.build_model();
  const cooperage::geom::Surface* side = nullptr;
  for (const auto& s : model.surfaces()) {
    if (s.geometry->type() == cooperage::geom::SurfaceType::Cylinder) side = &s;
  }
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> angle(0, 2 * M_PI), height(0.1, 2.9), radius(1.5, 2.5);
  std::vector<Vec3> points(1024);
  for (auto& p : points) {
    const double a = angle(rng), r = radius(rng);
    p = Vec3(r * std::cos(a), r * std::sin(a), height(rng));
  }
  for (auto _ : state) {
    for (const auto& p : points) benchmark::DoNotOptimize(side->geometry->project(p));
  }
  state.counters["projections_per_s"] = benchmark::Counter(
      static_cast<double>(points.size()), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_ProjectOnCylinder);

}  // namespace
