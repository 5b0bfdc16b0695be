// The paper's Table 1 for Cooperage: cooper on the many-to-one examples at
// three sizes each (the journal's size, half and a quarter): elements and
// elements per second, model built from the journal beforehand, one thread.
//   build/bin/cooperage_bench --benchmark_filter='CooperTable1'
#include "bench_models.h"
#include "peak_memory.h"

#include "framework/geometry/occ/workbench.h"
#include "framework/io/journal_reader.h"
#include "framework/pipeline/build_geometry.h"
#include "framework/pipeline/mesher.h"
#include "schemes/builtin_schemes.h"
#include "selector/select_schemes.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <optional>
#include <string>

namespace {

using namespace cooperage;

const char* const kModels[] = {"cylinder_boss", "block_two_bosses_hole", "block_appendages",
                               "stepped_block", "plate_three_holes",
                               // cooper III (issue 15): barrels ended by rib propagation
                               "blind_hole", "flanged_hub"};

void BM_CooperTable1(benchmark::State& state) {
  const std::string name = kModels[state.range(0)];
  const io::Job job =
      io::read_journal(std::string(COOPERAGE_SOURCE_DIR) + "/examples/" + name + ".xml");
  const geom::Model model = pipeline::build_geometry(job);
  io::MeshSettings settings = *job.mesh;
  const double size = *settings.size / static_cast<double>(state.range(1));
  settings.size = size;
  const pipeline::MeshOptions options = selector::mesh_options(3, 1);
  size_t hexes = 0;
  for (auto _ : state) {
    const auto r = pipeline::mesh_model(model, settings, bench::builtin_registry(), options);
    hexes = r.mesh.hex_count();
  }
  state.SetLabel(name + " size " + std::to_string(size));
  state.counters["elements"] = static_cast<double>(hexes);
  state.counters["elements_per_s"] =
      benchmark::Counter(static_cast<double>(hexes), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["peak_MB"] = static_cast<double>(bench::peak_memory_bytes()) / 1e6;
}
BENCHMARK(BM_CooperTable1)
    ->ArgsProduct({{0, 1, 2, 3, 4, 5, 6}, {1, 2, 4}})
    ->Unit(benchmark::kMillisecond);

}  // namespace

namespace {

// Many-to-one on the cylinder with a boss against the same solid cut by hand
// into three one-to-one pieces (a core under the boss, the boss, the tube
// around the core; imprinted and merged, so conformal): what the cooper
// scheme saves a user, and what it costs.
void run_boss(benchmark::State& state, bool cut) {
  occ::Workbench bench;
  if (cut) {
    bench.cylinder("core", {0, 0, 0}, {0, 0, 1}, 1.0, 3.0);
    bench.cylinder("boss", {0, 0, 3}, {0, 0, 1}, 1.0, 1.5);
    bench.cylinder("outer", {0, 0, 0}, {0, 0, 1}, 2.0, 3.0);
    bench.cylinder("hole", {0, 0, -1}, {0, 0, 1}, 1.0, 5.0);
    bench.cut("tube", {"outer", "hole"});
  } else {
    bench.cylinder("body", {0, 0, 0}, {0, 0, 1}, 2.0, 3.0);
    bench.cylinder("boss", {0, 0, 3}, {0, 0, 1}, 1.0, 1.5);
    bench.fuse("part", {"body", "boss"});
  }
  const geom::Model model = bench.build_model();
  io::MeshSettings settings;
  settings.size = 0.25 / static_cast<double>(state.range(0));
  const pipeline::MeshOptions options = selector::mesh_options(3, 1);
  size_t hexes = 0;
  double min_sj = 0, median_sj = 0;
  for (auto _ : state) {
    const auto r = pipeline::mesh_model(model, settings, bench::builtin_registry(), options);
    hexes = r.mesh.hex_count();
    min_sj = 1;
    median_sj = 0;
    for (const auto& b : r.quality.blocks) {
      const auto* sj = b.find("scaled_jacobian");
      min_sj = std::min(min_sj, sj->min);
      median_sj = std::max(median_sj, sj->median);  // one block per volume; report the larger
    }
  }
  state.counters["volumes"] = static_cast<double>(model.volumes().size());
  state.counters["elements"] = static_cast<double>(hexes);
  state.counters["elements_per_s"] =
      benchmark::Counter(static_cast<double>(hexes), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["min_SJ"] = min_sj;
  state.counters["median_SJ"] = median_sj;
}

void BM_BossManyToOne(benchmark::State& state) { run_boss(state, false); }
BENCHMARK(BM_BossManyToOne)->Arg(1)->Arg(2)->Arg(4)->Unit(benchmark::kMillisecond);

void BM_BossCutIntoOneToOne(benchmark::State& state) { run_boss(state, true); }
BENCHMARK(BM_BossCutIntoOneToOne)->Arg(1)->Arg(2)->Arg(4)->Unit(benchmark::kMillisecond);

}  // namespace

namespace {

// Elements per second of a journal at its size / range(0), with volume 1's
// element kind set when `kind` is given; counters for hexes and wedges.
void run_elements(benchmark::State& state, const char* example,
                  std::optional<io::ElementKind> kind = std::nullopt) {
  const io::Job job = io::read_journal(std::string(COOPERAGE_SOURCE_DIR) + "/examples/" + example);
  const geom::Model model = pipeline::build_geometry(job);
  io::MeshSettings settings = *job.mesh;
  settings.size = *settings.size / static_cast<double>(state.range(0));
  if (kind) {
    io::VolumeSetting v;
    v.id = 1;
    v.elements = *kind;
    settings.volumes = {v};
  }
  // The element kind reaches cooper through the job's settings (scheme::Settings).
  scheme::Registry registry;
  register_builtin_schemes(registry);
  const pipeline::MeshOptions options = selector::mesh_options(3, 1);
  size_t wedges = 0, hexes = 0;
  double min_sj = 1;
  for (auto _ : state) {
    const auto r = pipeline::mesh_model(model, settings, registry, options);
    wedges = r.mesh.wedge_count();
    hexes = r.mesh.hex_count();
    min_sj = 1;
    for (const auto& block : r.quality.blocks)
      min_sj = std::min(min_sj, block.find("scaled_jacobian")->min);
  }
  state.counters["wedges"] = static_cast<double>(wedges);
  state.counters["hexes"] = static_cast<double>(hexes);
  state.counters["elements_per_s"] = benchmark::Counter(
      static_cast<double>(wedges + hexes), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["min_SJ"] = min_sj;
}

// Wedges per second: the plate with three round holes in wedge mode (tri
// source cap, cooper one-to-one) at sizes 0.25, 0.125, 0.0625.
void BM_WedgeSweep(benchmark::State& state) { run_elements(state, "plate_wedges.xml"); }
BENCHMARK(BM_WedgeSweep)->Arg(1)->Arg(2)->Arg(4)->Unit(benchmark::kMillisecond);

// Many-to-one in wedge mode: the cylinder with a boss (two tri cap stacks).
void BM_WedgeManyToOne(benchmark::State& state) {
  run_elements(state, "cylinder_boss.xml", io::ElementKind::Wedge);
}
BENCHMARK(BM_WedgeManyToOne)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

// Mixed mode: the 20-degree blade (quad-dominant cap, hexes and wedges).
void BM_MixedSweep(benchmark::State& state) { run_elements(state, "sharp_corner_mixed.xml"); }
BENCHMARK(BM_MixedSweep)->Arg(1)->Arg(2)->Arg(4)->Unit(benchmark::kMillisecond);

}  // namespace
