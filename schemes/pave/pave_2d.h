// The 2D core of the pave scheme: unstructured all-quad meshing of a planar
// domain bounded by closed loops of given boundary nodes. Pure function on
// value types; no CAD (the SurfaceScheme in pave_scheme.h maps surfaces to 2D).
//
// Algorithm (a documented alternative to classic paving, Blacker &
// Stephenson 1991, with the same contract: all quads, boundary nodes given
// and untouched, any number of holes, sizes taken from the boundary):
//  (a) canonical frame (translation, rotation, scale, snapping) so that a
//      rigidly moved input gives the moved mesh;
//  (b) every loop's nodes are split into "coarse" vertices (every other
//      node, the parity chosen so that the worst skipped node is best) and
//      skipped nodes (coarse_loops.h); a hole with 4 nodes first gets a ring
//      of 8 quads (a 12-node loop), and a skipped reflex tip (> 250 deg)
//      paving's corner template (3 quads, the loop grows by 4 nodes);
//  (c) constrained Delaunay triangulation of the coarse loops (cdt_2d.h):
//      in the first attempt, rows of right triangles grown inward from the
//      loops along a cross field (frontal_fill.h: paving's rows at the
//      coarse level); in the others, seeded with a point 0.72 coarse sizes
//      inward of every flat coarse vertex; then refined by circumcentres to
//      about twice the local boundary spacing (circumradius bound, tuned so
//      the final mesh has ~1 quad per spacing^2): sizes grade smoothly
//      between loops of different spacing by interpolation; the output is
//      renumbered along a Hilbert curve so later steps stay cache-local;
//  (d) recombination of triangle pairs into quads, greedy by quality plus
//      augmenting paths; triangles left on the boundary move inward
//      (recombine.h);
//  (e) every quad split into 4 and every triangle into 3 quads
//      (split_to_quads.h): a coarse loop edge's midpoint is exactly the skipped
//      boundary node, so no node is added on the boundary; the boundary rows
//      are quads with an edge on the boundary;
//  (f) cleanup (doublets, diamonds; optionally on OpenMesh's half-edge mesh
//      with edge rotation, halfedge_cleanup.h) and smoothing that never inverts
//      (cleanup_2d.h, smooth_2d.h); checks: every quad valid, the quads
//      tile the domain exactly.
//  Odd loops: a loop with an odd node count keeps one coarse edge without
//  midpoint (an odd edge), and a loop whose corners are an odd number of
//  intervals apart switches parity with odd edges between them, so that
//  every corner is a coarse vertex; odd edges are paired by paths of coarse cells that lose their
//  midpoints too (parity_paths.h), so only the total must be even, as in
//  paving. The frontal mesh is kept at once when very good (median >= 0.98,
//  no quad below 0.7); else the circumcentre mesh is made too and the
//  better kept. A failed attempt, or one whose worst quad is below
//  retry_below, is retried with other settings (up to 5 retries; the best
//  valid attempt wins).
// Requirement: an even total node count and at least 4 nodes per loop.
#pragma once

#include "schemes/pave/halfedge_cleanup.h"
#include "schemes/pave/smooth_2d.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <vector>

namespace cooperage::pave {

/// Where pave_2d's time goes: the calling thread's CPU seconds per step, summed over attempts
/// (for benchmarks; filled only when PaveOptions::stats is set).
struct PaveStats {
  double boundary = 0;     ///< (b) coarse loops, rings, tips
  double triangulate = 0;  ///< (c) refined constrained Delaunay triangulation
  double recombine = 0;    ///< (d) recombination and parity paths
  double split = 0;        ///< (e) all-quad split
  double cleanup = 0;      ///< (f) doublets and diamonds
  double smooth = 0;       ///< (f) untangling, Laplacian sweeps, optimisation
  double check = 0;        ///< (f) inversion and tiling checks
  int attempts =
      0;  ///< settings tried (1 if the frontal mesh is very good, 2 if not, more when retried)
  int kept = 0;    ///< index of the attempt kept (with PaveOptions::frontal: 0 frontal, 1
                   ///< circumcentre, 2.. retries)
  int sweeps = 0;  ///< Laplacian sweeps of the last attempt made (not necessarily the kept one)
};

struct PaveOptions {
  detail::SmoothOptions smooth;     ///< the final smoothing
  double recombine_quality = 0.35;  ///< worst scaled Jacobian of a recombined coarse quad
  double max_radius = 0.9;     ///< coarse triangles' circumradius bound, in local sizes (CdtInput)
  bool frontal = true;         ///< rows of right triangles from the loops first (frontal_fill.h)
  double accept_radius = 0.8;  ///< circumradius a frontal triangle may keep, in local sizes
  double ring_width = 0.75;    ///< ring around a 4-node hole, in hole widths
  double tip_angle =
      250.0;  ///< skipped nodes above this interior angle [deg] get paving's corner template
  bool cleanup = true;  ///< remove doublets, collapse diamonds
  /// Clean up on OpenMesh's half-edge mesh with edge rotation
  /// (halfedge_cleanup.h) instead of the arrays (cleanup_2d.h). Off: it
  /// lowers irregular nodes by 3-5 % but some faces' minimum scaled
  /// Jacobian by more than noise, at 30x the arrays' time (bench/RESULTS.md,
  /// 2026-12-02 session 4).
  bool halfedge_cleanup = false;
  detail::HalfEdgeCleanupOptions halfedge;  ///< its settings
  bool boundary_rows = true;                ///< seed a coarse row along flat boundary stretches
  double retry_below =
      0.5;  ///< worst scaled Jacobian below which other settings are tried too (the issue's bar)
  int odd_edge_rank =
      0;  ///< where odd loops put their odd edge (0: best place; retries use others)
  /// Loop nodes with an interior angle below this or above 360 minus this
  /// [deg] are corners: the parity may switch along a loop (odd edges) so
  /// they become coarse vertices (corner_picks.h); 0 keeps one parity per loop.
  double corner_angle = 140.0;
  bool check_inversion = true;  ///< throw on an inverted quad (off: inspect a failed mesh)
  PaveStats* stats = nullptr;   ///< [out] step timings when set (reset by pave_2d)
};

/// A 2D quad mesh: boundary nodes first, in the input order (loop by loop),
/// at exactly their input positions; quads counter-clockwise.
struct QuadMesh2D {
  std::vector<Eigen::Vector2d> points;
  std::vector<std::array<int, 4>> quads;
  int boundary_count = 0;
};

/// Meshes the domain bounded by `loops` with quads.
/// \param[in] loops  outer loop counter-clockwise first, then holes clockwise;
///                   each a closed ring of boundary points without repetition
/// \throws MeshingError(InvalidInput) for an odd total node count (no
///         all-quad mesh exists), loops with fewer than 4 nodes, loops with
///         the wrong orientation or holes outside the outer loop;
///         MeshingError(MeshingFailed) when the loops intersect or an
///         element would be inverted. The error carries no entity; callers add it.
QuadMesh2D pave_2d(const std::vector<std::vector<Eigen::Vector2d>>& loops,
                   const PaveOptions& options = {});

}  // namespace cooperage::pave
