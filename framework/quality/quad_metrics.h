// Verdict-equivalent quality metrics of a 4-node quadrilateral in 3D.
//
// Node order: P0..P3 counter-clockwise seen from the side the surface
// normal points to. Edges e0=P1-P0, e1=P2-P1, e2=P3-P2, e3=P0-P3.
// Signed corner areas: a_0 = n.(e3 x e0), a_1 = n.(e0 x e1), a_2 = n.(e1 x e2),
// a_3 = n.(e2 x e3), where Verdict's n is the element's own unit centre
// normal (e0 - e2) x (e1 - e3) / |...|. Against its own normal a quad
// traversed clockwise still looks valid; the overloads taking `normal` use a
// reference (surface) normal instead, so such a quad gets a negative scaled
// Jacobian. A quad with P2 == P3 (collapsed) is measured as the triangle
// P0 P1 P2 for the Jacobian and scaled Jacobian, as Verdict does.
// Principal axes X1 = P1+P2-P0-P3, X2 = P2+P3-P0-P1; cross derivative
// X12 = P0+P2-P1-P3.
// cite: sandialabs/verdict V_QuadMetric.cpp; Verdict manual sec. 5.
#pragma once

#include <array>

#include <Eigen/Core>

namespace cooperage::quality {

using QuadNodes = std::array<Eigen::Vector3d, 4>;

/// min over corners of a_k / (|e_in||e_out|). Range [-1, 1]; square 1;
/// rhombus with angle a: sin a; acceptable [0.3, 1]. Zero-length edge: 0.
double quad_scaled_jacobian(const QuadNodes& p);
/// As above, corner areas signed by the reference normal.
double quad_scaled_jacobian(const QuadNodes& p, const Eigen::Vector3d& normal);

/// min over corners of a_k. Units length^2; unit square 1; acceptable
/// [0, inf). No sentinel.
double quad_jacobian(const QuadNodes& p);
/// As above, corner areas signed by the reference normal.
double quad_jacobian(const QuadNodes& p, const Eigen::Vector3d& normal);

/// |X1_hat . X2_hat|. Range [0, 1]; square 0; rhombus |cos a|; acceptable
/// [0, 0.5]. Degenerate axis: 0 (as Verdict).
double quad_skew(const QuadNodes& p);

/// |X12| / min(|X1|, |X2|). Range [0, inf); parallelogram 0; acceptable
/// [0, 0.7]. Degenerate axis: kDegenerate.
double quad_taper(const QuadNodes& p);

/// Max aspect Frobenius: (1/2) max over corners of (|e_in|^2 + |e_out|^2) /
/// |e_in x e_out|. Range [1, inf); square 1; acceptable [1, 1.3]. A corner
/// with zero area: kDegenerate.
double quad_max_aspect_frobenius(const QuadNodes& p);

/// Longest / shortest edge. Range [1, inf); square 1; acceptable [1, 1.3].
/// Zero-length edge: kDegenerate.
double quad_edge_ratio(const QuadNodes& p);

/// 2 min over corners of a_k / (|e_in|^2 + |e_out|^2). Range [0, 1];
/// square 1; acceptable [0.3, 1]. Zero-length edge or negative: 0.
double quad_shape(const QuadNodes& p);
/// As above, corner areas signed by the reference normal.
double quad_shape(const QuadNodes& p, const Eigen::Vector3d& normal);

/// Verdict's relative size squared: R = area / average_area with area =
/// (a_0+a_1+a_2+a_3)/4, value min(R, 1/R)^2. Range [0, 1]; acceptable
/// [0.3, 1]. area <= 0 or average_area <= 0: 0.
double quad_relative_size(const QuadNodes& p, double average_area);

/// Area (a_0+a_1+a_2+a_3)/4 against the own normal: what
/// quad_relative_size compares.
double quad_size(const QuadNodes& p);

}  // namespace cooperage::quality
