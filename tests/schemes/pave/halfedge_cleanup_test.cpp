// The half-edge clean-up (schemes/pave/halfedge_cleanup.h) on hand-built
// quad meshes whose result follows from topology, and on random pave meshes
// (same boundary, every quad valid, irregular count not higher).
#include "pave_test_util.h"

#include "framework/core/error.h"
#include "schemes/pave/cleanup_2d.h"
#include "schemes/pave/halfedge_cleanup.h"

#include <gtest/gtest.h>

#include <map>
#include <utility>

namespace cooperage::pave::testing {
namespace {

using detail::HalfEdgeCleanupOptions;
using detail::Quad;

/// An nx x ny grid of unit squares: the boundary ring first (counter-
/// clockwise from (0, 0)), then the interior nodes row by row.
struct Grid {
  QuadMesh2D mesh;
  std::map<std::pair<int, int>, int> id;
  int at(int i, int j) const { return id.at({i, j}); }
  Loops loops() const {
    return {std::vector<V2>(mesh.points.begin(), mesh.points.begin() + mesh.boundary_count)};
  }
  std::vector<char> fixed() const {
    std::vector<char> f(mesh.points.size(), 0);
    for (int i = 0; i < mesh.boundary_count; ++i) f[static_cast<size_t>(i)] = 1;
    return f;
  }
};

Grid grid(int nx, int ny) {
  Grid g;
  auto add = [&](int i, int j) {
    g.id[{i, j}] = static_cast<int>(g.mesh.points.size());
    g.mesh.points.emplace_back(i, j);
  };
  for (int i = 0; i < nx; ++i) add(i, 0);
  for (int j = 0; j < ny; ++j) add(nx, j);
  for (int i = nx; i > 0; --i) add(i, ny);
  for (int j = ny; j > 0; --j) add(0, j);
  g.mesh.boundary_count = static_cast<int>(g.mesh.points.size());
  for (int j = 1; j < ny; ++j) {
    for (int i = 1; i < nx; ++i) add(i, j);
  }
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i)
      g.mesh.quads.push_back({g.at(i, j), g.at(i + 1, j), g.at(i + 1, j + 1), g.at(i, j + 1)});
  }
  return g;
}

/// Replaces the quad with lower-left corner (i, j) in the grid's quad list.
void replace_quad(Grid& g, int i, int j, const std::vector<Quad>& with) {
  const Quad old{g.at(i, j), g.at(i + 1, j), g.at(i + 1, j + 1), g.at(i, j + 1)};
  auto& q = g.mesh.quads;
  q.erase(std::find(q.begin(), q.end(), old));
  q.insert(q.end(), with.begin(), with.end());
}

/// Interior nodes whose quad count is not 4.
int irregular_interior(const QuadMesh2D& m) { return stats(m).irregular; }

/// Runs the clean-up on m with its boundary fixed.
detail::HalfEdgeCleanupCounts clean(QuadMesh2D& m, const HalfEdgeCleanupOptions& options = {}) {
  std::vector<char> fixed(m.points.size(), 0);
  for (int i = 0; i < m.boundary_count; ++i) fixed[static_cast<size_t>(i)] = 1;
  return detail::halfedge_cleanup(m.points, m.quads, fixed, options);
}

TEST(HalfEdgeCleanup, DoubletDisappears) {
  // A 3 x 3 grid whose middle square is cut along its diagonal by a node v
  // at the centre: v is in two quads (a doublet), the diagonal's ends in
  // five. A doublet's two angles sum to 360 degrees, so they are flat at
  // best (scaled Jacobian 0): no valid mesh has one, hence no check before.
  Grid g = grid(3, 3);
  const int v = static_cast<int>(g.mesh.points.size());
  g.mesh.points.emplace_back(1.5, 1.5);
  const int a = g.at(1, 1), b = g.at(2, 1), c = g.at(2, 2), d = g.at(1, 2);
  replace_quad(g, 1, 1, {{v, a, b, c}, {v, c, d, a}});
  ASSERT_EQ(irregular_interior(g.mesh), 3);

  const auto counts = clean(g.mesh);
  EXPECT_EQ(counts.doublets, 1);
  EXPECT_EQ(check_mesh(g.loops(), g.mesh), "");
  EXPECT_EQ(g.mesh.quads.size(), 9u);
  EXPECT_EQ(g.mesh.points.size(), 16u);  // v is gone
  EXPECT_EQ(irregular_interior(g.mesh), 0);
}

