// Step (b) of pave_2d: the coarse boundary. Every loop of 2m nodes becomes a
// coarse loop of m vertices (every other node); the skipped nodes become the
// midpoints of the coarse loop edges when the coarse mesh is split into quads.
// A loop of 2m + 1 nodes becomes m + 1 vertices, one coarse edge spanning a
// single fine edge (an "odd edge" without midpoint).
// The parity (odd or even nodes) is chosen per loop so that the worst
// skipped node is best: a skipped node's angle is always split between two
// quads, while a coarse vertex gets as many cells as its angle needs; so
// sharp corners and reflex corners should be coarse vertices. Also here:
// the ring around 4-node holes, paving's corner template at reflex tips,
// and the seeds of the first coarse row.
#pragma once

#include "schemes/pave/quad_quality_2d.h"

#include <Eigen/Core>

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace cooperage::pave::detail {

struct CoarseBoundary {
  std::vector<int> fine_of_coarse;      ///< fine node of each coarse vertex
  std::vector<Eigen::Vector2d> points;  ///< coarse vertex positions
  std::vector<double> sizes;            ///< target coarse edge length at each
  /// Fewest coarse cells each coarse vertex needs, by FASTQ's node class of
  /// its interior angle: END < 135 deg 1, SIDE < 225 2, CORNER < 315 3, else 4.
  std::vector<int> min_cells;
  std::vector<std::vector<int>> loops;              ///< coarse loops (coarse ids)
  std::unordered_map<std::uint64_t, int> midpoint;  ///< coarse loop edge -> skipped fine node
  /// Coarse loop edges spanning a single fine edge (odd loops have an odd
  /// number, loops whose parity switches at corners any number): no
  /// midpoint; parity_paths() pairs them through the interior.
  std::vector<std::uint64_t> odd_edges;
  /// Paving's first row at the coarse level: for every coarse vertex on a
  /// flat stretch (interior angle 150..210 deg), a point one coarse size
  /// inward along the bisector; recombination then finds rectangles along
  /// the boundary, and the split gives two rows of quads parallel to it.
  std::vector<Eigen::Vector2d> seeds;
  std::vector<int> seed_from;  ///< coarse vertex of each seed
  std::vector<double> seed_sizes;
};

/// True when the coarse polygon of parity `offset` has the orientation of the
/// loop and at least 5% of its area (it does not fold).
bool coarse_loop_valid(const std::vector<Eigen::Vector2d>& points, const std::vector<int>& loop,
                       size_t offset);

/// Loop positions of the coarse vertices of `loop`. A single parity: even
/// loops choose_parity(), odd loops one odd edge where the worst skipped
/// node is best (odd_rank > 0 takes a worse place, for retries). With
/// corner_angle > 0 [rad], corner_picks() instead (the parity switches so
/// every corner is a coarse vertex; on holes reflex corners up to 250 deg)
/// when that lifts the worst skipped node by at least 0.2 and its coarse
/// polygon does not fold. Throws
/// std::runtime_error when no single parity gives a valid coarse loop.
/// When those picks make a coarse loop whose edges cross (a chord over a
/// skipped node cutting across a sliver of the face), the first single
/// parity (even loops) or odd-edge place (odd loops) whose loop does not.
std::vector<size_t> loop_picks(const std::vector<Eigen::Vector2d>& points,
                               const std::vector<int>& loop, int odd_rank, double corner_angle);

/// loop_picks() before the crossing check: the best skipped node's choice.
std::vector<size_t> preferred_picks(const std::vector<Eigen::Vector2d>& points,
                                    const std::vector<int>& loop, int odd_rank,
                                    double corner_angle);

/// Builds the coarse loops of the fine loops (fine node ids into `points`),
/// their vertices by loop_picks(). Throws std::runtime_error when a loop has
/// no valid coarse loop. With `odd_full_size`, an odd edge of a loop of 8 or
/// more coarse vertices counts at the full coarse size in the point sizes
/// (for the frontal fill, whose size field the loop sizes set; the
/// circumcentre refinement keeps the finer sizes, whose extra room the
/// parity paths of small faces need).
CoarseBoundary coarse_boundary(const std::vector<Eigen::Vector2d>& points,
                               const std::vector<std::vector<int>>& loops, bool seed_rows = true,
                               int odd_rank = 0, double corner_angle = 0.0,
                               bool odd_full_size = false);

/// The parity (0: even nodes, 1: odd nodes are coarse vertices) of loop L:
/// the one whose worst skipped node is best (a skipped node's angle is split
/// between two quads: quality sin(angle / 2)); ties go to the parity that
/// puts the sharper corners on coarse vertices.
size_t choose_parity(const std::vector<Eigen::Vector2d>& points, const std::vector<int>& loop);

/// Worst sin(angle / 2) over the nodes that parity `offset` skips.
double skipped_quality(const std::vector<Eigen::Vector2d>& points, const std::vector<int>& loop,
                       size_t offset);

/// Paving's corner template at every skipped node (loop_picks() with
/// `corner_angle`; even loops only)
/// whose interior angle exceeds `limit` [rad] and whose id is below
/// `first_new` (given nodes only: the template's own nodes are never
/// wrapped): three quads around the node, 4 new loop nodes. Appends nodes and
/// quads; returns the new loop (or the same loop when nothing was wrapped).
/// A tip whose template would cross or enclose a part of `loop` or of
/// `other_loops` (a hole next to the tip) is not wrapped.
std::vector<int> wrap_reflex_tips(const std::vector<int>& loop, double limit, int first_new,
                                  std::vector<Eigen::Vector2d>& points, std::vector<Quad>& quads,
                                  double corner_angle = 0.0,
                                  const std::vector<std::vector<int>>& other_loops = {});

/// Surrounds the 4-node hole `loop` (clockwise) with a ring of 8 quads: the
/// 4x4 lattice of the hole's bilinear map extrapolated by `width` hole widths.
/// Appends the 12 new nodes to points (free) and the quads to quads; returns
/// the new clockwise 12-node loop.
std::vector<int> ring_around_small_hole(const std::vector<int>& loop, double width,
                                        std::vector<Eigen::Vector2d>& points,
                                        std::vector<Quad>& quads);

}  // namespace cooperage::pave::detail
