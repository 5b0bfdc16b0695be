// Constrained Delaunay triangulation of closed 2D polygon loops with
// size-driven Delaunay refinement (the "coarse" triangulation of the pave
// scheme, see pave_2d.h). Value types in, value types out; no CAD.
//
// Construction: Bowyer-Watson insertion of the loop points into a super
// triangle, constraint recovery by edge flips (Sloan 1993, "A fast algorithm
// for generating constrained Delaunay triangulations"), Lawson flips to
// restore the constrained Delaunay property, outside/hole removal by parity
// flood fill, then refinement by circumcentre insertion (Ruppert 1995 /
// Shewchuk's "Delaunay refinement") with a constrained Bowyer-Watson cavity
// that never crosses a loop edge. Loop edges are never split: a circumcentre
// that encroaches a loop edge or lies behind one is not inserted.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <vector>

namespace cooperage::pave::detail {

/// A triangulation as plain arrays.
struct Triangulation2D {
  std::vector<Eigen::Vector2d>
      points;  ///< input points first (in input order), then Steiner points
  std::vector<std::array<int, 3>> tris;  ///< counter-clockwise, inside the loops only
};

struct CdtInput {
  std::vector<Eigen::Vector2d> points;  ///< all loop points
  std::vector<double> sizes;            ///< target edge length at each point, > 0
  std::vector<std::vector<int>> loops;  ///< closed rings of point indices: outer CCW, holes CW
  bool refine = true;                   ///< insert interior points at the local size
  /// Refinement splits a triangle whose circumradius R exceeds max_radius
  /// times the local size h, or 0.7 max_radius h with an edge shorter than
  /// R / 1.1. Delaunay refinement leaves triangles well below the bound, so
  /// 0.9 (an equilateral triangle of edge up to 1.56 h passes) gives about
  /// one fine quad per (h/2)^2 after recombination and the split; 0.64 gave
  /// ~1.7.
  double max_radius = 0.9;
  /// Before the refinement, grow rows of right triangles from the loops
  /// (frontal_fill.h) accepting circumradii up to accept_radius sizes; the
  /// seeds are then not used.
  bool frontal = false;
  double accept_radius = 0.8;
  /// Per loop point (may be empty): the fewest triangles it must end up in. A
  /// flat loop vertex (180 deg) needs 2, else its quad would have a straight
  /// angle; extra points are inserted on the bisector of its widest triangle.
  std::vector<int> min_triangles;
  /// Points to insert before refinement (paving's first row at the coarse
  /// level): seed k lies near loop point seed_from[k] and is dropped when it
  /// is behind a loop edge, encroaches one, or comes closer than half its
  /// size to a point.
  std::vector<Eigen::Vector2d> seeds;
  std::vector<int> seed_from;
  std::vector<double> seed_sizes;
};

/// Builds the refined constrained Delaunay triangulation of the loops.
/// Throws std::runtime_error when the loops intersect (constraint recovery
/// fails) or are degenerate; the caller turns it into a MeshingError.
Triangulation2D constrained_delaunay(const CdtInput& input);

}  // namespace cooperage::pave::detail
