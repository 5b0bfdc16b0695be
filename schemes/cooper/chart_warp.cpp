#include "schemes/cooper/chart_warp.h"

#include <algorithm>
#include <cmath>

namespace cooperage::cooper {

ChartWarp::ChartWarp(const std::vector<std::pair<Vec2, Vec2>>& ribs) {
  if (ribs.empty()) return;
  Vec2 lo = ribs.front().first, hi = lo;
  double largest = 0;
  for (const auto& [q, p] : ribs) {
    lo = lo.cwiseMin(q);
    hi = hi.cwiseMax(q);
    largest = std::max(largest, (p - q).norm());
  }
  if (largest <= 1e-9 * std::max((hi - lo).norm(), 1e-300)) return;
  for (const auto& [q, p] : ribs) {
    at_.push_back(q);
    residual_.push_back(p - q);
  }
}

ChartWarp::Vec2 ChartWarp::residual(const Vec2& q) const {
  Vec2 sum = Vec2::Zero();
  double wsum = 0;
  for (size_t k = 0; k < at_.size(); ++k) {
    const double d2 = (at_[k] - q).squaredNorm();
    if (d2 <= 0) return residual_[k];
    const double w = 1.0 / (d2 * std::sqrt(d2));
    sum += w * residual_[k];
    wsum += w;
  }
  return sum / wsum;
}

ChartWarp::Vec2 ChartWarp::forward(const Vec2& q) const {
  return active() ? Vec2(q + residual(q)) : q;
}

ChartWarp::Vec2 ChartWarp::inverse(const Vec2& p) const {
  if (!active()) return p;
  // q + r(q) = p. Damped fixed-point steps; the best iterate is kept (a
  // point between two ribs of opposite residuals need not converge).
  Vec2 q = p, best = p;
  double best_miss = (forward(p) - p).norm();
  const double tolerance = 1e-12 * (1 + p.norm());
  for (int i = 0; i < 50 && best_miss > tolerance; ++i) {
    q += 0.7 * (p - forward(q));
    const double miss = (forward(q) - p).norm();
    if (miss < best_miss) {
      best_miss = miss;
      best = q;
    }
  }
  return best;
}

}  // namespace cooperage::cooper
