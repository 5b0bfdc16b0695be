// Candidate sortings of a volume's faces into caps and sides (Blacker 1996,
// sec. 3: "a cap face is simply defined as any face which is not a side
// face"; the first valid sorting wins), in order of preference:
//  1. one barrel: a pair of caps (plus the faces filling their hole loops,
//     subcaps of a composite cap), every other face a side; ranked by
//     loops, curves, area and ids, the better cap the upper one;
//  2. a straight axis: the hint, then the normals of planar faces with
//     holes, then of planar faces (id order); the caps are the faces
//     facing it within kCapFacing degrees, both directions along it;
//  3. a curved sweep with several barrels: the faces that cannot be sides
//     plus up to two more as caps (an elbow with a boss on its end).
// Plain data: testable without CAD.
#pragma once

#include "schemes/cooper/sweep_order.h"
#include "schemes/cooper/volume_facts.h"

#include <optional>
#include <set>
#include <string>
#include <vector>

namespace cooperage::cooper {

/// A cap faces the sweep axis when its normal is within this angle [degrees]:
/// 35 rather than 30, as a cone 31 degrees off the plane under a lug, swept
/// as a side, left hexes of scaled Jacobian 0.03 beside it (0.53 as a cap).
inline constexpr double kCapFacing = 35.0;

struct CapCandidate {
  enum class Kind { Pair, Axis, Curved };
  Kind kind = Kind::Pair;
  std::set<int> caps;
  OrderAnchor anchor;
  int source = 0;  ///< Pair: the upper cap (its composite subcaps follow it)
  int target = 0;  ///< Pair: the lower cap
  /// Pair: the orientation is fixed (hinted, composite): no flip.
  bool fixed = false;
  std::string label;  ///< "caps 3 and 5", "axis (0, 0, 1)", ...
};

/// Faces filling a hole loop of `host` (one outer loop equal to the hole's
/// curves, within 15 degrees of flat across them): subcaps of a composite cap.
std::vector<int> hole_fillers(const VolumeFacts& facts, int host);

/// Pair candidates, best first, oriented (source upper). `sources` /
/// `targets` restrict them (a hinted subcap names its host as the source).
std::vector<CapCandidate> pair_candidates(const VolumeFacts& facts, const std::vector<int>& sources,
                                          const std::vector<int>& targets, std::string& why);

/// Axes in order: `hint` alone when given, else normals of planar faces with
/// holes, then of planar faces. Unit vectors, deduplicated up to sign.
std::vector<geom::Vec3> candidate_axes(const VolumeFacts& facts,
                                       const std::optional<geom::Vec3>& hint);

/// The caps of an axis: the faces facing it within kCapFacing degrees.
std::set<int> caps_facing(const VolumeFacts& facts, const geom::Vec3& axis);

/// Curved candidates: faces that cannot be sides plus up to two others.
std::vector<CapCandidate> curved_candidates(const VolumeFacts& facts, size_t limit = 2000);

/// The direction a ring of faces leaves a hole loop in (the projection
/// direction of the virtual face filling it), for each hole loop of a
/// planar face whose neighbours meet it re-entrantly: (face, direction).
std::vector<std::pair<int, geom::Vec3>> virtual_face_directions(const VolumeFacts& facts);

/// "(0, 0, 1)": a direction for a sentence.
std::string direction_text(const geom::Vec3& v);

}  // namespace cooperage::cooper
