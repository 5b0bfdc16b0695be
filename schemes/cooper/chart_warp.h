// A barrel's lower end in the chart of its upper end, exactly along the
// ribs (Blacker 1996, sec. 5: imprinting projects one end onto the other
// and takes a rib's two nodes as one point). The barrel's least-squares
// map explains the ring's affine motion only; where the side twists (a
// hole's nodes a part of an interval round from their partners, because
// the two ends split its circle at different vertices) or a hole shrinks,
// ribbed nodes miss their partners in the chart by up to an interval, and
// a loop of the lower end that starts at a ribbed node lands across the
// upper end's loops beside it. The residuals of the ribs (partner's chart
// position minus the node's own) are carried to every other node of the
// end by inverse-distance weights (power 3, as the sweep's residuals,
// sec. 6.1), so that ribbed nodes coincide and the rest follow them.
// Value types only.
#pragma once

#include <Eigen/Core>

#include <utility>
#include <vector>

namespace cooperage::cooper {

class ChartWarp {
 public:
  using Vec2 = Eigen::Vector2d;

  ChartWarp() = default;
  /// \param[in] ribs  (lower node's chart position, its partner's chart position)
  explicit ChartWarp(const std::vector<std::pair<Vec2, Vec2>>& ribs);

  /// False when the ribs' residuals are all below 1e-9 of their extent:
  /// the affine map explains them, and positions are left as they are.
  bool active() const { return !at_.empty(); }
  /// A lower node's chart position onto the upper end's (exact at ribs).
  Vec2 forward(const Vec2& q) const;
  /// The inverse of forward(), by fixed-point iteration: where a point of
  /// the upper end's chart lies on the lower end, in the affine chart.
  Vec2 inverse(const Vec2& p) const;

 private:
  Vec2 residual(const Vec2& q) const;
  std::vector<Vec2> at_;
  std::vector<Vec2> residual_;
};

}  // namespace cooperage::cooper
