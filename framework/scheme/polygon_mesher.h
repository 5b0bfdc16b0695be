// A 2D polygon quad mesher as an interface (DESIGN.md: schemes never include
// each other). Cooper meshes its virtual and imprinted subcaps -- pieces of
// caps that are not model surfaces, so no SurfaceView exists for them -- in
// a plane through this interface (Blacker 1996, sec. 6.1: "each stack can
// be meshed by simply meshing either the first or the last cap ... the
// paving algorithm is currently used"). The pave scheme's 2D core
// (schemes/pave/pave_2d.h, pave::pave_2d) is the intended implementation;
// the registration code wraps it and hands it to the schemes that need it.
#pragma once

#include <Eigen/Core>

#include <array>
#include <vector>

namespace cooperage::scheme {

/// A 2D quad mesh: the boundary nodes first, in the input order (loop by
/// loop) and at exactly their input positions; quads counter-clockwise.
struct QuadMesh2D {
  std::vector<Eigen::Vector2d> points;
  std::vector<std::array<int, 4>> quads;
  int boundary_count = 0;
};

class PolygonMesher {
 public:
  virtual ~PolygonMesher() = default;
  /// Meshes the domain bounded by `loops` with quads, adding no node on the
  /// boundary. \param[in] loops outer loop counter-clockwise first, then
  /// holes clockwise; each a closed ring without repetition, every loop with
  /// an even number of nodes. Throws MeshingError on failure.
  virtual QuadMesh2D mesh(const std::vector<std::vector<Eigen::Vector2d>>& loops) const = 0;
};

}  // namespace cooperage::scheme
