// The lattice of the side faces (Blacker 1996, sec. 3: "a side face must
// admit a submapping mesh and the combination of all adjacent side faces
// must also admit a submapped mesh", Fig. 4/5). Every curve use of a side
// face runs along the caps (it stays on one level) or across them (it links
// two levels): cap curves run along; walking a side loop, a SIDE corner
// keeps the role and an END or CORNER corner swaps it. Faces without a cap
// curve (a face stacked between two others along the sweep: the cylinder
// under a countersink's cone, a band split off by imprinting) take the
// role of a curve they share with a neighbour. Vertices joined by curves
// running along, and the vertices of one cap, form level classes; maximal
// runs of linking uses are the chains between them (the layers of the
// barrels). Plain data: testable without CAD.
#pragma once

#include "schemes/cooper/volume_facts.h"

#include <map>
#include <set>
#include <string>
#include <vector>

namespace cooperage::cooper {

/// A maximal run of linking uses in one side face loop.
struct LinkChain {
  int face = 0;
  std::vector<int> curves;    ///< loop order
  std::vector<bool> forward;  ///< per curve: walked from its start vertex
  int from_vertex = 0;        ///< where the run starts (loop order)
  int to_vertex = 0;
  int from_class = -1;  ///< level classes of the two ends
  int to_class = -1;
  /// +1 or -1: the chain's direction in its face's lattice (the same for
  /// every chain of a face that runs the same way).
  int lattice_sign = 1;
  double length = 0;  ///< summed curve lengths
};

/// Where a side face meets a cap (a curve of the cap's loop `cap_loop`).
struct CapContact {
  int face = 0;
  int cap = 0;
  int cap_loop = 0;  ///< 0 the cap's outer loop, >= 1 a hole loop
  int curve = 0;
  bool convex = true;  ///< dihedral below pi (else re-entrant)
  /// The side face lies on this side (+1: +j, -1: -j) of the run in its
  /// lattice (it lies on the left of its loop).
  int leaving_sign = 1;
  int level_class = -1;
};

/// A curve running along between two side faces (stacked sides).
struct StackedCurve {
  int curve = 0;
  int face = 0;
  int leaving_sign = 1;  ///< as CapContact::leaving_sign, in `face`
  int level_class = -1;
};

/// A side's corner typed otherwise than its angle alone says, to agree
/// with its neighbours (side_corner_types.h): submap must type it so too.
struct RetypedCorner {
  int surface = 0;
  int vertex = 0;
  int turn = 0;  ///< END 1, SIDE 0, CORNER -1
};

struct SideLattice {
  bool ok = false;
  std::string why;                ///< for !ok: a sentence naming the faces
  std::vector<int> caps;          ///< ascending
  std::vector<int> sides;         ///< ascending
  std::set<int> along;            ///< curves of the sides and caps running along
  std::vector<LinkChain> chains;  ///< by face, then loop order
  std::vector<CapContact> contacts;
  std::vector<StackedCurve> stacked;
  std::map<int, int> vertex_class;  ///< vertex id -> level class
  int classes = 0;
  /// The first chain curve where two sides meet at a knife edge (see
  /// kMinSideDihedral), as a sentence naming them; empty when none. Not a
  /// refusal here: one barrel sweeps it (with poor elements at the edge).
  std::string knife_edge;
  std::map<int, int> cap_class;  ///< cap face -> level class
  /// Per side face: its level classes (those of its runs along).
  std::map<int, std::vector<int>> face_classes;
  /// Ribs leaving a cap tangentially: their first interval must be at least
  /// first_size long (the interval constraints grade the curve `along`).
  std::vector<TangentDeparture> graded;
  std::vector<RetypedCorner> retyped;
};

/// Upper bound of an end cap's dihedral angle with its sides [degrees]; the
/// paper's bound is pi, a small margin keeps tangent (180) joints out.
inline constexpr double kMaxCapDihedral = 175.0;
/// Dihedral angle [degrees] above which a side meets a cap re-entrantly (a
/// shoulder: the cap is a virtual subcap there); between the two, tangent.
inline constexpr double kReentrantMin = 185.0;

/// Per side face with exactly two curves running along the caps (its rings
/// of ribs on two levels, one curve each): that pair. The sweep links node k
/// of one ring to node k of the next, so the two must be spaced alike: a
/// size function graded by a feature near one of them only (a thin strip of
/// one cap, curve_sizing.h) shears the ribs by elements
/// (pyocc_face_recognition: 18 mm over a 40 mm barrel at size 12).
struct AlongPair {
  int a = 0, b = 0;
  /// +1: a and b run the same way (the face's loop walks them in opposite
  /// senses), so fraction s of a faces fraction s of b; -1: s faces 1 - s;
  /// 0: not known (closed rings, rings on two loops).
  int orientation = 0;
  /// A ring ends in a corner under kSliverRingCorner on another face of its
  /// own (its cap): uniform spacing there lets the first chord cross the
  /// corner's other curve.
  bool sliver_end = false;
};
/// A corner this sharp [degrees] at a ring's end keeps its grading.
inline constexpr double kSliverRingCorner = 10.0;
std::vector<AlongPair> side_along_pairs(const VolumeFacts& facts, const SideLattice& lattice);

/// Two side faces meeting along the sweep within this angle [degrees] of
/// folding flat (dihedral below it, or above 360 minus it: faces tangent at
/// a cusp, which the sampled dihedral reports as 0 or 360) form a knife
/// edge: every hexahedron along it has a scaled Jacobian of at most
/// sin(angle) (0.14 at 8 degrees). At 10 degrees the plan => mesh campaign
/// refused three parts whose walls meet at 8.6-9.5 degrees; at 8 they mesh
/// and none of its other 997 parts changes.
inline constexpr double kMinSideDihedral = 8.0;

/// Fills f.directions, f.directions_why and f.ambiguous_corners from
/// f.angles (t = END 1, SIDE 0, CORNER -1 per corner, d_0 = 0, d_k = d_{k-1}
/// + t_k mod 4; none when a corner has no type, is a REVERSAL, or the turns
/// do not close). gather_facts() calls it for every single-loop face.
void type_corners(FaceFact& f);

/// Whether side_lattice() refuses `f` as a side whatever the caps are:
/// several loops, not submappable, or corners that give no lattice and wait
/// for no neighbour (not ambiguous). Every sorting must make it a cap.
bool cannot_be_side(const FaceFact& f);

/// Roles, chains, contacts and level classes for `caps` (every other face
/// of the volume is a side). Not ok when a side has several loops, is not
/// submappable, has a corner without a type or a REVERSAL, its roles cannot
/// be decided or contradict a neighbour's, meets a cap tangentially with a
/// rib that bends out of the volume or does not rise kTangentLiftDeg off
/// the cap within its first curve, or a chain links a level to itself.
SideLattice side_lattice(const VolumeFacts& facts, const std::set<int>& caps);

}  // namespace cooperage::cooper
