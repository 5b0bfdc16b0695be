// Quad-dominant meshes from triangulations: adjacent triangle pairs are
// merged into quadrilaterals where the quad is good, and the triangles left
// over stay triangles (Blacker 1996, abstract: "a wedge/hexahedral element
// mix ... by simply allowing ... mixed triangle/quadrilateral cap meshes").
// A triangle is left over only when no merge with a neighbour passes the
// quality threshold, or when the pairing cannot reach it: a greedy matching,
// best quad first, then augmenting paths (as in graph matching) that re-pair
// chains of quads to pair up two leftover triangles.
// cite: J.-F. Remacle et al., "Blossom-Quad: a non-uniform quadrilateral
// mesh generator using a minimum-cost perfect-matching algorithm", IJNME 89
// (2012) -- which uses an optimal matching where this uses greedy +
// bounded augmenting paths.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <vector>

#include "framework/mesh2d/triangulate.h"

namespace cooperage::mesh2d {

/// Settings of recombine().
struct RecombineOptions {
  /// Smallest accepted quad quality: the scaled Jacobian in 2D, min over the
  /// corners of sin(angle) (square 1; 0.5: every angle within [30, 150] degrees).
  double min_quad_quality = 0.5;
  /// Longest augmenting path, in quads re-paired (0: greedy only).
  int max_path_quads = 8;
};

/// A mixed 2D mesh: the points of the triangulation unchanged, quads and the
/// triangles left over, all counter-clockwise.
struct MixedMesh2D {
  std::vector<Eigen::Vector2d> points;
  std::vector<std::array<int, 4>> quads;
  std::vector<std::array<int, 3>> triangles;
  std::size_t boundary_count = 0;
};

/// Scaled Jacobian of the counter-clockwise quad (a, b, c, d): min over the
/// corners of the signed sine of the angle; <= 0 at a reflex or inverted corner.
double quad_quality(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                    const Eigen::Vector2d& d);

/// Merges triangle pairs of `t` into quads of quality >= min_quad_quality.
/// Deterministic and rotation invariant: qualities are compared after
/// rounding to 1e-9 and ties are broken by triangle indices, so a rigidly
/// moved triangulation (same connectivity) gives the same pairing.
MixedMesh2D recombine(const Triangulation2D& t, const RecombineOptions& options = {});

}  // namespace cooperage::mesh2d
