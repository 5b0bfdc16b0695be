// Subcap imprinting (Blacker 1996, sec. 5) on value types: the two ends of
// one barrel, projected along the barrel axis onto a plane (the least-squares
// map of the barrel's rings makes the projection of both ends agree on the
// exterior ribs), as polygons of node ids with 2D coordinates, plus the rib
// links between the ends. The result pairs every upper subcap with one lower
// subcap (a = Lambda_b, b = Lambda_a) whose boundaries are linked node for
// node by exterior and interior ribs.
//
// Terms (sec. 5): R-Gamma = loop nodes attached to a rib, S-Gamma = the rest;
// Gamma_ab = the part of a's loop whose ribs reach subcap b. Each step looks
// at one unmatched subcap a and one "gap" of its loop (a run of nodes
// without ribs, or a rib-to-rib edge whose partners are not adjacent on the
// opposing side):
//  * 5.1 matching: every node of a's loops is ribbed into b and vice versa;
//  * 5.2 subtraction: the gap's ribbed ends reach one opposing subcap b; the
//    gap (the non-shared boundary) is projected onto b, linked by interior
//    ribs, and b splits into b^ (a's side) and b'; a loop without any rib
//    (a subcap whose projection lies inside b) becomes a hole of b;
//  * 5.3 intersection: the gap's ends reach two different subcaps b and c;
//    the closest node p of the b/c boundary to the projected gap is chosen
//    so that the new cap's loop is even (all-quad), giving a^ on the lower
//    and a' on the upper end (reverse projection of Gamma_bp), matched;
//  * 5.4 seaming: a projected node within `seam_fraction` of the local edge
//    length of an opposing node without a rib is combined with it (never a
//    node on the exterior boundary, which carries an exterior rib);
//  * 5.5 self-intersection: a split loop that crosses or touches itself is
//    split into n + 1 loops at its n crossings (crossings are combined onto
//    nodes so that the loops stay even); inner loops (clockwise, overlaps)
//    are subtracted from the subcaps they overlap and become subcaps.
// Recategorisation: after every step the subcaps are classified again.
#pragma once

#include "schemes/cooper/imprint_polygons.h"

#include <array>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace cooperage::cooper {

/// One barrel's two ends in 2D. Upper and lower node ids are distinct.
struct BarrelEnds {
  std::map<int, Vec2> xy;                 ///< every node of both ends [model units]
  std::vector<Subcap> upper;              ///< subcaps of the upper cap
  std::vector<Subcap> lower;              ///< subcaps of the lower cap
  std::vector<std::pair<int, int>> ribs;  ///< (upper node, lower node): the exterior ribs
  /// Nodes of model curves: no node is inserted on an edge between two of them.
  std::set<int> fixed;
};

struct ImprintOptions {
  /// Seaming tolerance as a fraction of the shortest edge at the projected node (sec. 5.4).
  double seam_fraction = 0.3;
  bool even_parity = true;  ///< all-quad: every new loop even (sec. 5.3, 5.5)
  /// Bound on imprinting steps; imprinting also stops after 100 steps
  /// more than its ends have nodes (it is going round in circles then).
  int max_steps = 10000;
  /// Keep the ends as they were before each of the first `trace_steps`
  /// steps in ImprintResult::trace (for imprint_debug.h; 0: none).
  int trace_steps = 0;
};

enum class ImprintStep { Match, Subtract, Intersect, Seam, SelfIntersect };
const char* to_string(ImprintStep step);

struct ImprintResult {
  bool ok = false;
  std::string why;  ///< for !ok: which subcaps could not be resolved (their ids)
  /// For !ok: the same for a person, without the ids ("no imprinting step
  /// applies to the 4 subcaps left unmatched").
  std::string summary;
  /// The ends after imprinting: new nodes in xy, split subcaps (new ids
  /// above the input's), exterior + interior ribs.
  BarrelEnds ends;
  /// Matched subcap ids (upper, lower), ascending by upper id.
  std::vector<std::pair<int, int>> matches;
  /// Interior ribs created (upper node, lower node).
  std::vector<std::pair<int, int>> interior_ribs;
  /// Seams: (projected position's node on the other end, existing node it
  /// was combined with is the second) -- here (source node, existing node).
  std::vector<std::pair<int, int>> seams;
  std::vector<ImprintStep> steps;  ///< in order
  /// New subcap id -> the input subcap it was cut from.
  std::map<int, int> origin;
  /// For !ok: the subcaps no step could resolve, at the upper and lower end.
  std::array<std::vector<int>, 2> unmatched;
  /// With ImprintOptions::trace_steps: the ends (ribs so far included)
  /// before each step, and the step that came before it.
  std::vector<std::pair<BarrelEnds, std::string>> trace;
};

/// Imprints and matches the subcaps of one barrel's ends (sec. 5).
ImprintResult imprint_subcaps(const BarrelEnds& ends, const ImprintOptions& options = {});

}  // namespace cooperage::cooper
