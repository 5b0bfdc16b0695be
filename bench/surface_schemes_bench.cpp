// Surface schemes on the same faces: map vs submap vs pave on a rectangle,
// submap on a comb at three sizes and on a long strip. Reports quads per
// second (the scheme's mesh() alone; curves are meshed before timing) and
// peak memory.
#include "bench_models.h"
#include "peak_memory.h"

#include "framework/quality/quad_metrics.h"
#include "framework/quality/summary.h"

#include <benchmark/benchmark.h>

#include <vector>

namespace {

using namespace cooperage;

void run_surface_scheme(benchmark::State& state, const geom::Model& model, int surface,
                        const char* scheme_name, double size) {
  const scheme::SurfaceScheme* s = bench::builtin_registry().surface_scheme(scheme_name);
  const mesh::MeshDB db = bench::curves_for_surface(model, *s, surface, size);
  const scheme::SurfaceView view{model, surface, &db};
  size_t quads = 0;
  for (auto _ : state) {
    const scheme::EntityMesh m = s->mesh(view, {size});
    quads = m.quads.size();
    benchmark::DoNotOptimize(m.coords.data());
  }
  // Quality of the last mesh, against the surface normal.
  const scheme::EntityMesh m = s->mesh(view, {size});
  std::vector<double> sj;
  sj.reserve(m.quads.size());
  for (const auto& q : m.quads) {
    quality::QuadNodes p;
    geom::Vec3 c = geom::Vec3::Zero();
    for (int k = 0; k < 4; ++k) {
      p[static_cast<size_t>(k)] = m.coords[static_cast<size_t>(q[static_cast<size_t>(k)])];
      c += p[static_cast<size_t>(k)] / 4.0;
    }
    sj.push_back(
        quality::quad_scaled_jacobian(p, model.surface(surface).geometry->project(c).normal));
  }
  const auto summary = quality::summarize(quality::Metric::ScaledJacobian, sj);
  state.counters["min_SJ"] = summary.min;
  state.counters["median_SJ"] = summary.median;
  state.counters["quads"] = static_cast<double>(quads);
  state.counters["quads_per_s"] =
      benchmark::Counter(static_cast<double>(quads), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["peak_MB"] = static_cast<double>(bench::peak_memory_bytes()) / 1e6;
}

// Rectangle 10 x 10 at size 10/n: n^2 quads.
void BM_MapRectangle(benchmark::State& state) {
  static const geom::Model model = bench::rectangle_plate(10, 10);
  run_surface_scheme(state, model, bench::top_surface(model), "map",
                     10.0 / static_cast<double>(state.range(0)));
}
BENCHMARK(BM_MapRectangle)->Arg(100)->Arg(316)->Arg(1000)->Unit(benchmark::kMillisecond);

void BM_SubmapRectangle(benchmark::State& state) {
  static const geom::Model model = bench::rectangle_plate(10, 10);
  run_surface_scheme(state, model, bench::top_surface(model), "submap",
                     10.0 / static_cast<double>(state.range(0)));
}
BENCHMARK(BM_SubmapRectangle)->Arg(100)->Arg(316)->Arg(1000)->Unit(benchmark::kMillisecond);

void BM_PaveRectangle(benchmark::State& state) {
  static const geom::Model model = bench::rectangle_plate(10, 10);
  run_surface_scheme(state, model, bench::top_surface(model), "pave",
                     10.0 / static_cast<double>(state.range(0)));
}
BENCHMARK(BM_PaveRectangle)->Arg(100)->Arg(316)->Arg(1000)->Unit(benchmark::kMillisecond);

// A strip 1 wide and L long at size 0.1: 10 x 10 L quads, one block. Linear
// in L once each lattice line's boundary lengths are summed once (they were
// walked again for every point: quadratic, like a tall cylinder side).
void BM_SubmapLongStrip(benchmark::State& state) {
  const double length = static_cast<double>(state.range(0));
  const geom::Model model = bench::rectangle_plate(1.0, length);
  run_surface_scheme(state, model, bench::top_surface(model), "submap", 0.1);
}
BENCHMARK(BM_SubmapLongStrip)->Arg(100)->Arg(400)->Arg(1600)->Unit(benchmark::kMillisecond);

// A comb with 5 teeth (area 24) at sizes 1/4, 1/16, 1/64 of a unit.
void BM_SubmapComb(benchmark::State& state) {
  static const geom::Model model = bench::comb_prism(5);
  run_surface_scheme(state, model, bench::top_surface(model), "submap",
                     1.0 / static_cast<double>(state.range(0)));
}
BENCHMARK(BM_SubmapComb)->Arg(4)->Arg(16)->Arg(64)->Unit(benchmark::kMillisecond);

}  // namespace
