// The two-lane scaled Jacobian of pave's smoothing against the scalar one:
// the same bits for random, inverted, reflex and degenerate quads.
#include "schemes/pave/quad_quality_2d.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace cooperage::pave::detail {
namespace {

using V2 = Eigen::Vector2d;

// A node's quads as smoothing evaluates them (its corner moves, the rest is
// taken once): the same bits as the scalar function, in both lanes and for
// an odd quad left over.
TEST(QuadQuality2d, MovingCornerQuadsEqualTheScalarFunctionBitForBit) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> jitter(-0.7, 0.7);
  int inverted = 0, compared = 0;
  for (int ring = 0; ring < 80; ++ring) {
    const double scale = std::pow(10.0, jitter(rng) * 8);  // 1e-5.6 .. 1e5.6
    const size_t n = 1 + static_cast<size_t>(ring % 7);    // odd and even valences
    std::vector<std::array<V2, 3>> rest;
    std::vector<MovingCornerQuad> fixed;
    for (size_t k = 0; k < n; ++k) {
      std::array<V2, 3> q = {V2(1, 0), V2(1, 1), V2(0, 1)};
      for (V2& p : q) p = scale * (p + V2(jitter(rng), jitter(rng)));
      rest.push_back(q);
      fixed.push_back(moving_corner_quad(q[0], q[1], q[2]));
    }
    for (int trial = 0; trial < 5; ++trial) {
      const V2 x = scale * V2(jitter(rng), jitter(rng));
      std::vector<double> out(n);
      scaled_jacobians_at(fixed.data(), n, x, out.data());
      for (size_t k = 0; k < n; ++k) {
        const double expected = scaled_jacobian_2d(x, rest[k][0], rest[k][1], rest[k][2]);
        inverted += expected < 0;
        ++compared;
        EXPECT_EQ(out[k], expected) << "ring " << ring << " quad " << k;
      }
    }
  }
  EXPECT_GT(compared, 1000);
  EXPECT_GT(inverted, 100);  // the sample reaches reflex and inverted quads
  // A zero edge at the moving corner, and one among the fixed ones: -1.
  const MovingCornerQuad fixed[2] = {moving_corner_quad(V2(0, 0), V2(1, 1), V2(0, 1)),
                                     moving_corner_quad(V2(1, 0), V2(1, 0), V2(0, 1))};
  double out[2];
  scaled_jacobians_at(fixed, 2, V2(0, 0), out);
  EXPECT_EQ(out[0], -1.0);
  EXPECT_EQ(out[1], -1.0);
  scaled_jacobians_at(fixed + 1, 1, V2(0.2, 0.1), out);
  EXPECT_EQ(out[0], -1.0);
}

}  // namespace
}  // namespace cooperage::pave::detail
