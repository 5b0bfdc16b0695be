// What one job asks of the schemes (docs/design.md, "Plans and settings"):
// the one settings type that reaches a scheme, read-only, through the views
// of applicable(), constrain(), roles() and as mesh()'s argument. Schemes
// are registered once and keep no per-job state; everything that differs
// from one job to the next (element kind and sweep hints per volume, submap
// vertex types, the size, whether a surface may fall back) is read here.
#pragma once

#include "framework/io/job.h"

#include <string>
#include <vector>

namespace cooperage::scheme {

struct Settings {
  double size = 1.0;  ///< target element size [model units]
  /// The surface mesh is the product (`--dim 2`), not the input of a volume
  /// scheme: a surface scheme that cannot reach its quality may fall back
  /// to another one, to quad-dominant or to triangles, saying so in
  /// EntityMesh::warnings, instead of failing. A volume scheme needs the
  /// surface meshes it imposed, so the pipeline leaves this off in 3D.
  bool allow_fallback = false;
  /// In 3D, for one surface whose mesh every volume it bounds takes as it
  /// finds it (cooper's uncut source caps: PlanEntry::any_quad_mesh): a
  /// structured scheme that fails there may fall back to the all-quad one
  /// (pave), saying so in EntityMesh::warnings; never to triangles.
  bool allow_quad_fallback = false;
  /// The job's <mesh> settings (per-volume element kinds, sweep hints and
  /// pins, vertex types, sizes); null: none (every default). It must
  /// outlive every call that is given these Settings.
  const io::MeshSettings* job = nullptr;

  /// The settings of one run: `job`'s size (else 1), falling back only
  /// when the surface mesh is the product (dim 2).
  static Settings of(const io::MeshSettings& job, int dim = 3);
  /// Defaults: no job (what a view without Settings gives).
  static const Settings& none();

  /// The job's <volume> setting of a volume, or null.
  const io::VolumeSetting* volume(int volume_id) const;
  /// The element kind asked of a volume (Hex unless the job says otherwise).
  io::ElementKind elements(int volume_id) const;
  /// "no hex scheme applies", "no wedge scheme applies" or "no mixed scheme
  /// applies": a volume's refusal names the element kind it was asked for.
  std::string no_scheme_applies(int volume_id) const;
  /// Vertex types the chosen volume schemes' plans rely on (cooper types a
  /// side's corner that lies between two types to agree with its
  /// neighbours); the selector sets them before it chooses the surfaces.
  /// Null: none. Must outlive every call given these Settings.
  const std::vector<io::VertexTypeSetting>* planned_vertex_types = nullptr;
  /// The hard vertex classifications (submap), every surface's: the
  /// journal's, then the planned ones.
  std::vector<io::VertexTypeSetting> vertex_types() const;
};

}  // namespace cooperage::scheme
