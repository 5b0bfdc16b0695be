// The scheme interfaces (docs/design.md; the seed brief "Core types"): every surface and volume
// scheme answers applicable() a priori (from topology and angles, never by
// meshing), states its interval constraints, and meshes. A scheme is
// registered once and holds no per-job state: the job reaches it as
// Settings (settings.h) and its own analysis of an entity as the plan its
// applicable() returned (applicability.h), both through the views.
#pragma once

#include "framework/geometry/model.h"
#include "framework/intervals/interval_problem.h"
#include "framework/mesh/mesh_db.h"
#include "framework/scheme/applicability.h"
#include "framework/scheme/role.h"
#include "framework/scheme/settings.h"

#include <map>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace cooperage::scheme {

/// The settings of a job as mesh() used to take them; the one settings
/// type is Settings (settings.h). Kept so plug-in sources still compile.
using MeshParams = Settings;

/// A surface as a scheme sees it. `mesh` holds the meshed curves of its loops
/// during mesh(); it is null during applicable() and constrain(). `job` is
/// the run's Settings (null: defaults, settings()); `plan` is what this
/// scheme's applicable() returned for the same surface and settings, as the
/// selector kept it (null when the caller has none: a scheme then computes
/// its plan again; carried_plan()).
struct SurfaceView {
  const geom::Model& model;
  int surface_id = 0;
  const mesh::MeshDB* mesh = nullptr;
  const Settings* job = nullptr;
  const PlanData* plan = nullptr;

  const geom::Surface& surface() const { return model.surface(surface_id); }
  const Settings& settings() const { return job ? *job : Settings::none(); }
};

/// What the schemes chosen for the neighbours fix about shared surfaces
/// (the selector's choices so far): a scheme that can plan around them
/// should, since the selector refuses a plan that contradicts them.
struct NeighbourMeshes {
  /// A neighbour meshes these itself (a sweep ends on them or imprints
  /// them): this volume must take them as it finds them.
  std::set<int> made;
  /// A neighbour needs these from their surface scheme and does not take a
  /// volume's mesh (a sweep's side): this volume must not mesh them itself.
  std::set<int> kept;
  /// The surface scheme the neighbour needs on each of `kept` (submap on a
  /// sweep's side, the cap scheme on its source): needing another scheme
  /// there conflicts too (a wedge sweep's caps need triangles).
  std::map<int, std::string> kept_schemes;
  /// Meshing these itself would close a cycle of volumes waiting for each
  /// other's meshes (a ring of sweeps round an axis, each taking the last
  /// one's target as its source): a sweep ending on one should take the
  /// mesh it finds there, which the ring made from its own source.
  std::set<int> closing;
};

/// A volume as a scheme sees it; `mesh` holds its meshed surfaces during
/// mesh(); `job` and `plan` as in SurfaceView. `neighbours` is set by the
/// selector during applicable() (null elsewhere: nothing known).
struct VolumeView {
  const geom::Model& model;
  int volume_id = 0;
  const mesh::MeshDB* mesh = nullptr;
  const Settings* job = nullptr;
  const PlanData* plan = nullptr;
  const NeighbourMeshes* neighbours = nullptr;

  const geom::Volume& volume() const { return model.volume(volume_id); }
  const Settings& settings() const { return job ? *job : Settings::none(); }
};

/// The plan a view carries when it is of the scheme's own type `T` (made by
/// its applicable()), else null: the scheme then computes it from the view.
template <class T, class View>
const T* carried_plan(const View& view) {
  return dynamic_cast<const T*>(view.plan);
}

/// New elements for one entity, in local node numbering. Local node k is the
/// existing MeshDB node `global[k]` when that is >= 0, or a new node at
/// `coords[k]` when it is -1, owned by `owners[k]` if given, else by the
/// entity being meshed.
struct EntityMesh {
  std::vector<int> global;
  std::vector<geom::Vec3> coords;
  std::vector<mesh::NodeOwner> owners;  ///< empty, or one per local node
  std::vector<mesh::Quad> quads;
  std::vector<mesh::Tri> tris;
  std::vector<mesh::Hex> hexes;
  std::vector<mesh::Wedge> wedges;
  /// Optional: the scaled Jacobian (quality::hex_scaled_jacobian,
  /// wedge_scaled_jacobian) of every hex / wedge, in element order, computed
  /// on exactly the coordinates the mesh ends up with. The run's quality
  /// report takes them instead of computing every element again. Leave a
  /// vector empty unless it holds one value per element.
  std::vector<double> hex_scaled_jacobian, wedge_scaled_jacobian;
  /// Volume schemes only: the elements of surfaces the volume scheme meshes
  /// itself (role kMeshedByVolume, e.g. cooper's target caps), oriented with
  /// each surface's natural normal.
  std::map<int, std::vector<mesh::Quad>> surface_quads;
  std::map<int, std::vector<mesh::Tri>> surface_tris;
  /// Sentences for a person about what the scheme had to give up (a
  /// fallback, a relaxed goal); the pipeline reports them with the entity
  /// in MeshResult::warnings. Never used for errors.
  std::vector<std::string> warnings;