TEST(HalfEdgeCleanup, DiamondsTwoValenceThreeNodesBecomeOneValenceFour) {
  // A 2 x 2 grid whose centre node is split into a (left) and c (right)
  // with the diamond quad (a, bottom middle, c, top middle) between them.
  Grid g = grid(2, 2);
  const int centre = g.at(1, 1);
  g.mesh.points[static_cast<size_t>(centre)] = V2(0.7, 1.0);  // becomes a
  const int a = centre, c = static_cast<int>(g.mesh.points.size());
  g.mesh.points.emplace_back(1.3, 1.0);
  const int b = g.at(1, 0), d = g.at(1, 2);
  g.mesh.quads = {{g.at(0, 0), b, a, g.at(0, 1)},
                  {g.at(0, 1), a, d, g.at(0, 2)},
                  {a, b, c, d},
                  {b, g.at(2, 0), g.at(2, 1), c},
                  {c, g.at(2, 1), g.at(2, 2), d}};
  ASSERT_EQ(check_mesh(g.loops(), g.mesh), "");
  ASSERT_EQ(irregular_interior(g.mesh), 2);

  HalfEdgeCleanupOptions no_rotation;
  no_rotation.rotate = false;
  const auto counts = clean(g.mesh, no_rotation);
  EXPECT_EQ(counts.diamonds, 1);
  EXPECT_EQ(check_mesh(g.loops(), g.mesh), "");
  ASSERT_EQ(g.mesh.quads.size(), 4u);
  ASSERT_EQ(g.mesh.points.size(), 9u);
  // The merged node sits at the middle of the diagonal, in four quads.
  EXPECT_NEAR((g.mesh.points[static_cast<size_t>(a)] - V2(1.0, 1.0)).norm(), 0.0, 1e-12);
  EXPECT_EQ(irregular_interior(g.mesh), 0);
}

TEST(HalfEdgeCleanup, EdgeRotationLowersIrregularNodesAndKeepsQuadsValid) {
  // A 4 x 4 grid whose 2 x 1 block of squares at (1, 1)-(3, 2) is cut by the
  // hexagon's diagonal (1, 2)-(3, 1) instead of the edge (2, 1)-(2, 2): the
  // middle nodes get three quads, the diagonal's ends five. The middle nodes
  // are pushed out of the block so that both quads are convex.
  Grid g = grid(4, 4);
  const int u = g.at(2, 1), v = g.at(2, 2), p = g.at(1, 2), q = g.at(3, 1);
  g.mesh.points[static_cast<size_t>(u)].y() = 0.7;
  g.mesh.points[static_cast<size_t>(v)].y() = 2.3;
  replace_quad(g, 1, 1, {});
  replace_quad(g, 2, 1, {{q, g.at(3, 2), v, p}, {p, g.at(1, 1), u, q}});
  ASSERT_EQ(check_mesh(g.loops(), g.mesh), "");
  ASSERT_EQ(irregular_interior(g.mesh), 4);

  HalfEdgeCleanupOptions without;
  without.rotate = false;
  QuadMesh2D unrotated = g.mesh;
  EXPECT_EQ(clean(unrotated, without).rotations, 0);
  EXPECT_EQ(irregular_interior(unrotated), 4);  // no doublet, no diamond here

  const auto counts = clean(g.mesh);
  EXPECT_EQ(counts.rotations, 1);
  EXPECT_EQ(check_mesh(g.loops(), g.mesh), "");
  EXPECT_EQ(g.mesh.quads.size(), 16u);
  EXPECT_EQ(irregular_interior(g.mesh), 0);
}

