// Volume element generation (Blacker 1996, sec. 6.3): the cap mesh faces
// collect their ribs, which are progressed layer by layer.
#include "schemes/cooper/sweep_barrel.h"

#include "framework/quality/hex_metrics.h"
#include "framework/quality/wedge_metrics.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>

namespace cooperage::cooper {

void make_elements(const SweepInput& in, std::vector<mesh::Hex>& hexes,
                   std::vector<mesh::Wedge>& wedges) {
  const int n = in.cap_nodes;
  const std::size_t nq = in.quads.size(), nt = in.tris.size();
  const std::size_t layers = static_cast<std::size_t>(std::max(0, in.layers));
  hexes.resize(nq * layers);
  wedges.resize(nt * layers);
  // Layer j's elements occupy a fixed slice: filled in parallel, the same
  // arrays for any thread count.
  tbb::parallel_for(std::size_t{0}, layers, [&](std::size_t j) {
    const int lo = static_cast<int>(j) * n;
    const int hi = lo + n;
    // Bottom face counter-clockwise about the direction to the next layer.
    for (std::size_t k = 0; k < nq; ++k) {
      const auto& q = in.quads[k];
      hexes[j * nq + k] = {q[0] + lo, q[1] + lo, q[2] + lo, q[3] + lo,
                           q[0] + hi, q[1] + hi, q[2] + hi, q[3] + hi};
    }
    for (std::size_t k = 0; k < nt; ++k) {
      const auto& t = in.tris[k];
      wedges[j * nt + k] = {t[0] + lo, t[1] + lo, t[2] + lo, t[0] + hi, t[1] + hi, t[2] + hi};
    }
  });
}

namespace {

// Worst value and first element at or below the limit over a range; the
// combination (min, min) is order-free, so the parallel result is exact.
struct Worst {
  double value = 1.0;
  long first_bad = -1;
  void add(double sj, long e, double limit) {
    value = std::min(value, sj);
    if (sj <= limit && (first_bad < 0 || e < first_bad)) first_bad = e;
  }
  void join(const Worst& o) {
    value = std::min(value, o.value);
    if (o.first_bad >= 0 && (first_bad < 0 || o.first_bad < first_bad)) first_bad = o.first_bad;
  }
};

}  // namespace

double min_scaled_jacobian(const std::vector<Vec3>& points, const std::vector<mesh::Hex>& hexes,
                           const std::vector<mesh::Wedge>& wedges, double limit, long* first_bad,
                           std::vector<double>* values) {
  const std::size_t nh = hexes.size();
  if (values) values->resize(nh + wedges.size());
  const Worst worst = tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, nh + wedges.size(), 4096), Worst{},
      [&](const tbb::blocked_range<std::size_t>& range, Worst w) {
        // Hexes go through the batched kernel, 512 at a time.
        static_assert(sizeof(mesh::Hex) == 8 * sizeof(int), "rows are contiguous ints");
        constexpr std::size_t kBatch = 512;
        double sj[kBatch];
        for (std::size_t first = range.begin(); first < range.end(); first += kBatch) {
          const std::size_t last = std::min(range.end(), first + kBatch);
          const std::size_t hex_end = std::clamp(nh, first, last);
          if (hex_end > first)
            quality::hex_scaled_jacobians(points.data(), hexes[first].data(), hex_end - first, sj);
          for (std::size_t e = hex_end; e < last; ++e) {
            quality::WedgeNodes p;
            const auto& wedge = wedges[e - nh];
            for (std::size_t c = 0; c < 6; ++c) p[c] = points[static_cast<std::size_t>(wedge[c])];
            sj[e - first] = quality::wedge_scaled_jacobian(p);
          }
          for (std::size_t e = first; e < last; ++e) {
            if (values) (*values)[e] = sj[e - first];
            w.add(sj[e - first], static_cast<long>(e), limit);
          }
        }
        return w;
      },
      [](Worst a, const Worst& b) {
        a.join(b);
        return a;
      });
  if (first_bad) *first_bad = worst.first_bad;
  return worst.value;
}

}  // namespace cooperage::cooper
