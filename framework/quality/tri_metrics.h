// Verdict-equivalent quality metrics of a 3-node triangle in 3D.
//
// Node order: P0, P1, P2 counter-clockwise seen from the side the surface
// normal points to. Verdict measures a triangle against its own normal, so
// its values are orientation-blind (always >= 0); the overloads taking
// `normal` measure against a reference (surface) normal instead, so a
// triangle whose orientation disagrees with the surface gets a negative
// scaled Jacobian / Jacobian and zero shape.
// Reference element: the equilateral triangle (scaled Jacobian, shape,
// aspect Frobenius and edge ratio exactly 1). A right isosceles triangle has
// scaled Jacobian (2/sqrt 3) sin 45 = sqrt(2/3) ~ 0.816 (Verdict divides by
// the LARGEST product of two edge lengths, i.e. it takes the smallest corner
// sine), shape sqrt(3)/2 and aspect Frobenius 2/sqrt(3).
// cite: sandialabs/verdict V_TriMetric.cpp; Verdict manual sec. 4.
#pragma once

#include <array>

#include <Eigen/Core>

namespace cooperage::quality {

using TriNodes = std::array<Eigen::Vector3d, 3>;

/// (2/sqrt 3) |(P1-P0) x (P2-P0)| / max_{i<j}(|e_i||e_j|) = (2/sqrt 3) min
/// corner sine. Range [0, 1] (own normal); equilateral 1; acceptable
/// [0.5, 2/sqrt 3]. Degenerate (max edge product ~ 0): 0.
double tri_scaled_jacobian(const TriNodes& p);
/// As above, signed by the reference normal: negative when
/// normal . ((P1-P0) x (P2-P0)) < 0. Range [-1, 1].
double tri_scaled_jacobian(const TriNodes& p, const Eigen::Vector3d& normal);

/// Cooperage extension (Verdict has no tri Jacobian; its quad_jacobian
/// returns this value for a collapsed quad): |(P1-P0) x (P2-P0)| = 2 x area.
/// Units length^2; acceptable [0, inf).
double tri_jacobian(const TriNodes& p);
/// As above, signed by the reference normal.
double tri_jacobian(const TriNodes& p, const Eigen::Vector3d& normal);

/// (|e0|^2+|e1|^2+|e2|^2) / (2 sqrt 3 |(P1-P0) x (P2-P0)|). Range [1, inf);
/// equilateral 1; acceptable [1, 1.3]. Zero area: kDegenerate.
double tri_aspect_frobenius(const TriNodes& p);

/// Longest / shortest edge. Range [1, inf); equilateral 1; acceptable
/// [1, 1.3]. Zero-length edge: kDegenerate.
double tri_edge_ratio(const TriNodes& p);

/// 1 / condition, condition = (|v1|^2 + |v2|^2 - v1.v2) / (sqrt 3 |v1 x v2|),
/// v1 = P1-P0, v2 = P2-P0. Range [0, 1]; equilateral 1; acceptable
/// [0.25, 1]. Zero area: 0.
double tri_shape(const TriNodes& p);
/// As above, but 0 when the triangle is inverted against `normal`.
double tri_shape(const TriNodes& p, const Eigen::Vector3d& normal);

/// Verdict's relative size squared: R = (area / average_area)^2,
/// value min(R, 1/R). Range [0, 1]; acceptable [0.25, 1]. Zero area or
/// average_area <= 0: 0.
double tri_relative_size(const TriNodes& p, double average_area);

/// Area (the size tri_relative_size compares).
double tri_size(const TriNodes& p);

}  // namespace cooperage::quality
