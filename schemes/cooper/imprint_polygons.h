// Polygon work on node loops for subcap imprinting (Blacker 1996, sec. 5):
// loops of node ids with 2D coordinates (a barrel end projected along the
// barrel axis). Value types only.
#pragma once

#include <Eigen/Core>

#include <functional>
#include <map>
#include <optional>
#include <utility>
#include <vector>

namespace cooperage::cooper {

using Vec2 = Eigen::Vector2d;

/// A subcap of one barrel end: loops of node ids, outer loop first
/// (counter-clockwise in the barrel's 2D projection), holes clockwise.
struct Subcap {
  int id = 0;
  std::vector<std::vector<int>> loops;
};

/// Signed area of a loop (positive counter-clockwise).
double signed_area(const std::vector<int>& loop, const std::map<int, Vec2>& xy);
/// No area up to rounding: at most 1e-12 of its perimeter squared (a loop
/// walked along a line and back, a split along the subcap's own edges).
bool flat_loop(const std::vector<int>& loop, const std::map<int, Vec2>& xy);

/// The loops with the largest (the outer loop) first and counter-clockwise,
/// the others (holes) clockwise.
std::vector<std::vector<int>> oriented_loops(std::vector<std::vector<int>> loops,
                                             const std::map<int, Vec2>& xy);

/// The loops grouped by region: a loop inside an even number of the others
/// is an outer loop, one inside an odd number a hole of the innermost outer
/// loop holding it. A virtual cap across a fork (two prongs above one
/// ledge) has several outer loops; each region is its own subcap.
std::vector<std::vector<std::vector<int>>> separate_regions(
    const std::vector<std::vector<int>>& loops, const std::map<int, Vec2>& xy);

/// Splits closed loop `loop` (no repeated nodes) at its repeated or crossing
/// points into n + 1 loops (sec. 5.5). Crossings between segments are first
/// combined onto a node pair (the closer pair whose loops stay even when
/// `even_parity`); `combined` receives (removed node, kept node). A pair
/// `combinable` rejects (two nodes ribbed to different opposing nodes) is
/// taken only when no other pair of that crossing is left. Returns the
/// loops; counter-clockwise ones are caps, clockwise ones overlaps.
std::vector<std::vector<int>> split_self_intersections(
    const std::vector<int>& loop, const std::map<int, Vec2>& xy, bool even_parity,
    std::vector<std::pair<int, int>>* combined = nullptr,
    const std::function<bool(int, int)>& combinable = {});

namespace detail {

using Loop = std::vector<int>;

double cross(const Vec2& a, const Vec2& b);
/// The point of segment a-b nearest p.
Vec2 closest_on_segment(const Vec2& p, const Vec2& a, const Vec2& b);
/// The foot of p's perpendicular on segment a-b when it falls inside the
/// segment by more than 1e-9 of its length: a foot at an end, up to
/// rounding, is the end's (a moved part gave the other answer there).
std::optional<Vec2> foot_inside_segment(const Vec2& p, const Vec2& a, const Vec2& b);
/// Parameter on p0-p1 where it meets q0-q1 (touching included), if it does.
std::optional<double> segment_hit(const Vec2& p0, const Vec2& p1, const Vec2& q0, const Vec2& q1);
/// Even-odd point in polygon.
bool point_in_loop(const Vec2& p, const Loop& loop, const std::map<int, Vec2>& xy);
/// Inside the outer loop and outside every hole.
bool point_in_subcap(const Vec2& p, const Subcap& s, const std::map<int, Vec2>& xy);
/// Position of `node` in `loop`, -1 when absent.
int index_in(const Loop& loop, int node);
/// a and b are consecutive in the (cyclic) loop.
bool adjacent(const Loop& loop, int a, int b);
/// Splits a counter-clockwise loop by a path x -> interior -> y (x, y on the
/// loop): first = path + loop from y forward to x (the left side of the
/// path); second = reversed path + loop from x forward to y (sec. 5.2: the
/// caps b^ and b'). Both empty when x or y is not on the loop.
std::pair<Loop, Loop> split_loop(const Loop& loop, int x, const Loop& interior, int y);
/// A four-node loop with a corner whose sine is below 0.2 (nearly straight
/// or folded): meshed as one quad, it sweeps to a flat hex.
bool flat_quad(const Loop& loop, const std::map<int, Vec2>& xy);
/// A clockwise hole sharing an edge with counter-clockwise `outer` (the
/// region touches it): the hole joins the outer loop, which then runs around
/// it; false when they share no edge.
bool absorb_touching_hole(Loop& outer, const Loop& hole);
/// Loops of one subcap that share an edge (a split path run along a hole
/// leaves the two halves of one hole, or a hole touching the outer loop)
/// are joined: two holes become one, a hole joins the outer loop; true
/// when any were.
bool merge_touching_holes(std::vector<Loop>& loops);

/// Removes spikes p, q, p from a loop (an edge walked there and back, which
/// bounds nothing); true when one was removed.
bool remove_spikes(Loop& loop);
/// A point just on the material side of one of the hole's edges that is on
/// none of `outers`: it lies in the region owning the hole even when the
/// hole's nodes lie on the regions' boundaries.
Vec2 hole_owner_probe(const Loop& hole, const std::map<int, Vec2>& xy,
                      const std::vector<Loop>& outers);
/// Splits a loop at its first repeated node; false when none.
bool split_at_repeat(const Loop& loop, Loop& a, Loop& b);
/// The first pair of crossing segments (i, k), i < k, in the order of a
/// nested scan over i then k (segments sharing a node skipped), or none.
std::optional<std::pair<size_t, size_t>> first_crossing(const Loop& loop,
                                                        const std::map<int, Vec2>& xy);

}  // namespace detail
}  // namespace cooperage::cooper
