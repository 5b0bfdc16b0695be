// Interior barrel nodes (Blacker 1996, sec. 6.1 projection of the cap mesh,
// sec. 6.2 the two-sided blend); ALGORITHMS.md sec. 3.
#include "schemes/cooper/sweep_barrel.h"

#include "schemes/cooper/residual_field.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>
#include <string>

namespace cooperage::cooper {
namespace {

// Residuals r_k = layer_k - map(from_k) of a least-squares map on the loop
// nodes; returns max |r_k|.
double residuals(const AffineMap& map, const Vec3* from, const Vec3* layer, std::size_t B,
                 std::vector<Vec3>& r) {
  r.resize(B);
  double worst = 0;
  for (std::size_t k = 0; k < B; ++k) {
    r[k] = layer[k] - map.apply(from[k]);
    worst = std::max(worst, r[k].norm());
  }
  return worst;
}

// Layer-major rings (contiguous per layer for the least-squares sums).
std::vector<Vec3> layer_major_rings(const SweepInput& in) {
  const std::size_t B = static_cast<std::size_t>(in.boundary);
  const std::size_t J = static_cast<std::size_t>(in.layers);
  std::vector<Vec3> ring(B * (J + 1));
  for (std::size_t r = 0; r < B; ++r) {
    for (std::size_t j = 0; j <= J; ++j) ring[j * B + r] = in.ribs[r * (J + 1) + j];
  }
  return ring;
}

// s_j: mean arc-length fraction along the ribs, so graded layers work.
std::vector<double> arc_length_fractions(const SweepInput& in) {
  const std::size_t B = static_cast<std::size_t>(in.boundary);
  const std::size_t J = static_cast<std::size_t>(in.layers);
  std::vector<double> s(J + 1, 0.0);
  for (std::size_t r = 0; r < B; ++r) {
    const Vec3* rib = &in.ribs[r * (J + 1)];
    double total = 0;
    for (std::size_t j = 1; j <= J; ++j) total += (rib[j] - rib[j - 1]).norm();
    double run = 0;
    for (std::size_t j = 1; j <= J; ++j) {
      run += (rib[j] - rib[j - 1]).norm();
      s[j] += total > 0 ? run / total : static_cast<double>(j) / static_cast<double>(J);
    }
  }
  for (std::size_t j = 1; j <= J; ++j) s[j] /= static_cast<double>(B);
  s[J] = 1.0;
  return s;
}

// The residual field of the cap (built on first need, once per sweep).
class LazyField {
 public:
  explicit LazyField(const SweepInput& in) : in_(in) {}
  const ResidualField& get() const {
    std::call_once(once_, [&] {
      field_ = std::make_unique<ResidualField>(in_.source, static_cast<std::size_t>(in_.boundary));
    });
    return *field_;
  }

 private:
  const SweepInput& in_;
  mutable std::once_flag once_;
  mutable std::unique_ptr<ResidualField> field_;
};

bool blend_with(const SweepInput& in, std::vector<Vec3>& points, std::string& why,
                const LazyField& field);

}  // namespace

bool place_layer_nodes(const SweepInput& in, std::vector<Vec3>& points, std::string& why) {
  const std::size_t n = static_cast<std::size_t>(in.cap_nodes);
  const std::size_t B = static_cast<std::size_t>(in.boundary);
  const std::size_t J = static_cast<std::size_t>(in.layers);
  const std::vector<Vec3> ring = layer_major_rings(in);
  // Each layer: its ring, then the source's interior nodes (layer 0) or
  // zeros. Layers are written in parallel (the first touch of the largest
  // array of the sweep is spread over the threads); same values for any
  // thread count.
  points.clear();
  points.resize(n * (J + 1));  // Vec3 is left uninitialised: every entry is written below
  tbb::parallel_for(std::size_t{0}, J + 1, [&](std::size_t j) {
    Vec3* layer = &points[j * n];
    std::copy(ring.begin() + static_cast<long>(j * B),
              ring.begin() + static_cast<long>((j + 1) * B), layer);
    if (j == 0) {
      std::copy(in.source.begin() + static_cast<long>(B), in.source.end(), layer + B);
    } else {
      std::fill(layer + B, layer + n, Vec3::Zero());
    }
  });
  if (n == B) return true;  // no interior cap nodes

  const Vec3* upper = &ring[0];
  const Vec3* lower = &ring[J * B];
  // Target cap: the source map to the target loop, then onto the surface.
  const AffineMap to_target = least_squares_map(upper, lower, B, in.loop_starts);
  if (!to_target.ok) {
    why =
        "the least-squares map from the source loops to the target loops is singular or "
        "inverting (det A <= 0)";
    return false;
  }
  const double tolerance = residual_tolerance(ring.data(), ring.size());
  std::vector<Vec3> res_u;

  // Target interior nodes are independent of each other: placed in parallel
  // (each node's value does not depend on the thread count).
  Vec3* target = &points[J * n];
  const bool correct_target = residuals(to_target, upper, lower, B, res_u) > tolerance;
  const bool fixed = in.has_fixed_target.size() == n;
  const LazyField field(in);
  std::vector<Vec3> r_target;
  if (correct_target) field.get().apply(res_u, r_target);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(B, n, 1024),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t i = range.begin(); i != range.end(); ++i) {
                        if (fixed && in.has_fixed_target[i]) {
                          target[i] = in.fixed_target[i];
                          continue;
                        }
                        Vec3 y = to_target.apply(in.source[i]);
                        if (correct_target) y += r_target[i];
                        target[i] = in.project_target ? in.project_target(y) : y;
                      }
                    });

  return blend_with(in, points, why, field);
}

