#include "schemes/cooper/residual_field.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace cooperage::cooper {
namespace {

// Beyond this many weights (n x B) they are recomputed per call instead of
// kept (64 MB).
constexpr std::size_t kMaxKeptWeights = std::size_t{1} << 23;

double weight(const Vec3& x, const Vec3& b) {
  const double d2 = (x - b).squaredNorm();
  return 1.0 / (d2 * std::sqrt(d2) + 1e-300);
}

}  // namespace

ResidualField::ResidualField(const std::vector<Vec3>& points, std::size_t boundary)
    : points_(points), boundary_(boundary) {
  const std::size_t n = points_.size();
  if (n <= boundary_ || boundary_ == 0 || (n - boundary_) * boundary_ > kMaxKeptWeights) return;
  weights_.resize((n - boundary_) * boundary_);
  // Rows are independent: each is the same for any thread count.
  tbb::parallel_for(tbb::blocked_range<std::size_t>(boundary_, n, 256),
                    [&](const tbb::blocked_range<std::size_t>& rows) {
                      for (std::size_t i = rows.begin(); i != rows.end(); ++i) {
                        double* row = &weights_[(i - boundary_) * boundary_];
                        double sum = 0;
                        for (std::size_t k = 0; k < boundary_; ++k)
                          sum += row[k] = weight(points_[i], points_[k]);
                        for (std::size_t k = 0; k < boundary_; ++k) row[k] /= sum;
                      }
                    });
}

double residual_tolerance(const Vec3* points, std::size_t count) {
  if (count == 0) return 0.0;
  Vec3 lo = points[0], hi = points[0];
  for (std::size_t k = 1; k < count; ++k) {
    lo = lo.cwiseMin(points[k]);
    hi = hi.cwiseMax(points[k]);
  }
  return 1e-9 * (hi - lo).norm();
}

// cite: Blacker 1996, sec. 6.1 (least-squares weighted residuals).
void ResidualField::apply(const std::vector<Vec3>& r, std::vector<Vec3>& out) const {
  const std::size_t n = points_.size();
  out.assign(n, Vec3::Zero());
  Eigen::MatrixXd columns = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(boundary_), 3);
  for (std::size_t k = 0; k < boundary_ && k < r.size(); ++k) {
    out[k] = r[k];
    columns.row(static_cast<Eigen::Index>(k)) = r[k].transpose();
  }
  const Eigen::MatrixXd inside = interior(columns);
  for (std::size_t i = boundary_; i < n; ++i)
    out[i] = inside.row(static_cast<Eigen::Index>(i - boundary_)).transpose();
}

Eigen::MatrixXd ResidualField::interior(const Eigen::MatrixXd& r) const {
  const std::size_t n = points_.size();
  const Eigen::Index inner = static_cast<Eigen::Index>(n - std::min(n, boundary_));
  const Eigen::Index b = static_cast<Eigen::Index>(boundary_);
  if (b == 0) return Eigen::MatrixXd::Zero(inner, r.cols());
  if (!weights_.empty()) {
    using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
    const Eigen::Map<const RowMajor> w(weights_.data(), inner, b);
    return w * r;
  }
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(inner, r.cols());
  Eigen::VectorXd w(b);
  for (Eigen::Index i = 0; i < inner; ++i) {
    const Vec3& x = points_[boundary_ + static_cast<std::size_t>(i)];
    for (Eigen::Index k = 0; k < b; ++k) w(k) = weight(x, points_[static_cast<std::size_t>(k)]);
    out.row(i) = (w.transpose() * r) / w.sum();
  }
  return out;
}

// cite: Blacker 1996, sec. 6.1 (least-squares weighted residuals).
std::vector<Vec3> with_boundary_residuals(const std::vector<Vec3>& points,
                                          const std::vector<Vec3>& mapped,
                                          const std::vector<Vec3>& boundary_at) {
  const std::size_t boundary = boundary_at.size();
  std::vector<Vec3> residual(boundary);
  double largest = 0.0;
  for (std::size_t k = 0; k < boundary; ++k) {
    residual[k] = boundary_at[k] - mapped[k];
    largest = std::max(largest, residual[k].norm());
  }
  std::vector<Vec3> out = mapped;
  if (largest <= residual_tolerance(points.data(), boundary)) return out;
  std::vector<Vec3> r;
  ResidualField(points, boundary).apply(residual, r);
  for (std::size_t i = 0; i < out.size(); ++i) out[i] += r[i];
  return out;
}

}  // namespace cooperage::cooper
