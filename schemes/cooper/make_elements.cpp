// Volume element generation (Blacker 1996, sec. 6.3): the cap mesh faces
// collect their ribs, which are progressed layer by layer.
#include "schemes/cooper/sweep_barrel.h"

#include "framework/quality/hex_metrics.h"
#include "framework/quality/wedge_metrics.h"

#include <algorithm>

namespace cooperage::cooper {

void make_elements(const SweepInput& in, std::vector<mesh::Hex>& hexes,
                   std::vector<mesh::Wedge>& wedges) {
  const int n = in.cap_nodes;
  hexes.clear();
  wedges.clear();
  hexes.reserve(in.quads.size() * static_cast<std::size_t>(in.layers));
  wedges.reserve(in.tris.size() * static_cast<std::size_t>(in.layers));
  for (int j = 0; j < in.layers; ++j) {
    const int lo = j * n;
    const int hi = lo + n;
    // Bottom face counter-clockwise about the direction to the next layer.
    for (const auto& q : in.quads) {
      hexes.push_back({q[0] + lo, q[1] + lo, q[2] + lo, q[3] + lo, q[0] + hi, q[1] + hi,
                       q[2] + hi, q[3] + hi});
    }
    for (const auto& t : in.tris) {
      wedges.push_back({t[0] + lo, t[1] + lo, t[2] + lo, t[0] + hi, t[1] + hi, t[2] + hi});
    }
  }
}

double min_scaled_jacobian(const std::vector<Vec3>& points, const std::vector<mesh::Hex>& hexes,
                           const std::vector<mesh::Wedge>& wedges, double limit, long* first_bad) {
  double worst = 1.0;
  long bad = -1;
  quality::HexNodes h;
  for (std::size_t e = 0; e < hexes.size(); ++e) {
    for (std::size_t c = 0; c < 8; ++c) h[c] = points[static_cast<std::size_t>(hexes[e][c])];
    const double sj = quality::hex_scaled_jacobian(h);
    if (sj <= limit && bad < 0) bad = static_cast<long>(e);
    worst = std::min(worst, sj);
  }
  quality::WedgeNodes w;
  for (std::size_t e = 0; e < wedges.size(); ++e) {
    for (std::size_t c = 0; c < 6; ++c) w[c] = points[static_cast<std::size_t>(wedges[e][c])];
    const double sj = quality::wedge_scaled_jacobian(w);
    if (sj <= limit && bad < 0) bad = static_cast<long>(hexes.size() + e);
    worst = std::min(worst, sj);
  }
  if (first_bad) *first_bad = bad;
  return worst;
}

}  // namespace cooperage::cooper
