// Hex metrics against hand-computed values (Verdict definitions).
#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "framework/quality/hex_metrics.h"
#include "framework/quality/metric.h"

namespace cooperage::quality {
namespace {

using Eigen::Vector3d;

HexNodes box(double a, double b, double c) {
  return {Vector3d(0, 0, 0), Vector3d(a, 0, 0), Vector3d(a, b, 0), Vector3d(0, b, 0),
          Vector3d(0, 0, c), Vector3d(a, 0, c), Vector3d(a, b, c), Vector3d(0, b, c)};
}

HexNodes sheared(double s) {  // top face shifted by s in x
  HexNodes h = box(1, 1, 1);
  for (int i = 4; i < 8; ++i) h[i].x() += s;
  return h;
}

struct HexCase {
  std::string name;
  HexNodes nodes;
  double scaled_jacobian, jacobian, skew, taper, aspect, edge_ratio, shape;
};

std::vector<HexCase> cases() {
  const double s = 0.5;
  const double c = 1.0 / std::sqrt(1.0 + s * s);
  // Box 1x2x3, every corner matrix diag(1,2,3) up to order:
  //   |A|_F^2 = 1+4+9 = 14, |adj A|_F^2 = (1*2)^2+(2*3)^2+(3*1)^2 = 49, det = 6,
  //   aspect = sqrt(14*49)/6/3 = 7 sqrt(14)/18 ~ 1.45516,
  //   shape  = 3 * 6^(2/3) / 14 ~ 0.70755.
  // Sheared hex (s = 0.5): every corner and the centre have det 1 and edges
  //   1, 1, sqrt(1+s^2) -> scaled Jacobian 1/sqrt(1+s^2); skew = |X1.X3| =
  //   s/sqrt(1+s^2); aspect per corner: |A|_F^2 = 3+s^2,
  //   |adj|^2 = 1 + (1+s^2) + 1 = 3+s^2 -> (3+s^2)/3; shape 3/(3+s^2);
  //   edge ratio sqrt(1+s^2).
  return {
      {"unit_cube", box(1, 1, 1), 1, 1, 0, 0, 1, 1, 1},
      {"box_1x2x3", box(1, 2, 3), 1, 6, 0, 0, 7 * std::sqrt(14.0) / 18, 3,
       3 * std::pow(6.0, 2.0 / 3.0) / 14},
      {"sheared", sheared(s), c, 1, s * c, 0, (3 + s * s) / 3, std::sqrt(1 + s * s),
       3 / (3 + s * s)},
  };
}

TEST(HexMetrics, TableOfHandComputedValues) {
  for (const auto& t : cases()) {
    SCOPED_TRACE(t.name);
    EXPECT_NEAR(hex_scaled_jacobian(t.nodes), t.scaled_jacobian, 1e-12);
    EXPECT_NEAR(hex_jacobian(t.nodes), t.jacobian, 1e-12);
    EXPECT_NEAR(hex_skew(t.nodes), t.skew, 1e-12);
    EXPECT_NEAR(hex_taper(t.nodes), t.taper, 1e-12);
    EXPECT_NEAR(hex_max_aspect_frobenius(t.nodes), t.aspect, 1e-12);
    EXPECT_NEAR(hex_edge_ratio(t.nodes), t.edge_ratio, 1e-12);
    EXPECT_NEAR(hex_shape(t.nodes), t.shape, 1e-12);
  }
}

TEST(HexMetrics, RelativeSize) {
  EXPECT_NEAR(hex_relative_size(box(1, 2, 3), 6.0), 1.0, 1e-12);
  EXPECT_NEAR(hex_relative_size(box(1, 2, 3), 3.0), 0.25, 1e-12);   // tau = 2 -> (1/2)^2
  EXPECT_NEAR(hex_relative_size(box(1, 2, 3), 12.0), 0.25, 1e-12);  // tau = 1/2
  EXPECT_EQ(hex_relative_size(box(1, 2, 3), 0.0), 0.0);
  EXPECT_NEAR(hex_size(box(1, 2, 3)), 6.0, 1e-12);
}

TEST(HexMetrics, TaperOfTaperedHex) {
  // Top face shrunk to [0.25,0.75]^2: X1 = X2 = (3,0,0)/(0,3,0), X12 = 0,
  // X13 = (P0+P3+P5+P6)-(P1+P2+P4+P7) = (-1, 0, 0) -> taper |X13|/min(3,4)
  HexNodes h = box(1, 1, 1);
  h[4] = {0.25, 0.25, 1};
  h[5] = {0.75, 0.25, 1};
  h[6] = {0.75, 0.75, 1};
  h[7] = {0.25, 0.75, 1};
  EXPECT_NEAR(hex_taper(h), 1.0 / 3.0, 1e-12);
  EXPECT_NEAR(hex_skew(h), 0.0, 1e-12);
}

TEST(HexMetrics, DegenerateCollapsedTopFace) {
  // Top face collapsed to one point: a pyramid. Corners 4..7 have a
  // zero-length edge, so det = 0 there.
  HexNodes h = box(1, 1, 1);
  for (int i = 4; i < 8; ++i) h[i] = {0.5, 0.5, 1};
  EXPECT_DOUBLE_EQ(hex_jacobian(h), 0.0);
  EXPECT_DOUBLE_EQ(hex_scaled_jacobian(h), 0.0);  // Verdict: DBL_MAX (see header)
  EXPECT_DOUBLE_EQ(hex_shape(h), 0.0);
  EXPECT_DOUBLE_EQ(hex_edge_ratio(h), kDegenerate);
  EXPECT_DOUBLE_EQ(hex_max_aspect_frobenius(h), kDegenerate);
}

TEST(HexMetrics, FullyCollapsedIsDegenerate) {
  HexNodes h;
  h.fill(Vector3d(1, 2, 3));
  EXPECT_DOUBLE_EQ(hex_scaled_jacobian(h), 0.0);
  EXPECT_DOUBLE_EQ(hex_jacobian(h), 0.0);
  EXPECT_DOUBLE_EQ(hex_skew(h), kDegenerate);
  EXPECT_DOUBLE_EQ(hex_taper(h), kDegenerate);
}

TEST(HexMetrics, InvertedHex) {
  HexNodes h = box(1, 1, 1);
  for (int i = 4; i < 8; ++i) h[i].z() = -1;  // top face below the bottom
  EXPECT_NEAR(hex_scaled_jacobian(h), -1.0, 1e-12);
  EXPECT_NEAR(hex_jacobian(h), -1.0, 1e-12);
  EXPECT_DOUBLE_EQ(hex_shape(h), 0.0);
  EXPECT_DOUBLE_EQ(hex_max_aspect_frobenius(h), kDegenerate);
  EXPECT_DOUBLE_EQ(hex_relative_size(h, 1.0), 0.0);
}

// The definition evaluated frame by frame: each corner's three edges from
// its own node triple and the centre's principal axes, normalised, then the
// determinant. Distortions up to 0.6 of an edge invert some of the hexes,
// so every corner's sign convention is exercised.
double scaled_jacobian_by_definition(const HexNodes& p) {
  const int corner[8][4] = {{0, 1, 3, 4}, {1, 2, 0, 5}, {2, 3, 1, 6}, {3, 0, 2, 7},
                            {4, 7, 5, 0}, {5, 4, 6, 1}, {6, 5, 7, 2}, {7, 6, 4, 3}};
  auto unit_det = [](const Vector3d& a, const Vector3d& b, const Vector3d& c) {
    return a.normalized().dot(b.normalized().cross(c.normalized()));
  };
  const Vector3d x1 = (p[1] - p[0]) + (p[2] - p[3]) + (p[5] - p[4]) + (p[6] - p[7]);
  const Vector3d x2 = (p[3] - p[0]) + (p[2] - p[1]) + (p[7] - p[4]) + (p[6] - p[5]);
  const Vector3d x3 = (p[4] - p[0]) + (p[5] - p[1]) + (p[6] - p[2]) + (p[7] - p[3]);
  double m = unit_det(x1, x2, x3);
  for (const auto& c : corner)
    m = std::min(m, unit_det(p[c[1]] - p[c[0]], p[c[2]] - p[c[0]], p[c[3]] - p[c[0]]));
  return m;
}

TEST(HexMetrics, ScaledJacobianEqualsItsDefinitionOnDistortedHexes) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> jitter(-0.6, 0.6);
  int inverted = 0;
  for (int trial = 0; trial < 500; ++trial) {
    HexNodes h = box(1, 2, 0.5);
    for (auto& p : h) p += Vector3d(jitter(rng), jitter(rng), jitter(rng));
    const double expected = scaled_jacobian_by_definition(h);
    inverted += expected < 0;
    EXPECT_NEAR(hex_scaled_jacobian(h), expected, 1e-12) << "trial " << trial;
  }
  EXPECT_GT(inverted, 50);  // the sample reaches inverted corners
}

TEST(HexMetrics, BatchedScaledJacobiansEqualOneAtATime) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> jitter(-0.6, 0.6);
  std::vector<Vector3d> points;
  std::vector<std::array<int, 8>> hexes;
  for (int trial = 0; trial < 101; ++trial) {  // odd: the last hex has no partner
    std::array<int, 8> h;
    for (int c = 0; c < 8; ++c) {
      h[static_cast<size_t>(c)] = static_cast<int>(points.size());
      points.push_back(box(2, 1, 1)[static_cast<size_t>(c)] +
                       Vector3d(jitter(rng), jitter(rng), jitter(rng)));
    }
    std::swap(h[0], h[trial % 8]);  // hexes in any node layout
    hexes.push_back(h);
  }
  hexes.push_back({0, 0, 0, 0, 0, 0, 0, 0});  // collapsed: 0, as one at a time
  std::vector<double> batch(hexes.size());
  hex_scaled_jacobians(points.data(), hexes.front().data(), hexes.size(), batch.data());
  for (size_t e = 0; e < hexes.size(); ++e) {
    HexNodes p;
    for (int c = 0; c < 8; ++c)
      p[static_cast<size_t>(c)] = points[static_cast<size_t>(hexes[e][c])];
    EXPECT_EQ(batch[e], hex_scaled_jacobian(p)) << "hex " << e;
  }
  EXPECT_EQ(batch.back(), 0.0);
}

