// The imprinting state machine of imprint_subcaps() (Blacker 1996, sec. 5):
// detail shared by imprint_subcaps.cpp (matching, subtraction, seaming,
// self-intersection), imprint_intersect.cpp (intersection, sec. 5.3) and
// imprint_join_holes.cpp (a subtraction between two holes).
#pragma once

#include "schemes/cooper/imprint_polygons.h"
#include "schemes/cooper/imprint_seam_choices.h"
#include "schemes/cooper/imprint_subcaps.h"

#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace cooperage::cooper::detail {

class Imprinter {
 public:
  Imprinter(const BarrelEnds& in, const ImprintOptions& options);
  ImprintResult run();

 private:
  std::vector<Subcap>& caps(int e) { return e == 0 ? r_.ends.upper : r_.ends.lower; }
  const std::map<int, Vec2>& xy() const { return r_.ends.xy; }
  bool matched(int cap) const { return match_of_.count(cap) > 0; }

  bool all_matched();
  /// "4 subcaps left unmatched" (after unmatched_list()).
  std::string left_unmatched() const;
  std::string unmatched_list();
  void finish();
  // Every rib so far, the interior ones too, into r_.ends.ribs: a failed
  // imprint's debug output (imprint_debug.h) shows where it got to.
  void export_ribs();
  // (upper node, lower node) of every rib so far, exterior and interior.
  std::vector<std::pair<int, int>> ribs_so_far() const;
  std::optional<int> partner(int e, int node) const;
  void link(int e, int node, int other);

  // Unmatched subcaps of end e whose loops contain node.
  std::vector<int> holders(int e, int node);

  // sec. 5.1: a is fully ribbed into b and b into a, loop for loop.
  bool try_matches();

  // Projects node v of end e onto end 1 - e (seaming onto an opposing node
  // without a rib when close, sec. 5.4, unless `seam` is false); returns
  // the opposing node.
  int project(int e, int v, const Loop& around, bool seam = true);
  // An edge of `chain` (a closed loop or an open path) crosses one of `loops`.
  bool crosses_any(const Loop& chain, bool closed, const std::vector<Loop>& loops) const;
  // Moves the chain's new nodes (ids from first_new) off the `obstacles`
  // they cross or nearly touch (imprint_clear_holes.cpp); false, nothing
  // moved, when it still crosses one.
  bool keep_clear(const Loop& chain, bool closed, const std::vector<Loop>& obstacles,
                  int first_new);
  int new_cap(int e, std::vector<Loop> loops, int parent);
  // sec. 5.2: a closed loop strictly inside subcap bi of end o cuts it; the
  // inside (with bi's holes in it) becomes a new subcap, whose id is returned.
  int subtract_inside(int o, size_t bi, const Loop& loop);

  // Replaces subcap index `bi` of end e by outer loops `pieces`, handing
  // out its holes to the piece containing them; returns their ids. Pieces
  // that cross or touch themselves are resolved first (sec. 5.5).
  std::vector<int> replace(int e, size_t bi, const std::vector<Loop>& pieces);
  void apply_combined(int e, const std::vector<std::pair<int, int>>& combined);

  // sec. 5.5: an overlap (a loop traversed clockwise after a subtraction)
  // lies inside other subcaps; it is subtracted from each and becomes a subcap.
  void subtract_overlap(int e, const Loop& piece);

  // A gap of loop l of subcap s (end e): consecutive ribbed nodes r0 -> r1
  // with the nodes between them unribbed (or none, when the partners are not
  // adjacent on an opposing subcap).
  bool try_gaps();
  // An empty gap whose ends are linked already, or the only one: nothing to do.
  bool skipped_gap(int e, const Loop& gap, int x, int y, size_t anchors);
  // A node of an unmatched subcap's hole of end o, on no unmatched outer loop.
  bool on_hole_only(int o, int node);
  // The ribbed positions of `outer` (end e) that end gaps.
  std::vector<size_t> gap_anchors(int e, const Loop& outer, const std::vector<size_t>& ribbed);
  bool opposing_edge(int e, int x, int y);
  bool crosses_opposing(int e, const Loop& la);

  // sec. 5.2: a subcap without any rib projects inside one opposing subcap.
  bool free_loop(int e, const Subcap& a);

  // Hole loops of a without ribs: projected as holes into the subcap of the
  // opposing end that holds a's outer image, plus a subcap filling each.
  bool hole_loops(int e, const Subcap& a);

  // A free loop crossing opposing boundaries (overlapping subcaps without
  // ribs, sec. 5.3): each crossing is combined onto the closest pair of an
  // unribbed node of a and an unribbed, non-exterior opposing node (sec. 5.4),
  // giving a's loop ribs; the gaps between them are then subtracted.
  bool free_crossing(int e, const Subcap& a);

