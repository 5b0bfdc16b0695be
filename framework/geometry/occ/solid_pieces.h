// The solids of a workbench as separate pieces that can be cut by a plane, a
// cylinder or a cone and turned back into a model: what the automatic decomposition
// (framework/decompose/) works on. No OCCT type appears here.
#pragma once

#include "framework/geometry/model.h"
#include "framework/geometry/occ/workbench.h"

#include <memory>
#include <string>
#include <vector>

namespace cooperage::occ {

/// An unbounded cutting surface. Plane: through `origin` with unit normal
/// `direction`. Cylinder: axis through `origin` along unit `direction`,
/// radius `radius` (> 0). Cone: axis through `origin` along unit
/// `direction`, radius `radius` (> 0) at `origin`, growing along
/// `direction` at `half_angle` (radians, in (0, pi/2)); it stops short of
/// its apex.
struct CutSurface {
  enum class Kind { Plane, Cylinder, Cone };
  Kind kind = Kind::Plane;
  Vec3 origin = Vec3::Zero();
  Vec3 direction = Vec3::UnitZ();
  double radius = 0.0;
  double half_angle = 0.0;
  /// Cylinder and cone: where their seam lies (a direction off the axis;
  /// zero: any). A seam through the vertices of the curves the cut runs
  /// along keeps the cut face a plain annulus.
  Vec3 seam = Vec3::Zero();
  /// Distance within which the kernel takes the cut to run along existing
  /// edges (0: exact): a cone through two B-spline circles of a CAD model
  /// passes them only within their fitting error.
  double fuzzy = 0.0;
};

/// Solids (and free faces) in model volume order: piece i is volume i + 1 of
/// build_model(). Copies are cheap (the kernel shapes are shared handles).
class SolidPieces {
 public:
  SolidPieces();
  ~SolidPieces();
  SolidPieces(const SolidPieces&);
  SolidPieces& operator=(const SolidPieces&);
  SolidPieces(SolidPieces&&) noexcept;
  SolidPieces& operator=(SolidPieces&&) noexcept;

  /// The solids Workbench::build_model(options) numbers as volumes 1..n,
  /// imprinted and merged as it does.
  static SolidPieces of(const Workbench& bench, const BuildOptions& options = {});

  /// Number of solids.
  int size() const;

  /// Solid `index` (0-based) alone, with its name.
  SolidPieces only(int index) const;

  /// The solids of cutting solid `index` by `cut`, in the kernel's
  /// (deterministic) order; fewer than 2 when the cut misses the solid's
  /// interior. Throws MeshingError(GeometryError) when the kernel fails.
  SolidPieces split(int index, const CutSurface& cut) const;

  /// The vertices of solid `index`, then `per_curve` points inside each of
  /// its edges (evenly in parameter): the points decompose::volume_samples
  /// takes from its model, without building one (a piece too thin to keep
  /// is told from them before its model is built).
  std::vector<Vec3> boundary_samples(int index, int per_curve) const;

  /// These solids with solid `index` replaced by all solids of `pieces`
  /// (which keep the name of the replaced one).
  SolidPieces replace(int index, const SolidPieces& pieces) const;

  /// The model of the solids and free faces. imprint_merge: fragment them
  /// again so touching solids share faces (needed after cuts that cross a
  /// neighbour's face; the pieces of one split share their cut faces
  /// already). Volumes keep the solid order. Throws MeshingError.
  /// `glue`: solids known only to touch are glued (OCCT's gluing skips the
  /// intersections of faces that do not coincide: a third faster), which is
  /// exact only while that holds; the decomposition checks a glued model it
  /// meshes against the part (same skin and volume) and else fuses in full.
  geom::Model build_model(bool imprint_merge, bool glue = false) const;

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace cooperage::occ
