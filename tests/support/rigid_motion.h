// A seeded random rigid motion and the check that a mesh of the moved model
// is the moved mesh (the paper's orientation insensitivity; tests only).
#pragma once

#include "framework/geometry/occ/workbench.h"
#include "framework/mesh/mesh_db.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <random>
#include <string>

namespace cooperage::testing {

struct RigidMotion {
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
  double angle_deg = 0;  ///< rotation about `axis` through the origin
  Eigen::Vector3d shift = Eigen::Vector3d::Zero();

  /// A rotation of up to 180 degrees about a random axis, then a shift of up
  /// to 5 in each coordinate.
  static RigidMotion random(unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    RigidMotion m;
    m.axis = Eigen::Vector3d(u(rng), u(rng), u(rng)).normalized();
    m.angle_deg = 180 * u(rng);
    m.shift = Eigen::Vector3d(5 * u(rng), 5 * u(rng), 5 * u(rng));
    return m;
  }

  Eigen::Vector3d apply(const Eigen::Vector3d& p) const {
    return Eigen::AngleAxisd(angle_deg * M_PI / 180, axis) * p + shift;
  }

  /// Moves a workbench shape the same way.
  void apply(occ::Workbench& bench, const std::string& shape) const {
    bench.rotate(shape, {0, 0, 0}, axis, angle_deg);
    bench.translate(shape, shift);
  }
};

/// Largest distance between the moved nodes of `a` and the nodes of `b`, in
/// node order (the meshes must have the same node count).
inline double moved_node_distance(const mesh::MeshDB& a, const mesh::MeshDB& b,
                                  const RigidMotion& motion) {
  double worst = 0;
  for (size_t n = 0; n < a.node_count(); ++n) {
    const int i = static_cast<int>(n);
    worst = std::max(worst, (motion.apply(a.node(i)) - b.node(i)).norm());
  }
  return worst;
}

}  // namespace cooperage::testing