  // sec. 5.2/5.4 when a free loop projects exactly onto an opposing loop (a
  // boss above a foot of the same footprint): every node seams onto its
  // opposing node, loop for loop; the subcaps then match (sec. 5.1).
  bool try_coincident();
  bool coincident_loop(int e, const Loop& la);
  // Splits subcap bi of end e along a path x -> path -> y between two nodes
  // of one of its hole loops: the piece between the path and one arc of the
  // hole becomes a subcap, the hole grows by it (sec. 5.2-5.3).
  bool split_hole(int e, size_t bi, int x, const Loop& path, int y);
  // Splits subcap bi of end e along x -> path -> y from its outer loop to a
  // hole that touches the outer loop at a node; false when there is none.
  bool split_pinched(int e, size_t bi, int x, const Loop& path, int y);
  // sec. 5.2: a's gap r0 -> path -> r1 runs from one loop of subcap bi of
  // the opposing end to another (holes, or a hole and the outer loop), and
  // a's loop goes on along that loop, by further gaps to further loops and
  // back to the first: all the gaps are projected, the piece they enclose
  // leaves bi and the loops join.
  bool join_holes(int e, const Subcap& a, int r0, const Loop& path, int r1, size_t bi);
  bool gap_step(int e, const Subcap& a, int r0, const Loop& gap, int r1);
  // sec. 5.2-5.3: the image x -> path -> y of a gap (path[j] the image of
  // gap[j], projected with seams or not) crosses one hole of subcap bi of
  // end 1 - e twice: the crossings are seamed onto nodes of the hole, bi is
  // split along path - hole arc - path and the gap's middle stays a gap
  // (imprint_gap_through_hole.cpp); x and y lie on bi's outer loop, or on
  // another of its holes, which then grows by the piece. False, nothing
  // changed, otherwise.
  struct Undo;
  bool gap_through_hole(int e, const Loop& around, const Loop& gap, const Loop& path, bool seamed,
                        int x, int y, size_t bi, const Loop& fresh, const Undo& undo);
  // sec. 5.2-5.3: x and y lie on one hole H of subcap bi and the image
  // x -> path -> y leaves bi into H and comes back: the two crossings are
  // seamed onto nodes of H, the parts of the path outside H cut pieces off
  // bi that join H, and the gap's middle, inside H, stays a gap
  // (imprint_gap_through_own_hole.cpp). False, nothing changed, otherwise.
  bool gap_through_own_hole(int e, const Loop& around, const Loop& gap, const Loop& path,
                            bool seamed, int x, int y, size_t bi, const Loop& fresh,
                            const Undo& undo);
  // The gap's images for a seam choice: gap nodes j1 and j2 seamed onto
  // hole nodes h1 and h2, those before j1 and after j2 projected, those
  // between left without an image (-1): they stay a gap.
  Loop project_with_seams(int e, const Loop& gap, const Loop& around, bool seamed,
                          const SeamChoice& c);
  // The ribs a gap's projection made (from the nodes in `fresh`, unribbed
  // before it), taken back when it split nothing.
  struct Undo {
    size_t interior_ribs, seams, steps;
    int next_node;
  };
  Undo undo_point() const;
  void roll_back(int e, const Loop& fresh, const Undo& undo);
  // sec. 5.3: the image x -> gap -> y of a gap of a, inside subcap bi of
  // the opposing end at both ends, leaves it across one of its loops and
  // comes back: both crossings are combined onto a node of the gap and a
  // free node of that loop, the lens kept even (imprint_gap_crossing.cpp).
  // False, nothing changed, for any other crossing.
  bool gap_crossing(int e, const Subcap& a, int x, const Loop& gap, int y, size_t bi);
  // A gap node lies outside subcap bi of the opposing end by more than a
  // tenth of its edges (`around` is the gap's loop, for their length).
  bool gap_leaves_subcap(int e, const Loop& gap, const Loop& around, size_t bi);
  // sec. 5.4: seams the gap's nodes onto the free nodes of an arc x -> y of
  // one of the `common` opposing subcaps' outer loops, the closest such arc
  // with as many nodes; false when there is none or seaming is off.
  bool seam_gap_to_arc(int e, const Loop& gap, int x, int y, const std::vector<int>& common);

  // sec. 5.3: the gap's ends reach two subcaps, b (at r1) and c (at r0).
  bool intersect(int e, const Subcap& a, int r0, const Loop& gap, int r1,
                 const std::vector<int>& hx, const std::vector<int>& hy);
  size_t index_of_cap(int e, int id);
  void insert_on_edge(int e, int u, int v, int w);
  ImprintOptions options_;
  ImprintResult r_;
  std::map<int, int> partner_[2];
  std::set<int> exterior_;
  std::map<int, int> match_of_;  // subcap id -> matched subcap id
  int next_node_ = 0;
  int first_new_node_ = 0;  // nodes below it were given (other barrels may share them)
  int next_cap_ = 0;
  /// Set by a step that finds the ends in a state it cannot split (a node
  /// it needs on a loop is not there): imprinting stops with this reason
  /// rather than walking a loop for a node it never meets.
  std::string abandoned_;
  long version_ = 0;  // bumped by every new rib and subcap: progress
};

}  // namespace cooperage::cooper::detail