TEST(HalfEdgeCleanup, RotationAtTheBoundaryOnlyWhenBoundaryCountsMayChange) {
  // As above at the bottom edge of a 4 x 2 grid: the boundary node u (2, 0)
  // is in one quad (ideal: two) and cannot be pushed out, so the cut quad
  // is flat there (no check before); rotating back gives the grid.
  Grid g = grid(4, 2);
  const int p = g.at(1, 1), q = g.at(3, 0), u = g.at(2, 0), v = g.at(2, 1);
  g.mesh.points[static_cast<size_t>(v)].y() = 1.3;
  replace_quad(g, 1, 0, {});
  replace_quad(g, 2, 0, {{q, g.at(3, 1), v, p}, {p, g.at(1, 0), u, q}});
  ASSERT_EQ(irregular_interior(g.mesh), 2);  // v in three quads, p in five

  HalfEdgeCleanupOptions fixed_counts;
  fixed_counts.boundary_counts = false;
  QuadMesh2D kept = g.mesh;
  EXPECT_EQ(clean(kept, fixed_counts).rotations, 0);
  EXPECT_EQ(kept.quads.size(), g.mesh.quads.size());

  EXPECT_EQ(clean(g.mesh).rotations, 1);
  EXPECT_EQ(check_mesh(g.loops(), g.mesh), "");
  EXPECT_EQ(irregular_interior(g.mesh), 0);
}

TEST(HalfEdgeCleanup, RegularGridIsLeftAlone) {
  Grid g = grid(5, 4);
  const QuadMesh2D before = g.mesh;
  const auto counts = clean(g.mesh);
  EXPECT_EQ(counts.doublets + counts.diamonds + counts.rotations, 0);
  EXPECT_EQ(g.mesh.points, before.points);
  EXPECT_EQ(g.mesh.quads, before.quads);
}

// Random pave meshes made without clean-up, then cleaned on the half-edge
// mesh: the boundary is unchanged, every quad valid, the mesh tiles the face,
// and the irregular count (boundary nodes against their ideal count too)
// does not rise.
TEST(HalfEdgeCleanup, RandomPaveMeshesKeepBoundaryValidityAndDoNotGetMoreIrregular) {
  PaveOptions raw;
  raw.cleanup = false;
  int faces = 0, changed = 0, before_sum = 0, after_sum = 0;
  for (unsigned seed = 2000; seed < 2060; ++seed) {
    const Loops loops = random_face(seed);
    QuadMesh2D m;
    try {
      m = pave_2d(loops, raw);
    } catch (const MeshingError&) {
      continue;  // pave without clean-up may fail on a face; not this test's subject
    }
    ++faces;
    std::vector<char> fixed(m.points.size(), 0);
    for (int i = 0; i < m.boundary_count; ++i) fixed[static_cast<size_t>(i)] = 1;
    const int before = detail::irregular_nodes(m.points, m.quads, fixed);
    const auto counts = detail::halfedge_cleanup(m.points, m.quads, fixed);
    changed += counts.doublets + counts.diamonds + counts.rotations > 0;
    const int after = detail::irregular_nodes(m.points, m.quads, fixed);
    before_sum += before;
    after_sum += after;
    EXPECT_EQ(check_mesh(loops, m), "") << "seed " << seed << "\n" << describe(loops);
    EXPECT_LE(after, before) << "seed " << seed;
  }
  EXPECT_GE(faces, 50);
  EXPECT_GT(changed, 0);
  std::printf("half-edge clean-up on %d raw pave meshes: %d changed, irregular %d -> %d\n", faces,
              changed, before_sum, after_sum);
}

// The clean-up as pave's step: every random face still meshes validly.
TEST(HalfEdgeCleanup, PaveWithHalfEdgeCleanupMeshesRandomFaces) {
  PaveOptions options;
  options.halfedge_cleanup = true;
  for (unsigned seed = 3000; seed < 3040; ++seed) {
    const Loops loops = random_face(seed);
    QuadMesh2D m;
    ASSERT_NO_THROW(m = pave_2d(loops, options)) << "seed " << seed << "\n" << describe(loops);
    EXPECT_EQ(check_mesh(loops, m), "") << "seed " << seed;
  }
}

}  // namespace
}  // namespace cooperage::pave::testing
