// Volume classification (Blacker 1996, sec. 3): sort the faces of a volume
// into side faces (jointly submappable, linking the caps) and caps, with the
// end caps' dihedral angles below pi. Part I accepts one barrel: exactly two
// caps, the source and the target, every other face a side linking them.
// The source cap may be composite: a face plus coplanar faces filling its
// hole loops (subcaps touching no side, Blacker 1996, sec. 4-5).
// A priori: never meshes (asks the registry's surface schemes applicable()).
#pragma once

#include "framework/geometry/model.h"
#include "framework/scheme/registry.h"
#include "framework/scheme/vertex_angles.h"
#include "schemes/cooper/elements.h"

#include <optional>
#include <set>
#include <string>
#include <vector>

namespace cooperage::cooper {

/// The journal's optional sweep hints for one volume.
struct SweepHints {
  std::vector<int> sources;              ///< source surface ids (part I: at most one)
  std::vector<int> targets;              ///< target surface ids (part I: at most one)
  std::optional<geom::Vec3> direction;   ///< rough sweep direction (source to target)
};

/// A side face of the barrel and how its loop splits.
struct SideFace {
  int surface = 0;
  std::vector<int> source_curves;  ///< its curves on the source cap boundary
  std::vector<int> target_curves;  ///< its curves on the target cap boundary
  /// Linking (sweep-direction) curves, as maximal chains between the caps,
  /// each in loop order.
  std::vector<std::vector<int>> linking_chains;
  /// Touches more than two caps or spans a cap's level (a stepped ring,
  /// part II): its runs balance by its own submap constraints, not as
  /// source = target.
  bool spans_caps = false;
};

struct Classification {
  bool ok = false;
  std::string why;           ///< a sentence naming the volume, faces and rule
  double score = 0.0;        ///< in [0, 1]
  int source = 0;            ///< source cap surface
  int target = 0;            ///< target cap surface
  /// The best quad-cap scheme (map, submap, pave or a plug-in's); wedge
  /// mode the best tri-cap scheme ("tri"); mixed mode "map", "submap" or
  /// "quad_dominant" (see Elements::Mixed)
  std::string source_scheme;
  /// Composite source cap (Blacker 1996, sec. 4-5: a cap made of subcaps):
  /// faces of the volume, coplanar with `source`, each filling one hole
  /// loop of it and touching no side; meshed by their own surface schemes
  /// (`source_subcap_schemes`, same order) and swept with the source as one
  /// cap mesh. Empty for a single-face source cap.
  std::vector<int> source_subcaps;
  std::vector<std::string> source_subcap_schemes;
  /// Indices of the source surface's loops that bound the cap (the loops
  /// not filled by subcaps); empty: all of them.
  std::vector<int> source_loops;
  std::vector<SideFace> sides;  ///< ascending surface id
};

/// Upper bound of an end cap's dihedral angle with its sides [degrees]; the
/// paper's bound is pi, a small margin keeps tangent (180) joints out.
inline constexpr double kMaxCapDihedral = 175.0;
/// Dihedral angle (degrees) above which a side meets a cap re-entrantly (a
/// shoulder: the cap is a virtual subcap there); between the two, tangent.
inline constexpr double kReentrantMin = 185.0;

/// Classifies the faces of a volume for a one-barrel sweep.
/// \param[in] model      the model
/// \param[in] volume_id  the volume
/// \param[in] registry   supplies the schemes serving sweep sides (submap) and caps
/// \param[in] hints      optional source/target/direction; obeyed or rejected with a reason
/// The choice is deterministic and independent of the order of the faces:
/// candidate cap pairs are ranked by (direction hint,) loops, curves, area,
/// ids; the source is the cap with more loops, then curves, then area, then
/// the lower id, unless only the other one has a surface scheme.
/// \param[in] elements   the cap schemes: hex mode the quad-cap schemes; wedge
///                       mode the tri-cap ones ("tri", swept into wedges);
///                       mixed mode map/submap or "quad_dominant" (Elements::Mixed)
Classification classify_faces(const geom::Model& model, int volume_id,
                              const scheme::Registry& registry, const SweepHints& hints = {},
                              Elements elements = Elements::Hex);

namespace detail {

/// Empty when surface `side` (one loop, submappable, its outer-loop corners
/// given) links cap curve sets `upper_curves` and `lower_curves` as a side
/// (Blacker 1996, sec. 3: one run on each cap, END/CORNER at the cap/link
/// junctions, SIDE inside runs); else a sentence why not. Fills `out`
/// (source_curves = upper run, target_curves = lower run, linking chains).
std::string check_side(const geom::Model& model, int side,
                       const std::vector<scheme::LoopCorner>& corners, int upper,
                       const std::set<int>& upper_curves, int lower,
                       const std::set<int>& lower_curves, SideFace& out);

/// The best-scoring applicable scheme serving sweep sides (submap), or "".
std::string side_scheme(const geom::Model& model, const scheme::Registry& registry, int surface);

/// The best-scoring applicable scheme serving quad caps (map, submap, pave,
/// plug-ins; ties: registration order), or "" with `why` set.
std::string cap_scheme(const geom::Model& model, const scheme::Registry& registry, int surface,
                       std::string& why);
/// The cap scheme of an element kind: hex mode as above, wedge mode the best
/// tri-cap scheme ("tri"), mixed mode the best mixed-cap scheme, an all-quad
/// one (map, submap) only where it reaches kMixedMinQuadQuality, else
/// "quad_dominant".
std::string cap_scheme(const geom::Model& model, const scheme::Registry& registry, int surface,
                       std::string& why, Elements elements);

}  // namespace detail

}  // namespace cooperage::cooper
