// Automatic decomposition (issue 17; Blacker 1996, sec. 3 calls lifting the
// hand decomposition of Fig. 3 "a natural next step"): every volume that no
// volume scheme applies to is cut, by planes, cylinders and cones taken from
// its own faces and edges, into pieces that a scheme applies to, the best cut
// first, recursively and within bounds. The pieces are then imprinted and
// merged with everything else, so the mesh is conformal by construction.
#pragma once

#include "framework/decompose/cut_surface.h"
#include "framework/geometry/model.h"
#include "framework/geometry/occ/solid_pieces.h"
#include "framework/scheme/registry.h"

#include <functional>
#include <string>
#include <vector>

namespace cooperage::decompose {

struct DecomposeOptions {
  double size = 0.0;  ///< element size (> 0): no piece thinner than one layer across a cut
  int max_cuts = 80;  ///< candidate cuts given to the kernel, per volume in all
  int max_depth = 3;  ///< cuts along one chain (a cut, a cut of a piece, ...)
  int branches = 2;   ///< cuts that leave pieces to cut again, explored per level
  int threads = 0;    ///< threads judging the cuts of a level (0: all cores); same result for any
  /// The job's settings (null: defaults), for every a-priori verdict on the
  /// volume and its pieces; per-entity settings never reach a decomposition
  /// (the pipeline refuses them first: cuts renumber the entities).
  const scheme::Settings* settings = nullptr;
};

/// A volume to which no volume scheme applies, and every scheme's reason.
struct RefusedVolume {
  int volume = 0;
  std::string why;
};

/// One cut of the decomposition.
struct AppliedCut {
  CutSurface surface;
  std::string through;    ///< "plane of surface 12" (the part's ids, part_ids.h)
  int depth = 0;          ///< 0: cut of the volume itself; 1: of one of its pieces, ...
  int pieces = 0;         ///< solids it gave
  double thinnest = 0.0;  ///< thinnest of them across the cut, model units
};

/// The decomposition of one volume of the input model.
struct VolumeDecomposition {
  int volume = 0;  ///< id before decomposition
  std::string name;
  std::string why;  ///< every volume scheme's refusal of the whole volume
  /// "no hex scheme applies" (or wedge, mixed: the element kind asked)
  std::string refusal = "no hex scheme applies";
  std::vector<AppliedCut> cuts;
  int tried = 0;            ///< candidate cuts given to the kernel
  std::vector<int> pieces;  ///< its pieces' ids in the decomposed model
};

struct Report {
  std::vector<VolumeDecomposition> volumes;  ///< the volumes that were cut, by id
  int tried = 0;                             ///< candidate cuts given to the kernel in all
  double seconds = 0.0;                      ///< time of the search (wall clock)
  /// Ids of the decomposed model: volume -> id of the volume it is part of
  /// in the input model (identity when nothing was cut).
  std::vector<int> origin;
};

/// Whether a model (the pieces of a cut) plans as a whole: "" when it does,
/// else the reason (the pipeline passes its planner, which checks shared
/// faces' schemes and interval feasibility). Without `rings`, a plan with
/// a ring of sweeps (SchemePlan::ring_closers) does not count: the search
/// takes one only as its last resort (CutSearch::solve_meridian).
using ModelCheck = std::function<std::string(const geom::Model&, bool rings)>;

struct Decomposed {
  geom::Model model;  ///< `model` itself when nothing was cut
  Report report;
};

/// Cuts every volume of `model` (built from `solids`, volume i + 1 being
/// solid i) to which no volume scheme of `registry` applies.
/// @throws MeshingError(NotApplicable) naming the volume, every scheme's
///         refusal, the number of cuts tried and why the best left a piece
///         unmeshable; MeshingError(InvalidInput) for a size that is not
///         positive. Deterministic: the same cuts for any thread count and
///         for a rigid motion of the part (candidates are ordered by ids).
Decomposed decompose(const occ::SolidPieces& solids, const geom::Model& model,
                     const scheme::Registry& registry, const ModelCheck& check,
                     const DecomposeOptions& options);
/// The same, for the volumes refused_volumes() found (computed once by a
/// caller that needed them already).
Decomposed decompose(const occ::SolidPieces& solids, const geom::Model& model,
                     const scheme::Registry& registry, const ModelCheck& check,
                     const DecomposeOptions& options, const std::vector<RefusedVolume>& refused);

/// The volumes of `model` to which no volume scheme applies for the job's
/// `settings` (null: defaults), ascending, with the reasons.
std::vector<RefusedVolume> refused_volumes(const geom::Model& model,
                                           const scheme::Registry& registry,
                                           const scheme::Settings* settings = nullptr);

/// The volumes of `model` to which no volume scheme applies for the job's
/// `settings` (null: defaults), ascending.
std::vector<int> unmeshable_volumes(const geom::Model& model, const scheme::Registry& registry,
                                    const scheme::Settings* settings = nullptr);

}  // namespace cooperage::decompose