  /// Adds a local node; returns its local index.
  int add(const geom::Vec3& x, int global_node = -1) {
    global.push_back(global_node);
    coords.push_back(x);
    if (!owners.empty()) owners.push_back({});
    return static_cast<int>(coords.size()) - 1;
  }
  /// Adds a new node with an explicit owner (e.g. a node on a target cap).
  int add_owned(const geom::Vec3& x, mesh::NodeOwner owner) {
    if (owners.size() != coords.size()) owners.resize(coords.size());
    global.push_back(-1);
    coords.push_back(x);
    owners.push_back(owner);
    return static_cast<int>(coords.size()) - 1;
  }
};

class SurfaceScheme {
 public:
  virtual ~SurfaceScheme() = default;
  virtual std::string_view name() const = 0;
  /// The roles a volume scheme may give it (flags); None: free surfaces only.
  virtual Role serves() const { return Role::None; }
  /// A priori: can this scheme mesh the surface? Never meshes. May return
  /// its plan (Applicability::plan), which the later calls get back in view.plan.
  virtual Applicability applicable(const SurfaceView& view) const = 0;
  /// Adds the constraints this scheme needs on the surface's curve intervals.
  virtual void constrain(const SurfaceView& view, intervals::IntervalProblem& problem) const = 0;
  /// Meshes the surface; its curves are meshed in view.mesh. `settings` is
  /// the run's (the pipeline also sets view.job to it). Throws MeshingError.
  virtual EntityMesh mesh(const SurfaceView& view, const Settings& settings) const = 0;
};

/// Which surface scheme a volume scheme needs on each of its surfaces.
using SurfaceRoles = std::map<int, std::string>;
/// The role of a surface the volume scheme meshes itself, inside mesh().
inline constexpr const char* kMeshedByVolume = "(volume)";

class VolumeScheme {
 public:
  virtual ~VolumeScheme() = default;
  virtual std::string_view name() const = 0;
  virtual Applicability applicable(const VolumeView& view) const = 0;
  virtual void constrain(const VolumeView& view, intervals::IntervalProblem& problem) const = 0;
  /// The surface schemes this volume scheme imposes, e.g. {side: submap}.
  virtual SurfaceRoles roles(const VolumeView& view) const = 0;
  /// Surfaces among roles() whose mesh the scheme takes as it finds it: any
  /// valid mesh with the agreed curve intervals (cooper's uncut source caps).
  /// A neighbouring volume scheme that meshes such a surface itself (role
  /// kMeshedByVolume, e.g. the other volume's sweep ends on it) is then
  /// meshed first, and this volume reads its mesh (docs/design.md, "Volumes
  /// that wait for a neighbour").
  virtual std::vector<int> takes_existing_mesh(const VolumeView& /*view*/) const { return {}; }
  /// The one surface a one-to-one sweep starts from, whose image its other
  /// end's mesh is (0: not such a sweep). The selector closes a ring of
  /// sweeps onto an existing mesh only when both ends' meshes come from one
  /// surface's mesh (NeighbourMeshes::closing).
  virtual int sweep_source(const VolumeView& /*view*/) const { return 0; }
  /// Vertex types of its surfaces the plan relies on where a surface scheme
  /// alone might classify otherwise (a side's corner between two types,
  /// typed to agree with its neighbours); the selector hands them to the
  /// surface schemes as if the journal pinned them.
  virtual std::vector<io::VertexTypeSetting> vertex_types(const VolumeView& /*view*/) const {
    return {};
  }
  /// After the interval solve, before the curves are meshed: where the
  /// nodes of the volume's curves go along them, given every curve's count
  /// (`sizes` holds the size functions so far; a sweep puts the nodes of
  /// the curves between its caps on the caps' levels). Default: as they are.
  virtual void space_curves(const VolumeView& /*view*/, const std::map<int, int>& /*counts*/,
                            std::map<int, mesh::SizeFunction>& /*sizes*/) const {}
  /// Meshes the volume; its surfaces are meshed in view.mesh. `settings` is
  /// the run's (the pipeline also sets view.job to it). Throws MeshingError.
  virtual EntityMesh mesh(const VolumeView& view, const Settings& settings) const = 0;
  /// Whether the scheme can make wedges (journal `elements="wedge"` or
  /// "mixed", Settings::elements()); the selector offers only such schemes
  /// for those volumes.
  virtual bool makes_wedges() const { return false; }
};

}  // namespace cooperage::scheme
