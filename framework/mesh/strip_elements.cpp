#include "framework/mesh/strip_elements.h"

#include <cmath>

namespace cooperage::mesh {
namespace {

// Positions in the ring of a chain from tip0 to tip1, stepping by `step`
// (+1 forward, -1 backward), and the arc-length fraction at each.
struct Chain {
  std::vector<int> at;
  std::vector<double> fraction;
};

Chain chain(const std::vector<Vec3>& ring, size_t tip0, size_t tip1, long step) {
  const long n = static_cast<long>(ring.size());
  Chain c;
  double length = 0;
  for (long k = static_cast<long>(tip0);; k = (k + step + n) % n) {
    if (!c.at.empty())
      length += (ring[static_cast<size_t>(k)] - ring[static_cast<size_t>(c.at.back())]).norm();
    c.at.push_back(static_cast<int>(k));
    c.fraction.push_back(length);
    if (k == static_cast<long>(tip1)) break;
  }
  for (double& f : c.fraction) f = length > 0 ? f / length : 0.0;
  return c;
}

}  // namespace

std::optional<StripElements> strip_elements(const std::vector<Vec3>& ring, size_t tip0,
                                            size_t tip1) {
  if (tip0 == tip1 || tip0 >= ring.size() || tip1 >= ring.size()) return std::nullopt;
  const Chain a = chain(ring, tip0, tip1, +1);
  const Chain b = chain(ring, tip0, tip1, -1);
  const size_t m = a.at.size() - 1, n = b.at.size() - 1;  // edges of each chain
  if (m < 2 || n < 2) return std::nullopt;
  StripElements out;
  size_t i = 0, j = 0;
  while (i < m || j < n) {
    // The moves that keep every element proper: the tips close with
    // triangles only, and a chain reaches its end only with the other.
    const bool first = i == 0 && j == 0;
    const bool last = i + 1 == m && j + 1 == n;
    const bool both = first || last || (i + 1 < m && j + 1 < n);
    const bool a_only = !first && i + 1 < m;
    const bool b_only = !first && j + 1 < n;
    double best = INFINITY;
    int move = -1;  // 0 both, 1 a only, 2 b only
    const auto offer = [&](bool allowed, int which, double fa, double fb) {
      const double d = std::abs(fa - fb);
      if (allowed && d < best - 1e-12) {
        best = d;
        move = which;
      }
    };
    offer(both, 0, a.fraction[std::min(i + 1, m)], b.fraction[std::min(j + 1, n)]);
    offer(a_only, 1, a.fraction[std::min(i + 1, m)], b.fraction[j]);
    offer(b_only, 2, a.fraction[i], b.fraction[std::min(j + 1, n)]);
    if (move < 0) return std::nullopt;
    const int ai = a.at[i], bj = b.at[j];
    if (move == 0) {
      const int a1 = a.at[i + 1], b1 = b.at[j + 1];
      if (first) {
        out.tris.push_back({ai, a1, b1});
      } else if (last) {
        out.tris.push_back({ai, a1, bj});
      } else {
        out.quads.push_back({ai, a1, b1, bj});
      }
      ++i;
      ++j;
    } else if (move == 1) {
      out.tris.push_back({ai, a.at[i + 1], bj});
      ++i;
    } else {
      out.tris.push_back({ai, b.at[j + 1], bj});
      ++j;
    }
  }
  return out;
}

}  // namespace cooperage::mesh