bool blend_layers(const SweepInput& in, std::vector<Vec3>& points, std::string& why) {
  const LazyField field(in);
  return blend_with(in, points, why, field);
}

namespace {

bool blend_with(const SweepInput& in, std::vector<Vec3>& points, std::string& why,
                const LazyField& field) {
  const std::size_t n = static_cast<std::size_t>(in.cap_nodes);
  const std::size_t B = static_cast<std::size_t>(in.boundary);
  const std::size_t J = static_cast<std::size_t>(in.layers);
  if (n == B) return true;
  const std::vector<Vec3> ring = layer_major_rings(in);
  const std::vector<double> s = arc_length_fractions(in);
  const double tolerance = residual_tolerance(ring.data(), ring.size());
  const Vec3* upper = &ring[0];
  const Vec3* lower = &ring[J * B];
  const Vec3* target = &points[J * n];
  // x_ij = x^U_ij (1 - s_j) + x^L_ij s_j. Layers are independent: one task
  // per layer; a failing layer is reported by its index (the lowest one), so
  // the message does not depend on scheduling either.
  std::vector<char> failed(J + 1, 0);
  // Column 3 j + d: coordinate d of layer j's blended boundary residuals,
  // for the layers whose rings no map explains (`corrected`).
  std::vector<char> corrected(J + 1, 0);
  Eigen::MatrixXd residual_columns(static_cast<Eigen::Index>(B),
                                   3 * static_cast<Eigen::Index>(J + 1));
  tbb::parallel_for(std::size_t{1}, J, [&](std::size_t j) {
    const Vec3* layer = &ring[j * B];
    const AffineMap from_upper = least_squares_map(upper, layer, B, in.loop_starts);
    const AffineMap from_lower = least_squares_map(lower, layer, B, in.loop_starts);
    if (!from_upper.ok || !from_lower.ok) {
      failed[j] = from_upper.ok ? 2 : 1;
      return;
    }
    std::vector<Vec3> ru, rl;  // this layer's residuals
    const double eu = residuals(from_upper, upper, layer, B, ru);
    const double el = residuals(from_lower, lower, layer, B, rl);
    const bool cu = eu > tolerance;
    const bool cl = el > tolerance;
    // Where the rings change shape along the barrel (a countersink's cone
    // over its bore), a layer takes after the end whose map explains its
    // ring: weights from the residuals of the two maps instead of j / J.
    const double sj = cu || cl ? eu / (eu + el) : s[j];
    const Eigen::Matrix3d Au = (1.0 - sj) * from_upper.A;
    const Eigen::Matrix3d Al = sj * from_lower.A;
    const Vec3 c = from_upper.to_centre - Au * from_upper.from_centre - Al * from_lower.from_centre;
    // (1 - s) [A_U (x - xu) + yc] + s [A_L (t - xl) + yc] with yc shared.
    Vec3* out = &points[j * n];
    for (std::size_t i = B; i < n; ++i) out[i] = Au * in.source[i] + Al * target[i] + c;
    if (cu || cl) {
      corrected[j] = 1;
      for (std::size_t k = 0; k < B; ++k) {
        residual_columns.block<1, 3>(static_cast<Eigen::Index>(k),
                                     3 * static_cast<Eigen::Index>(j)) =
            ((1.0 - sj) * ru[k] + sj * rl[k]).transpose();
      }
    }
  });
  // The residuals carried inside, several layers per pass over the weights.
  // The groups follow the layer order (not the scheduling), so the values
  // are the same for any thread count.
  std::vector<std::size_t> to_correct;
  for (std::size_t j = 1; j < J; ++j) {
    if (corrected[j] && !failed[j]) to_correct.push_back(j);
  }
  constexpr std::size_t kLayersPerPass = 16;
  const std::size_t passes = (to_correct.size() + kLayersPerPass - 1) / kLayersPerPass;
  // Built here, outside the loop: its rows are built in parallel, and a
  // thread waiting for them may take another pass of the loop, which must
  // not wait for the field it is building.
  if (passes > 0) field.get();
  tbb::parallel_for(std::size_t{0}, passes, [&](std::size_t pass) {
    const std::size_t first = pass * kLayersPerPass;
    const std::size_t count = std::min(kLayersPerPass, to_correct.size() - first);
    Eigen::MatrixXd r(static_cast<Eigen::Index>(B), 3 * static_cast<Eigen::Index>(count));
    for (std::size_t t = 0; t < count; ++t) {
      r.middleCols<3>(3 * static_cast<Eigen::Index>(t)) =
          residual_columns.middleCols<3>(3 * static_cast<Eigen::Index>(to_correct[first + t]));
    }
    const Eigen::MatrixXd inside = field.get().interior(r);
    for (std::size_t t = 0; t < count; ++t) {
      Vec3* out = &points[to_correct[first + t] * n];
      const Eigen::Index c = 3 * static_cast<Eigen::Index>(t);
      for (std::size_t i = B; i < n; ++i) {
        const Eigen::Index row = static_cast<Eigen::Index>(i - B);
        out[i] += Vec3(inside(row, c), inside(row, c + 1), inside(row, c + 2));
      }
    }
  });
  for (std::size_t j = 1; j < J; ++j) {
    if (!failed[j]) continue;
    why = "the least-squares map to layer " + std::to_string(j) + " from the " +
          (failed[j] == 2 ? "target" : "source") + " loops is singular or inverting (det A <= 0)";
    return false;
  }
  return true;
}

}  // namespace

}  // namespace cooperage::cooper