TEST(HexMetrics, RotationAndScalingInvariance) {
  std::mt19937 rng(20240611);
  std::uniform_real_distribution<double> jitter(-0.15, 0.15);
  std::normal_distribution<double> gauss(0.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    HexNodes h = box(1, 1, 1);
    for (auto& p : h) p += Vector3d(jitter(rng), jitter(rng), jitter(rng));
    ASSERT_GT(hex_scaled_jacobian(h), 0.0);
    Eigen::Quaterniond q(gauss(rng), gauss(rng), gauss(rng), gauss(rng));
    q.normalize();
    const double scale = 0.1 + 10.0 * std::abs(gauss(rng));
    const Vector3d shift(gauss(rng), gauss(rng), gauss(rng));
    HexNodes g;
    for (int i = 0; i < 8; ++i) g[i] = scale * (q * h[i]) + shift;
    const std::vector<std::pair<const char*, std::function<double(const HexNodes&)>>> invariant = {
        {"scaled_jacobian", hex_scaled_jacobian},
        {"skew", hex_skew},
        {"taper", hex_taper},
        {"shape", hex_shape},
        {"aspect", hex_max_aspect_frobenius},
        {"edge_ratio", hex_edge_ratio}};
    for (const auto& [name, f] : invariant) {
      SCOPED_TRACE(name);
      EXPECT_NEAR(f(g), f(h), 1e-12 * std::max(1.0, std::abs(f(h))));
    }
    EXPECT_NEAR(hex_jacobian(g), scale * scale * scale * hex_jacobian(h),
                1e-12 * scale * scale * scale);
  }
}

}  // namespace
}  // namespace cooperage::quality
