// The HTML report of a big mesh: time to render it (quality of every
// element, the part's skin, simplification to the face budget, encoding)
// and the size of the page, on an n x n x n lattice of hexes marked, like a
// run's MeshDB, with its interior nodes (framework/report).
#include "framework/report/html_report.h"

#include <benchmark/benchmark.h>

#include <array>
#include <vector>

namespace {

using namespace cooperage;

struct Lattice {
  std::vector<Eigen::Vector3d> coords;
  std::vector<std::array<int, 8>> hexes;
  std::vector<bool> on_boundary;
  explicit Lattice(int n) {
    const auto id = [n](int i, int j, int k) { return (k * (n + 1) + j) * (n + 1) + i; };
    for (int k = 0; k <= n; ++k)
      for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
          // A slight shear so the scaled Jacobians spread over a range.
          coords.emplace_back(i + 0.3 * k / n * j, j, k);
          on_boundary.push_back(i == 0 || j == 0 || k == 0 || i == n || j == n || k == n);
        }
    for (int k = 0; k < n; ++k)
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
          hexes.push_back({id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k),
                           id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1),
                           id(i, j + 1, k + 1)});
  }
};

void BM_Report(benchmark::State& state) {
  const Lattice lattice(static_cast<int>(state.range(0)));
  report::ReportInput in;
  in.title = "lattice";
  in.coords = &lattice.coords;
  in.maybe_boundary = lattice.on_boundary;
  report::ElementBlock block;
  block.name = block.part = "volume 1";
  block.connectivity = lattice.hexes.front().data();
  block.count = lattice.hexes.size();
  in.blocks.push_back(block);
  std::size_t bytes = 0;
  for (auto _ : state) {
    const std::string html = report::render_report(in);
    bytes = html.size();
    benchmark::DoNotOptimize(html.data());
  }
  state.counters["hexes"] = static_cast<double>(lattice.hexes.size());
  state.counters["hexes_per_s"] = benchmark::Counter(static_cast<double>(lattice.hexes.size()),
                                                     benchmark::Counter::kIsIterationInvariantRate);
  state.counters["html_kB"] = static_cast<double>(bytes) / 1000.0;
}
BENCHMARK(BM_Report)->Arg(20)->Arg(50)->Arg(100)->Unit(benchmark::kMillisecond);

}  // namespace
