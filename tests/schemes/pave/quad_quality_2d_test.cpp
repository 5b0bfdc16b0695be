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

TEST(QuadQuality2d, PairEqualsTheScalarFunctionBitForBit) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> jitter(-0.7, 0.7);
  std::vector<std::array<V2, 4>> quads;
  for (int i = 0; i < 400; ++i) {
    std::array<V2, 4> q = {V2(0, 0), V2(1, 0), V2(1, 1), V2(0, 1)};
    const double scale = std::pow(10.0, jitter(rng) * 8);  // 1e-5.6 .. 1e5.6
    for (V2& p : q) p = scale * (p + V2(jitter(rng), jitter(rng)));
    quads.push_back(q);
  }
  quads.push_back({V2(0, 0), V2(0, 0), V2(1, 1), V2(0, 1)});  // a zero edge: -1
  quads.push_back({V2(0, 0), V2(1, 0), V2(0, 1), V2(1, 1)});  // bow tie
  int inverted = 0;
  for (size_t i = 0; i + 1 < quads.size(); i += 2) {
    const V2* p[4];
    const V2* q[4];
    for (int k = 0; k < 4; ++k) p[k] = &quads[i][static_cast<size_t>(k)];
    for (int k = 0; k < 4; ++k) q[k] = &quads[i + 1][static_cast<size_t>(k)];
    double pair[2];
    scaled_jacobian_2d_pair(p, q, pair);
    for (int lane = 0; lane < 2; ++lane) {
      const auto& quad = quads[i + static_cast<size_t>(lane)];
      const double expected = scaled_jacobian_2d(quad[0], quad[1], quad[2], quad[3]);
      inverted += expected < 0;
      EXPECT_EQ(pair[lane], expected) << "quad " << i + static_cast<size_t>(lane);
    }
  }
  EXPECT_GT(inverted, 20);  // the sample reaches reflex and inverted quads
  const V2* zero_edge[4] = {&quads[400][0], &quads[400][1], &quads[400][2], &quads[400][3]};
  double pair[2];
  scaled_jacobian_2d_pair(zero_edge, zero_edge, pair);
  EXPECT_EQ(pair[0], -1.0);
}

}  // namespace
}  // namespace cooperage::pave::detail
