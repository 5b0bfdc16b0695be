// The exact path of mesh2d's predicates, the one the floating-point filter
// cannot decide: BM_Orient2dExact on collinear points (exact binary
// fractions), BM_IncircleExact on
// cocircular ones (pave's frontal fill meets about one such query per quad).
// items/s = exact queries per second.
#include "framework/mesh2d/predicates.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

namespace cooperage::mesh2d {
namespace {

// Points on a circle of radius 5 from Pythagorean triples, moved by an
// offset that keeps them exact: every query is ambiguous to the filter.
std::vector<Point2> cocircular(double offset) {
  const double t[][2] = {{5, 0},  {4, 3},   {3, 4},   {0, 5},  {-3, 4}, {-4, 3},
                         {-5, 0}, {-4, -3}, {-3, -4}, {0, -5}, {3, -4}, {4, -3}};
  std::vector<Point2> p;
  for (const auto& q : t) p.emplace_back(offset + q[0] * 0.125, offset + q[1] * 0.125);
  return p;
}

void BM_IncircleExact(benchmark::State& state) {
  const std::vector<Point2> p = cocircular(static_cast<double>(state.range(0)));
  const size_t n = p.size();
  size_t i = 0;
  double sum = 0;
  for (auto _ : state) {
    sum += incircle(p[i % n], p[(i + 3) % n], p[(i + 6) % n], p[(i + 1) % n]);
    ++i;
  }
  benchmark::DoNotOptimize(sum);
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()));
}
BENCHMARK(BM_IncircleExact)->Arg(0)->Arg(1000);

void BM_Orient2dExact(benchmark::State& state) {
  const double o = static_cast<double>(state.range(0));
  const std::vector<Point2> p = {
      {o + 0.1, o + 0.2}, {o + 0.3, o + 0.6}, {o + 0.7, o + 1.4}, {o + 1.1, o + 2.2}};
  size_t i = 0;
  double sum = 0;
  for (auto _ : state) {
    sum += orient2d(p[i % 4], p[(i + 1) % 4], p[(i + 2) % 4]);
    ++i;
  }
  benchmark::DoNotOptimize(sum);
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()));
}
BENCHMARK(BM_Orient2dExact)->Arg(0);

}  // namespace
}  // namespace cooperage::mesh2d
