// simplify_faces: fewer faces for a picture of a big surface mesh, by vertex
// clustering (J. Rossignac, P. Borrel, "Multi-resolution 3D approximations
// for rendering complex scenes", 1993): nodes in one cell of a uniform grid
// merge into their mean; faces that collapse are dropped, duplicates merged.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <vector>

namespace cooperage::report {

/// Quads and triangles over a point list; faces[i][3] == -1 for a triangle.
/// values holds one number per face (the report's scaled Jacobian).
struct FaceSoup {
  std::vector<Eigen::Vector3d> points;
  std::vector<std::array<int, 4>> faces;
  std::vector<double> values;
};

/// The finest clustering grid (cells along the longest bounding box side,
/// up to 4096) whose result has at most `max_faces` faces; `in` unchanged
/// when it already has no more. A kept face takes the lowest value of the
/// faces merged into it and of the faces that collapsed onto its corners, so
/// a poor element stays visible. Deterministic.
/// @param[in] in         faces to simplify
/// @param[in] max_faces  the budget (>= 1)
FaceSoup simplify_faces(const FaceSoup& in, std::size_t max_faces);

}  // namespace cooperage::report
