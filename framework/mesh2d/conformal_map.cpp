#include "framework/mesh2d/conformal_map.h"

#include "framework/core/error.h"

#include <Eigen/Geometry>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>
#include <limits>

namespace cooperage::mesh2d {
namespace {

using Eigen::Vector2d;
using Eigen::Vector3d;

/// The triangle in an orthonormal frame of its own plane: q[0] at the
/// origin, q[1] on the x axis, q[2] above it (counter-clockwise). False when
/// the triangle has (almost) no area.
bool local_frame(const Vector3d& p0, const Vector3d& p1, const Vector3d& p2,
                 std::array<Vector2d, 3>& q) {
  const Vector3d e1 = p1 - p0;
  const Vector3d n = e1.cross(p2 - p0);
  const double l = e1.norm();
  const double area2 = n.norm();
  const double scale = std::max({l, (p2 - p0).norm(), (p2 - p1).norm()});
  if (!(l > 0) || !(area2 > 1e-14 * scale * scale)) return false;
  const Vector3d x = e1 / l;
  const Vector3d y = (n / area2).cross(x);
  q[0] = Vector2d::Zero();
  q[1] = Vector2d(l, 0.0);
  q[2] = Vector2d((p2 - p0).dot(x), (p2 - p0).dot(y));
  return true;
}

}  // namespace

std::vector<Vector2d> conformal_map(const std::vector<Vector3d>& points,
                                    const std::vector<std::array<int, 3>>& triangles, int pin0,
                                    int pin1) {
  const int n = static_cast<int>(points.size());
  if (pin0 < 0 || pin1 < 0 || pin0 >= n || pin1 >= n || pin0 == pin1) {
    throw MeshingError(ErrorCode::Internal, "conformal map: invalid pinned vertices");
  }
  // Columns: u then v of every free vertex used by a triangle (pinned
  // vertices are known and go to the right-hand side).
  std::vector<int> column(static_cast<size_t>(n), -1);
  for (const auto& t : triangles) {
    for (int v : t) column[static_cast<size_t>(v)] = 0;
  }
  column[static_cast<size_t>(pin0)] = column[static_cast<size_t>(pin1)] = -2;
  int free = 0;
  for (int& c : column) {
    if (c == 0) c = free++;
  }
  std::vector<Vector2d> out(static_cast<size_t>(n), Vector2d::Zero());
  out[static_cast<size_t>(pin1)] =
      Vector2d((points[static_cast<size_t>(pin1)] - points[static_cast<size_t>(pin0)]).norm(), 0.0);
  if (free == 0) return out;

  // Two rows per triangle (Levy et al. 2002, sec. 3): for the flat positions
  // (u_k, v_k) of its corners and w_k, the edge opposite corner k in the
  // triangle's own frame, the residual of the Cauchy-Riemann equations is
  // sum_k (u_k w_k + v_k J w_k) / (2 A), J the rotation by +90 degrees;
  // times sqrt(A) it is the energy's square root.
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(triangles.size() * 12);
  std::vector<double> rhs;
  rhs.reserve(triangles.size() * 2);
  int row = 0;
  for (const auto& t : triangles) {
    std::array<Vector2d, 3> q;
    if (!local_frame(points[static_cast<size_t>(t[0])], points[static_cast<size_t>(t[1])],
                     points[static_cast<size_t>(t[2])], q)) {
      continue;
    }
    const double area = 0.5 * q[1].x() * q[2].y();
    const double s = 1.0 / std::sqrt(4.0 * area);
    double bx = 0.0, by = 0.0;
    for (int k = 0; k < 3; ++k) {
      const Vector2d w = q[static_cast<size_t>((k + 2) % 3)] - q[static_cast<size_t>((k + 1) % 3)];
      const int v = t[static_cast<size_t>(k)];
      // Row x: u w.x - v w.y; row y: u w.y + v w.x.
      const double cux = s * w.x(), cvx = -s * w.y(), cuy = s * w.y(), cvy = s * w.x();
      const int c = column[static_cast<size_t>(v)];
      if (c >= 0) {
        entries.emplace_back(row, c, cux);
        entries.emplace_back(row, free + c, cvx);
        entries.emplace_back(row + 1, c, cuy);
        entries.emplace_back(row + 1, free + c, cvy);
      } else {
        const Vector2d& known = out[static_cast<size_t>(v)];
        bx -= cux * known.x() + cvx * known.y();
        by -= cuy * known.x() + cvy * known.y();
      }
    }
    rhs.push_back(bx);
    rhs.push_back(by);
    row += 2;
  }
  Eigen::SparseMatrix<double> a(row, 2 * free);
  a.setFromTriplets(entries.begin(), entries.end());
  const Eigen::Map<const Eigen::VectorXd> b(rhs.data(), row);
  const Eigen::SparseMatrix<double> normal = a.transpose() * a;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(normal);
  if (solver.info() != Eigen::Success) {
    throw MeshingError(ErrorCode::MeshingFailed, "conformal map: the linear system is singular");
  }
  const Eigen::VectorXd x = solver.solve(a.transpose() * b);
  if (solver.info() != Eigen::Success || !x.allFinite()) {
    throw MeshingError(ErrorCode::MeshingFailed, "conformal map: the linear system is singular");
  }
  for (int v = 0; v < n; ++v) {
    const int c = column[static_cast<size_t>(v)];
    if (c >= 0) out[static_cast<size_t>(v)] = Vector2d(x[c], x[free + c]);
  }
  return out;
}

double max_conformal_distortion(const std::vector<Vector3d>& points,
                                const std::vector<Vector2d>& flat,
                                const std::vector<std::array<int, 3>>& triangles) {
  double worst = 1.0;
  for (const auto& t : triangles) {
    std::array<Vector2d, 3> q;
    if (!local_frame(points[static_cast<size_t>(t[0])], points[static_cast<size_t>(t[1])],
                     points[static_cast<size_t>(t[2])], q)) {
      continue;
    }
    const Vector2d& a = flat[static_cast<size_t>(t[0])];
    Eigen::Matrix2d f;
    f << flat[static_cast<size_t>(t[1])] - a, flat[static_cast<size_t>(t[2])] - a;
    const double det = f.determinant();
    const double scale = std::max(f.col(0).squaredNorm(), f.col(1).squaredNorm());
    if (!(std::abs(det) > 1e-14 * scale)) continue;
    if (det < 0) return std::numeric_limits<double>::infinity();
    Eigen::Matrix2d g;
    g << q[1], q[2];
    const Eigen::Matrix2d m = g * f.inverse();
    // Singular values of a 2x2 matrix from its Frobenius norm and determinant.
    const double fro2 = m.squaredNorm();
    const double d = std::abs(m.determinant());
    const double root = std::sqrt(std::max(0.0, fro2 * fro2 - 4.0 * d * d));
    const double s1 = std::sqrt(0.5 * (fro2 + root));
    const double s2 = d / s1;
    if (!(s2 > 0)) return std::numeric_limits<double>::infinity();
    worst = std::max(worst, s1 / s2);
  }
  return worst;
}

}  // namespace cooperage::mesh2d
