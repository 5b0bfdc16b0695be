// The cooper plan of one volume, computed once and carried from
// applicable() to constrain(), roles() and mesh() (Blacker 1996, sec. 3-4):
// facts -> a sorting into caps and sides (cap_candidates.h) -> the side
// lattice -> the sweep order -> slabs and regions -> the barrel tree ->
// who meshes each cap -> the interval rows. One code path: a one-to-one
// sweep is the tree with one barrel. A priori: never meshes.
#pragma once

#include "schemes/cooper/barrel_constraints.h"
#include "schemes/cooper/cap_roles.h"
#include "schemes/cooper/elements.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/settings.h"

#include <optional>
#include <set>
#include <string>
#include <vector>

namespace cooperage::cooper {

/// The journal's optional sweep hints for one volume; binding: a plan
/// honours them or refuses naming `where`.
struct SweepHints {
  std::vector<int> sources;             ///< surfaces to sweep from (upper caps)
  std::vector<int> targets;             ///< surfaces to sweep to (lower caps)
  std::optional<geom::Vec3> direction;  ///< the sweep direction (upper caps to lower caps)
  std::string where;                    ///< "job.xml:12", the journal line, or ""
};

struct PlanInputs {
  SweepHints hints;
  Elements elements = Elements::Hex;
  bool polygon_mesher = false;  ///< imprinted pieces can be meshed in 2D
  /// The job's settings, passed to the side and cap schemes' applicable()
  /// (submap's vertex types); null: defaults.
  const scheme::Settings* settings = nullptr;
  /// Shared surfaces the neighbours' schemes already mesh or keep (the
  /// selector): of the plans that work, one that takes the former as caps
  /// meshed beforehand and meshes none of the latter is chosen first.
  scheme::NeighbourMeshes neighbours;
};

struct VolumePlan {
  bool ok = false;
  std::string why;   ///< a sentence: the plan, or the reason for refusing
  double score = 0;  ///< one barrel in [0.5, 0.9], several in [0.3, 0.45]
  /// The refusal is the paper's Fig. 3a (virtual faces projecting in
  /// different directions): decompose the volume.
  bool needs_decomposition = false;
  int volume = 0;
  Elements elements = Elements::Hex;
  std::string candidate;  ///< the sorting that gave the plan
  /// One barrel: its main upper cap (the source; with its subcaps, a
  /// composite cap) and its lower cap (the target); else 0.
  int source = 0;
  int target = 0;
  std::optional<geom::Vec3> down;  ///< the straight sweep direction, if any
  VolumeFacts facts;
  SideLattice lattice;
  SweepOrder order;
  SlabRegions slabs;
  BarrelTree tree;
  CapRoles roles;
  std::vector<IntervalRow> rows;                 ///< for constrain()
  std::vector<AlongPair> along_pairs;            ///< for constrain(): side_along_pairs()
  /// Refused: the step that refused (1 lattice, 2 order, 3 slabs, 4 tree,
  /// 5 cap roles, 6 hints); the furthest candidate is reported.
  int stage = 0;

  bool one_barrel() const { return tree.barrels.size() == 1; }
};

/// The direction the sweep leaves its upper caps: the straight axis, else
/// the inward normal of the one-barrel source at its centre.
geom::Vec3 sweep_direction(const VolumePlan& plan);

/// Plans a volume for the cooper sweep.
VolumePlan plan_volume(const geom::Model& model, int volume_id, const scheme::Registry& registry,
                       const PlanInputs& inputs);

/// The barrel tree as text for a person (cooperage plan): barrels with
/// their levels, sides, upper and lower caps (real caps with who meshes
/// them, virtual caps with the barrel on the other side) and the imprint
/// operation each barrel needs.
std::string describe_plan(const VolumePlan& plan);

/// The imprint operation a barrel needs (Blacker 1996, sec. 5): "match"
/// (one piece on each end), "subtract" (several pieces on one end), or
/// "imprint" (several on both: subtraction, intersection, seaming).
std::string imprint_operation(const BarrelNode& barrel);

}  // namespace cooperage::cooper
