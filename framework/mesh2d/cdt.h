// The triangle store behind triangulate(): triangles with neighbour links and
// constrained-edge flags, point location by walking, Lawson insertion with
// edge flips, segment recovery by flipping (Sloan 1993) and inside/outside
// classification by crossing parity. Internal to framework/mesh2d.
// cite: C. L. Lawson, "Software for C1 surface interpolation" (1977);
// S. W. Sloan, "A fast algorithm for generating constrained Delaunay
// triangulations", Computers & Structures 47 (1993).
#pragma once

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "framework/mesh2d/predicates.h"

namespace cooperage::mesh2d::detail {

/// Relative tolerance for Delaunay ties: an edge is flipped only when the
/// in-circle determinant exceeds this fraction of its permanent, so
/// (nearly) cocircular points keep the triangulation they were built with and
/// a rigidly moved input, whose rounding differs, gives the same connectivity.
inline constexpr double kDelaunayTieTol = 1e-11;
/// A point closer than this fraction of an edge's length to the edge's line
/// is treated as lying on it.
inline constexpr double kOnEdgeTol = 1e-10;

/// Triangle t: vertices v (counter-clockwise); n[i] is the neighbour across
/// the edge opposite v[i] (-1: none), c[i] whether that edge is a constraint.
struct Tri {
  std::array<int, 3> v{{-1, -1, -1}};
  std::array<int, 3> n{{-1, -1, -1}};
  std::array<bool, 3> c{{false, false, false}};
  bool inside = false;
  std::uint32_t stamp = 0;  ///< changes whenever the triangle is rewritten
};

inline int nxt(int i) { return i == 2 ? 0 : i + 1; }
inline int prv(int i) { return i == 0 ? 2 : i - 1; }

class Cdt {
 public:
  enum class Where { Inside, OnEdge, OnVertex, Blocked, Outside };
  struct Location {
    Where where = Where::Outside;
    int tri = -1;
    int edge = -1;  ///< OnEdge / Blocked / Outside: the edge; OnVertex: the vertex index in tri
  };

  std::vector<Point2> pts;
  std::vector<double> size;  ///< local size per point
  std::vector<Tri> tris;
  std::vector<int> vtri;     ///< a triangle incident to each point
  std::vector<int> touched;  ///< triangles rewritten since the last clear

  /// Starts with one triangle (s0, s1, s2) enclosing everything; returns its index.
  int init(const Point2& s0, const Point2& s1, const Point2& s2);
  /// Appends a point (not yet triangulated); returns its index.
  int add_point(const Point2& p, double h);

  /// Walks from triangle `start` to p. With stop_at_constraints the walk never
  /// crosses a constrained edge and reports Blocked there instead.
  Location locate(const Point2& p, int start, bool stop_at_constraints) const;
  /// Inserts point vi at loc (Inside or OnEdge of an unconstrained edge with
  /// two neighbours) and restores the Delaunay property by flips that never
  /// cross constraints. Returns false (nothing changed) when it cannot.
  bool insert(int vi, const Location& loc);
  /// Makes (a, b) an edge and marks it constrained. Throws
  /// MeshingError(InvalidInput) when a point lies on the segment.
  void insert_segment(int a, int b);
  /// Classifies triangles by the parity of constraints crossed from the
  /// super triangle: odd = inside the domain.
  void mark_inside();
  /// Lawson flips over every unconstrained edge between inside triangles.
  void make_delaunay();

  /// Renumbers the triangles in a canonical order (by their vertex triples,
  /// each rotated to start at its smallest vertex), so that equal
  /// triangulations reached by different flip histories are stored alike.
  void canonicalize();

  /// (t, i) with edge i of t joining a and b (either direction); (-1, -1) if none.
  std::pair<int, int> find_edge(int a, int b) const;
  /// Should the unconstrained edge i of t be flipped (Delaunay, with tie tolerance)?
  bool flip_wanted(int t, int i) const;
  /// Index k with tris[u].n[k] == t.
  int back_index(int u, int t) const;

 private:
  void set(int t, const std::array<int, 3>& v, const std::array<int, 3>& n,
           const std::array<bool, 3>& c);
  void relink(int nb, int from, int to);
  /// Flips edge i of t; afterwards t = (p, q, s), u = (p, s, r) where
  /// p = old v[i]. Returns u.
  int flip(int t, int i);
  void legalize(std::vector<std::pair<int, int>>& stack);
  std::vector<std::pair<int, int>> star(int a) const;
};

}  // namespace cooperage::mesh2d::detail
