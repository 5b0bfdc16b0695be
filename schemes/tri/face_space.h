// The 2D space a face is triangulated in. Planar faces: an orthonormal frame
// of the plane attached to the face's first boundary node and segment (so a
// rotated face gives the same 2D numbers). Other faces: the surface's (u, v)
// parameters scaled per direction by the average |dS/du|, |dS/dv| over the
// boundary nodes (exact for cylinders), periodic seams unwrapped continuously
// along each loop, v mirrored when needed so that counter-clockwise in 2D is
// the right-hand rule about the natural normal.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

#include "framework/geometry/model.h"
#include "framework/mesh/mesh_db.h"

namespace cooperage::tri {

using geom::Vec2;
using geom::Vec3;

/// A face's boundary loops as closed node rings (the last node of a loop is
/// not repeated) and their images in the face's 2D space.
struct FlatFace {
  std::vector<std::vector<int>> nodes;   ///< MeshDB node per loop point
  std::vector<std::vector<Vec2>> loops;  ///< 2D point per loop point (seam nodes appear twice)
};

/// Maps between a face and its 2D triangulation space.
class FaceSpace {
 public:
  /// Builds the space from the face's meshed loops and flattens them.
  /// Throws MeshingError(MeshingFailed, surface) when a curve is not meshed,
  /// a loop does not close, or the parameterisation is degenerate.
  FaceSpace(const geom::Model& model, int surface_id, const mesh::MeshDB& db, FlatFace& out);

  /// The surface point of a 2D point (curved faces: S(u, v) projected onto the face).
  Vec3 point(const Vec2& p) const;
  /// Unit natural normal at (or near) a surface point x.
  Vec3 normal(const Vec3& x) const;
  bool planar() const { return planar_; }

 private:
  Vec2 flat_planar(const Vec3& x) const;

  const geom::Surface* surface_ = nullptr;
  bool planar_ = false;
  Vec3 origin_ = Vec3::Zero(), ex_ = Vec3::UnitX(), ey_ = Vec3::UnitY(), n_ = Vec3::UnitZ();
  double su_ = 1.0, sv_ = 1.0, vsign_ = 1.0;
};

/// Node rings of a surface's loops from its meshed curves (reversed for
/// Reversed uses, junction nodes once, the closing node dropped).
std::vector<std::vector<int>> loop_nodes(const geom::Model& model, int surface_id,
                                         const mesh::MeshDB& db);

}  // namespace cooperage::tri
