// The one flattener of Cooperage: a face's boundary loops in a plane where
// lengths and angles are close to the surface's, and the way back to the
// surface, for every scheme that meshes in 2D (pave, tri, quad-dominant).
//
// * Planes: an orthonormal frame of the plane (origin at the first node, x
//   along the first edge): exact, and a rigidly moved face gives the same
//   coordinates.
// * Other faces: the parameters (u, v) of the nodes (a node the global
//   projection put on a far sheet of the face, away from both neighbours,
//   projected again from them: loop_parameters.cpp), continuous across
//   periodic seams, poles opened into segments (loop_parameters.h), each
//   direction scaled by the mean |dS/du|, |dS/dv| over the nodes. Where that
//   plane keeps the surface's angles (on a background triangulation, every
//   triangle's conformal distortion sigma_max / sigma_min <= max_distortion:
//   cylinders, mild B-splines) it is the chart, points going back through
//   S(u, v). Elsewhere (cones, spheres, tori, distorted B-splines, poles)
//   the background triangulation, placed on the surface, is flattened by a
//   least-squares conformal map (conformal_map.h) and the chart is that
//   flat triangulation: a plane point goes back by its barycentric
//   coordinates in the flat triangle holding it, interpolating (u, v), then
//   through S(u, v). Pole points merge into the pole node.
// * Loops that touch at a shared node (a hole meeting the outer loop at a
//   vertex) are merged into one loop through the node twice, its copies
//   moved a little apart (touching_loops.h); sources() says which loop
//   node every chart point is.
// * The chart is checked: its loops must be simple and properly nested
//   (outer loop counter-clockwise, holes clockwise inside it, nothing
//   crossing); the first candidate that passes is used; none: MeshingError.
#pragma once

#include "framework/geometry/evaluators.h"
#include "framework/mesh2d/touching_loops.h"

#include <Eigen/Core>

#include <memory>
#include <string>
#include <vector>

namespace cooperage::mesh2d {

class TriangleLocator;

struct ChartOptions {
  /// Largest conformal distortion (sigma_max / sigma_min of the map plane ->
  /// surface on any background triangle) of the scaled (u, v) plane; above
  /// it the conformal map is used. 1.15 keeps right angles within ~8 deg.
  double max_distortion = 1.15;
  /// Background triangles per boundary spacing across (the conformal map's
  /// resolution): its triangles are refined to this fraction of the local
  /// boundary spacing.
  double background_size = 0.7;
};

class SurfaceChart {
 public:
  enum class Kind { Plane, ScaledUv, Conformal };

  /// \param[in] surface  the face's geometry (must outlive the chart)
  /// \param[in] loops    boundary node positions, loop by loop (closed rings,
  ///                     outer first, the face on the left against the
  ///                     natural normal; a seam node appears twice, a pole once)
  /// Throws MeshingError(MeshingFailed) when no chart gives valid loops.
  SurfaceChart(const geom::SurfaceGeometry& surface,
               const std::vector<std::vector<geom::Vec3>>& loops, const ChartOptions& options = {});
  ~SurfaceChart();
  SurfaceChart(SurfaceChart&&) noexcept;

  /// The loops in the plane: outer loop counter-clockwise, holes clockwise;
  /// as given, unless loops touching at a node were merged.
  const std::vector<std::vector<Eigen::Vector2d>>& loops_2d() const { return loops_2d_; }
  /// Per point of loops_2d(): the input loop and index it stands for.
  const std::vector<std::vector<LoopPointRef>>& sources() const { return sources_; }
  /// The surface point of a plane point.
  geom::Vec3 to_3d(const Eigen::Vector2d& x) const;
  /// The natural unit normal of the surface at a plane point.
  geom::Vec3 normal_at(const Eigen::Vector2d& x) const;
  /// The surface parameters of a plane point.
  geom::Vec2 uv_at(const Eigen::Vector2d& x) const;
  Kind kind() const { return kind_; }
  /// True when the plane had to be mirrored because the loops disagree with
  /// the natural normal: counter-clockwise in the plane is then clockwise
  /// about the normal.
  bool mirrored() const { return mirrored_; }
  /// "plane", "scaled (u, v)" or "conformal map".
  std::string describe() const;

 private:
  void make_plane(const std::vector<std::vector<geom::Vec3>>& loops);
  void make_curved(const std::vector<std::vector<geom::Vec3>>& loops, const ChartOptions& options);

  const geom::SurfaceGeometry& surface_;
  Kind kind_ = Kind::Plane;
  bool mirrored_ = false;
  geom::Vec3 origin_ = geom::Vec3::Zero(), ex_ = geom::Vec3::UnitX(), ey_ = geom::Vec3::UnitY(),
             normal_ = geom::Vec3::UnitZ();
  double su_ = 1.0, sv_ = 1.0;  ///< ScaledUv: plane = (u su, v sv)
  /// Conformal: per flat triangle its corners' (u, v).
  std::vector<std::array<geom::Vec2, 3>> corner_uv_;
  std::unique_ptr<TriangleLocator> locator_;
  std::vector<std::vector<Eigen::Vector2d>> loops_2d_;
  std::vector<std::vector<LoopPointRef>> sources_;
};

/// Why the loops are not a valid planar domain (a loop with fewer than 3
/// points, repeated consecutive points, crossing or touching segments, an
/// outer loop that is not counter-clockwise, a hole that is not clockwise or
/// not inside the outer loop), or "" when they are. Exact predicates.
std::string invalid_loops(const std::vector<std::vector<Eigen::Vector2d>>& loops);

}  // namespace cooperage::mesh2d
