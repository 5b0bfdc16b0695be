// The run's quality report of a 1 M-hex cooper mesh (issue 20): computed
// from the mesh (range 0) against taking the scaled Jacobians the sweep's
// inversion check already computed (range 1, pipeline::KnownScaledJacobians,
// as mesh_model does). The plate with three round holes of bench/e2e, meshed
// once per process. hexes_per_s: elements reported per second of wall time.
//   build/bin/cooperage_bench --benchmark_filter='BM_QualityReport'
#include "bench_models.h"

#include "framework/geometry/occ/workbench.h"
#include "framework/pipeline/mesher.h"
#include "framework/quality/evaluate.h"
#include "selector/select_schemes.h"

#include <benchmark/benchmark.h>

#include <memory>

namespace {

using namespace cooperage;

struct Meshed {
  geom::Model model;
  mesh::MeshDB mesh;
  pipeline::KnownScaledJacobians known;
};

const Meshed& plate() {
  static std::unique_ptr<Meshed> m;
  if (!m) {
    occ::Workbench wb;
    wb.brick("b", {0, 0, 0}, {10, 6, 1});
    wb.cylinder("h1", {2.5, 3, -0.5}, {0, 0, 1}, 0.8, 2);
    wb.cylinder("h2", {5.0, 3, -0.5}, {0, 0, 1}, 0.8, 2);
    wb.cylinder("h3", {7.5, 3, -0.5}, {0, 0, 1}, 0.8, 2);
    wb.cut("plate", {"b", "h1", "h2", "h3"});
    geom::Model model = wb.build_model();
    io::MeshSettings settings;
    settings.size = 0.0377;
    auto r = pipeline::mesh_model(model, settings, bench::builtin_registry(),
                                  selector::mesh_options(3, 0));
    m = std::make_unique<Meshed>(Meshed{std::move(model), std::move(r.mesh), {}});
    // What the sweep hands over: every hex's value on the final nodes.
    for (const auto& [id, v] : m->mesh.volumes()) {
      m->known.hexes[id] = quality::evaluate(quality::Metric::ScaledJacobian,
                                             quality::ElementType::Hex, m->mesh.coords(), v.hexes);
    }
  }
  return *m;
}

void BM_QualityReport(benchmark::State& state) {
  const Meshed& m = plate();
  const bool carried = state.range(0) == 1;
  for (auto _ : state) {
    auto report = pipeline::assess_quality(m.mesh, m.model, {}, carried ? &m.known : nullptr);
    benchmark::DoNotOptimize(report);
  }
  const double hexes = static_cast<double>(m.mesh.hex_count());
  state.counters["hexes"] = hexes;
  state.counters["hexes_per_s"] =
      benchmark::Counter(hexes, benchmark::Counter::kIsIterationInvariantRate);
  state.SetLabel(carried ? "carried" : "recomputed");
}
BENCHMARK(BM_QualityReport)->Arg(0)->Arg(1)->UseRealTime()->Unit(benchmark::kMillisecond);

}  // namespace
