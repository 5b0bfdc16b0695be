// Metric names, summary statistics and evaluate() over a small mesh.
#include <array>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "framework/quality/evaluate.h"
#include "framework/quality/hex_metrics.h"
#include "framework/quality/metric.h"
#include "framework/quality/summary.h"

namespace cooperage::quality {
namespace {

using Eigen::Vector3d;

TEST(Metric, NamesRoundTrip) {
  for (Metric m : kAllMetrics) EXPECT_EQ(metric_from_string(to_string(m)), m);
  EXPECT_EQ(to_string(Metric::ScaledJacobian), "scaled_jacobian");
  EXPECT_EQ(to_string(Metric::AspectFrobenius), "aspect_frobenius");
  EXPECT_EQ(to_string(Metric::RelativeSize), "relative_size");
  EXPECT_FALSE(metric_from_string("condition").has_value());
  EXPECT_EQ(element_type_from_string("wedge"), ElementType::Wedge);
}

TEST(Metric, DirectionsAndRanges) {
  EXPECT_TRUE(higher_is_better(Metric::ScaledJacobian));
  EXPECT_TRUE(higher_is_better(Metric::Shape));
  EXPECT_FALSE(higher_is_better(Metric::Skew));
  EXPECT_FALSE(higher_is_better(Metric::EdgeRatio));
  const auto r = acceptable_range(Metric::ScaledJacobian, ElementType::Hex);
  ASSERT_TRUE(r.has_value());
  EXPECT_DOUBLE_EQ(r->lo, 0.5);
  EXPECT_DOUBLE_EQ(r->hi, 1.0);
  EXPECT_FALSE(is_defined(Metric::Skew, ElementType::Wedge));
  EXPECT_FALSE(acceptable_range(Metric::Taper, ElementType::Tri).has_value());
}

TEST(Summary, KnownVector) {
  // scaled Jacobian values; natural histogram range [-1, 1], bins of 0.2.
  const std::vector<double> v = {1.0, 0.9, 0.8, 0.45, 0.2, -0.5, 0.0, 0.95};
  const MetricSummary s = summarize(Metric::ScaledJacobian, v, 0.5, std::nullopt);
  EXPECT_EQ(s.metric, "scaled_jacobian");
  EXPECT_EQ(s.count, 8u);
  EXPECT_DOUBLE_EQ(s.min, -0.5);
  EXPECT_DOUBLE_EQ(s.max, 1.0);
  EXPECT_NEAR(s.mean, 3.8 / 8, 1e-15);
  // sorted: -0.5 0 0.2 0.45 0.8 0.9 0.95 1 -> median (0.45 + 0.8) / 2
  EXPECT_NEAR(s.median, 0.625, 1e-15);
  EXPECT_DOUBLE_EQ(s.histogram_lo, -1.0);
  EXPECT_DOUBLE_EQ(s.histogram_hi, 1.0);
  // bins: [-1,-.8) [-.8,-.6) [-.6,-.4) [-.4,-.2) [-.2,0) [0,.2) [.2,.4) [.4,.6) [.6,.8) [.8,1]
  const std::vector<size_t> expected = {0, 0, 1, 0, 0, 1, 1, 1, 0, 4};
  EXPECT_EQ(s.histogram, expected);
  EXPECT_EQ(s.below_threshold, 4u);  // 0.45, 0.2, -0.5, 0.0
  EXPECT_EQ(s.inverted, 2u);         // -0.5 and 0.0
}

TEST(Summary, UnboundedMetricUsesDataRangeAndUpperThreshold) {
  const std::vector<double> v = {1.0, 2.0, 3.0, 5.0, kDegenerate};
  const MetricSummary s = summarize(Metric::EdgeRatio, v, std::nullopt, 3.0);
  EXPECT_DOUBLE_EQ(s.histogram_lo, 1.0);
  EXPECT_DOUBLE_EQ(s.histogram_hi, 5.0);
  EXPECT_EQ(s.histogram.size(), 10u);
  EXPECT_EQ(s.histogram[0], 1u);  // 1.0
  EXPECT_EQ(s.histogram[2], 1u);  // 2.0 -> t = 2.5
  EXPECT_EQ(s.histogram[5], 1u);  // 3.0 -> t = 5
  EXPECT_EQ(s.histogram[9], 2u);  // 5.0 and the sentinel
  EXPECT_EQ(s.below_threshold, 2u);
  EXPECT_EQ(s.inverted, 0u);  // only for Jacobian metrics
  EXPECT_DOUBLE_EQ(s.median, 3.0);
}

TEST(Summary, Empty) {
  const MetricSummary s = summarize(Metric::Shape, {}, 0.3, std::nullopt);
  EXPECT_EQ(s.count, 0u);
  EXPECT_EQ(s.histogram.size(), 10u);
  EXPECT_EQ(s.below_threshold, 0u);
}

// Two unit cubes stacked in z, the second inverted by swapping top and bottom.
struct TwoHexMesh {
  std::vector<Vector3d> coords;
  std::vector<std::array<int, 8>> hexes;
  TwoHexMesh() {
    for (int k = 0; k < 3; ++k) {
      coords.emplace_back(0, 0, k);
      coords.emplace_back(1, 0, k);
      coords.emplace_back(1, 1, k);
      coords.emplace_back(0, 1, k);
    }
    hexes.push_back({0, 1, 2, 3, 4, 5, 6, 7});
    hexes.push_back({8, 9, 10, 11, 4, 5, 6, 7});  // inverted
  }
};

TEST(Evaluate, HexMeshAndSummary) {
  const TwoHexMesh m;
  const auto sj = evaluate(Metric::ScaledJacobian, ElementType::Hex, m.coords, m.hexes);
  ASSERT_EQ(sj.size(), 2u);
  EXPECT_NEAR(sj[0], 1.0, 1e-12);
  EXPECT_NEAR(sj[1], -1.0, 1e-12);
  const auto s = summarize(Metric::ScaledJacobian, sj, 0.5, std::nullopt);
  EXPECT_EQ(s.inverted, 1u);
  EXPECT_EQ(s.below_threshold, 1u);

  EvaluateOptions opts;
  opts.average_size = 1.0;
  const auto rs = evaluate(Metric::RelativeSize, ElementType::Hex, m.coords, m.hexes, opts);
  EXPECT_NEAR(rs[0], 1.0, 1e-12);
  EXPECT_DOUBLE_EQ(rs[1], 0.0);
}

// Hex scaled Jacobians go through the batched kernel when rows are eight
// ints, and one element at a time otherwise: both equal the single-hex
// function bit for bit (an odd count, more than one parallel chunk).
TEST(Evaluate, HexScaledJacobianEqualsOneElementAtATime) {
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> jitter(-0.5, 0.5);
  std::vector<Vector3d> coords;
  std::vector<std::array<int, 8>> hexes;
  std::vector<int> wide;  // the same rows with a ninth, unused column
  for (int e = 0; e < 9001; ++e) {
    std::array<int, 8> h;
    for (int c = 0; c < 8; ++c) {
      h[static_cast<size_t>(c)] = static_cast<int>(coords.size());
      coords.emplace_back((c == 1 || c == 2 || c == 5 || c == 6) + jitter(rng),
                          (c == 2 || c == 3 || c == 6 || c == 7) + jitter(rng),
                          (c >= 4) + jitter(rng));
    }
    hexes.push_back(h);
    wide.insert(wide.end(), h.begin(), h.end());
    wide.push_back(-7);
  }
  const auto batched = evaluate(Metric::ScaledJacobian, ElementType::Hex, coords, hexes);
  const auto strided =
      evaluate(Metric::ScaledJacobian, ElementType::Hex, coords, wide.data(), hexes.size(), 9);
  ASSERT_EQ(batched.size(), hexes.size());
  ASSERT_EQ(strided.size(), hexes.size());
  for (size_t e = 0; e < hexes.size(); ++e) {
    HexNodes p;
    for (int c = 0; c < 8; ++c)
      p[static_cast<size_t>(c)] = coords[static_cast<size_t>(hexes[e][c])];
    const double one = hex_scaled_jacobian(p);
    ASSERT_EQ(batched[e], one) << "hex " << e;
    ASSERT_EQ(strided[e], one) << "hex " << e;
  }
}

TEST(Evaluate, QuadsWithStrideAndNormals) {
  const std::vector<Vector3d> coords = {Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(1, 1, 0),
                                        Vector3d(0, 1, 0)};
  const std::vector<int> conn = {0, 1, 2, 3, 0, 3, 2, 1};  // CCW, then CW
  const auto own = evaluate(Metric::ScaledJacobian, ElementType::Quad, coords, conn.data(), 2, 4);
  EXPECT_NEAR(own[0], 1.0, 1e-12);
  EXPECT_NEAR(own[1], 1.0, 1e-12);
  const std::vector<Vector3d> normals(2, Vector3d(0, 0, 1));
  EvaluateOptions opts;
  opts.normals = &normals;
  const auto surf =
      evaluate(Metric::ScaledJacobian, ElementType::Quad, coords, conn.data(), 2, 4, opts);
  EXPECT_NEAR(surf[0], 1.0, 1e-12);
  EXPECT_NEAR(surf[1], -1.0, 1e-12);
  // Relative size against the mean area (1): both 1.
  const auto rs = evaluate(Metric::RelativeSize, ElementType::Quad, coords, conn.data(), 2, 4);
  EXPECT_NEAR(rs[0], 1.0, 1e-12);
}

TEST(Evaluate, RejectsBadInput) {
  const TwoHexMesh m;
  EXPECT_THROW(evaluate(Metric::Skew, ElementType::Wedge, m.coords, m.hexes), MeshingError);
  std::vector<std::array<int, 8>> bad = {{0, 1, 2, 3, 4, 5, 6, 99}};
  EXPECT_THROW(evaluate(Metric::Jacobian, ElementType::Hex, m.coords, bad), MeshingError);
  const std::vector<int> conn = {0, 1, 2};
  EXPECT_THROW(evaluate(Metric::Jacobian, ElementType::Quad, m.coords, conn.data(), 1, 3),
               MeshingError);
}

}  // namespace
}  // namespace cooperage::quality
