// Smoothing of a 2D all-quad mesh that never inverts an element (step (e) of
// the pave pipeline, pave_2d.h).
//
// 0. Untangling first (Freitag & Plassmann 2000): the free nodes of quads
//    with a non-positive corner maximise the worst corner area by pattern
//    search, so the later steps start from a valid mesh.
// 1. Gauss-Seidel sweeps over the free nodes towards the length-weighted
//    Laplacian of the edge neighbours dx_i = sum |e_ij| e_ij / sum |e_ij|
//    (FASTQ's paving smoother, Blacker & Stephenson 1991 sec. 6), optionally
//    blended with the isoparametric (parallelogram) rule x_i = mean over its
//    quads of (x_prev + x_next - x_opposite) (Herrmann 1976). A move is
//    kept only if the worst scaled Jacobian of the node's quads does not get
//    worse (or stays above `keep_quality` while the mean improves); else half
//    the move is tried. Inverted quads can therefore only improve.
// 2. Local optimisation of the nodes next to poor quads: a pattern search
//    that maximises the worst scaled Jacobian of the node's quads (the
//    "optimisation-based" smoothing of Canann, Tristano & Staten 1998).
// 3. Polish of the nodes next to fair quads (below 0.9): a short pattern
//    search maximising the mean scaled Jacobian of the node's quads without
//    lowering the worst (near irregular nodes the Laplacian places nodes by
//    position, not by shape); last, so that it cannot trap step 2.
#pragma once

#include "schemes/pave/quad_quality_2d.h"

#include <Eigen/Core>

#include <vector>

namespace cooperage::pave::detail {

struct SmoothOptions {
  int sweeps = 12;           ///< maximum Gauss-Seidel sweeps (more hardly change the quality)
  double tolerance = 0.005;  ///< stop when the largest move < tolerance * mean edge length
  double keep_quality =
      0.6;  ///< a move may lower the worst quality down to this if the mean improves
  double optimise_below = 0.8;  ///< nodes of quads worse than this get the pattern search
  int optimise_rounds = 10;
  /// Rounds of the polish: nodes of quads worse than polish_below maximise
  /// the mean quality of their quads without lowering their worst.
  int polish_rounds = 1;
  double polish_below = 0.9;
  /// Weight of the parallelogram rule against the length-weighted Laplacian;
  /// 0 measured best on the benchmark faces (median scaled Jacobian).
  double parallelogram_weight = 0.0;
};

/// Moves the free nodes (fixed[i] == 0) of the counter-clockwise quads.
/// \return the number of Laplacian sweeps made
int smooth_quads_2d(std::vector<Eigen::Vector2d>& points, const std::vector<Quad>& quads,
                    const std::vector<char>& fixed, const SmoothOptions& options = {});

}  // namespace cooperage::pave::detail
