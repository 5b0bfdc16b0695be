// A 2D polygon quad mesher as an interface (docs/design.md: schemes never include
// each other). Cooper meshes its virtual and imprinted subcaps -- pieces of
// caps that are not model surfaces, so no SurfaceView exists for them -- in
// a plane through this interface (Blacker 1996, sec. 6.1: "each stack can
// be meshed by simply meshing either the first or the last cap ... the
// paving algorithm is currently used"). The pave scheme's 2D core
// (schemes/pave/pave_2d.h, pave::pave_2d) is the intended implementation;
// the registration code wraps it and hands it to the schemes that need it.
// In wedge mode cooper uses a triangle implementation (framework/mesh2d), in
// mixed mode pave's 2D core with its poor quads split
// (framework/mesh/split_poor_quads.h), so a mesh may carry triangles too.
#pragma once

#include <Eigen/Core>

#include <array>
#include <vector>

namespace cooperage::scheme {

/// A 2D polygon mesh: the boundary nodes first, in the input order (loop by
/// loop) and at exactly their input positions; quads and triangles
/// counter-clockwise (triangles only from triangle / quad-dominant meshers).
struct QuadMesh2D {
  std::vector<Eigen::Vector2d> points;
  std::vector<std::array<int, 4>> quads;
  int boundary_count = 0;
  std::vector<std::array<int, 3>> tris{};
};

class PolygonMesher {
 public:
  virtual ~PolygonMesher() = default;
  /// Meshes the domain bounded by `loops` (quads, or triangles / both for
  /// the wedge and mixed meshers), adding no node on the boundary.
  /// \param[in] loops outer loop counter-clockwise first, then holes
  /// clockwise; each a closed ring without repetition (an all-quad mesher,
  /// and the quad-dominant one built on it, needs an even number of nodes
  /// in every loop). Throws MeshingError on failure.
  virtual QuadMesh2D mesh(const std::vector<std::vector<Eigen::Vector2d>>& loops) const = 0;
};

}  // namespace cooperage::scheme
