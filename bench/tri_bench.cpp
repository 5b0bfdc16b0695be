// The tri surface scheme: triangles per second on the plate with three holes
// (face_models.h) at ~5k, ~50k and ~500k triangles, with the smallest angle.
//
// BM_TriFace/<n>: n ~ thousands of triangles; the scheme's mesh() alone is
// timed (curves meshed before). Counters: tris, tris_per_s, min_angle_deg,
// peak_MB.
// Triangle caps swept into wedges: BM_WedgeSweep in cooper_table1_bench.cpp.
#include "bench_models.h"
#include "face_models.h"
#include "peak_memory.h"

#include <Eigen/Geometry>
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>

namespace {

using namespace cooperage;

/// Smallest corner angle [degrees] of the triangles of m.
double min_angle_deg(const scheme::EntityMesh& m) {
  double best = 180.0;
  for (const auto& t : m.tris)
    for (size_t k = 0; k < 3; ++k) {
      const geom::Vec3& p = m.coords[static_cast<size_t>(t[k])];
      const geom::Vec3 a = m.coords[static_cast<size_t>(t[(k + 1) % 3])] - p;
      const geom::Vec3 b = m.coords[static_cast<size_t>(t[(k + 2) % 3])] - p;
      best = std::min(best, std::atan2(a.cross(b).norm(), a.dot(b)) * 180.0 / M_PI);
    }
  return best;
}

// The plate's face (area 53.97) holds ~159 / size^2 triangles (measured: 15.9k
// at size 0.1, ~2.9 per size^2 of area), so ~5k triangles at size 0.178 and
// n thousand at 0.178 / sqrt(n / 5).
constexpr double kSize5k = 0.178;

void BM_TriFace(benchmark::State& state) {
  static const geom::Model model = bench::plate_three_holes();
  const int surface = bench::top_surface(model);
  const double size = kSize5k / std::sqrt(static_cast<double>(state.range(0)) / 5.0);
  const scheme::SurfaceScheme* tri = bench::builtin_registry().surface_scheme("tri");
  const mesh::MeshDB db = bench::curves_for_surface(model, *tri, surface, size);
  const scheme::SurfaceView view{model, surface, &db};
  scheme::EntityMesh m;
  for (auto _ : state) {
    m = tri->mesh(view, {size});
    benchmark::DoNotOptimize(m.coords.data());
  }
  state.counters["tris"] = static_cast<double>(m.tris.size());
  state.counters["tris_per_s"] = benchmark::Counter(static_cast<double>(m.tris.size()),
                                                    benchmark::Counter::kIsIterationInvariantRate);
  state.counters["min_angle_deg"] = min_angle_deg(m);
  state.counters["peak_MB"] = static_cast<double>(bench::peak_memory_bytes()) / 1e6;
}
BENCHMARK(BM_TriFace)->Arg(5)->Arg(50)->Arg(500)->Unit(benchmark::kMillisecond);

}  // namespace
