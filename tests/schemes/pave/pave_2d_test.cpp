// Tests of the 2D core pave_2d: the benchmark faces (quality printed,
// validity asserted), rigid-motion invariance, and the rejection of odd
// boundary counts.
#include "pave_test_util.h"

#include "framework/core/error.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <random>

namespace cooperage::pave::testing {
namespace {

TEST(Pave2D, BenchmarkFacesAreValidAndPrintQuality) {
  std::printf("%-24s %6s %8s %8s %12s\n", "face", "quads", "min SJ", "med SJ", "irreg/100q");
  for (const NamedFace& face : benchmark_faces()) {
    SCOPED_TRACE(face.name);
    const QuadMesh2D m = pave_2d(face.loops);
    EXPECT_EQ(check_mesh(face.loops, m), "");
    const Stats s = stats(m);
    std::printf("%-24s %6d %8.3f %8.3f %12.1f\n", face.name, s.quads, s.min_sj, s.median_sj,
                100.0 * s.irregular / s.quads);
    if (face.simple) {
      EXPECT_GT(s.median_sj, 0.8);
      EXPECT_GT(s.min_sj, 0.3);
    }
  }
}

// Paving's rows along a uniformly spaced square or L (even intervals on
// every side) close into the structured grid: the quad count is the area
// over the spacing squared, every quad is a square, every interior node
// has four edges. Circumcentre refinement alone gave 8.8 irregular nodes
// per 100 quads and a median of 0.983 on the benchmark square.
TEST(Pave2D, UniformlySpacedSquareAndLGiveTheStructuredGrid) {
  struct Case {
    const char* name;
    Loops loops;
    int quads;
  };
  const std::vector<Case> cases{
      {"square 10", {polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {10, 10, 10, 10})}, 100},
      {"square 40", {polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {40, 40, 40, 40})}, 1600},
      {"L",
       {polygon({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}, {12, 6, 6, 6, 6, 12})},
       108}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const QuadMesh2D m = pave_2d(c.loops);
    EXPECT_EQ(check_mesh(c.loops, m), "");
    const Stats s = stats(m);
    EXPECT_EQ(s.quads, c.quads);
    EXPECT_EQ(s.irregular, 0);
    EXPECT_GT(s.min_sj, 1.0 - 1e-9);
  }
}

// With the frontal attempt on (the default) the kept mesh scores at least
// as well as the circumcentre mesh alone (median + a quarter of the
// minimum, both above 0.5), whichever attempt wins on the face.
TEST(Pave2D, KeptMeshIsAtLeastAsGoodAsTheCircumcentreMeshAlone) {
  for (const NamedFace& face : benchmark_faces()) {
    SCOPED_TRACE(face.name);
    PaveOptions circumcentre_only;
    circumcentre_only.frontal = false;
    PaveStats stats;
    PaveOptions both;
    both.stats = &stats;
    const Stats a = testing::stats(pave_2d(face.loops, circumcentre_only));
    const QuadMesh2D kept = pave_2d(face.loops, both);
    EXPECT_EQ(check_mesh(face.loops, kept), "");
    const Stats b = testing::stats(kept);
    if (a.min_sj >= 0.5 && b.min_sj >= 0.5) {
      EXPECT_GE(b.median_sj + 0.25 * b.min_sj, a.median_sj + 0.25 * a.min_sj - 1e-12);
    }
    if (stats.kept == 1) {  // the circumcentre mesh won: the very same mesh
      EXPECT_EQ(b.quads, a.quads);
      EXPECT_DOUBLE_EQ(b.median_sj, a.median_sj);
    }
  }
}

TEST(Pave2D, SingleQuadAndSmallestLoops) {
  const Loops quad{polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {1, 1, 1, 1})};
  const QuadMesh2D m = pave_2d(quad);
  EXPECT_EQ(m.quads.size(), 1u);
  EXPECT_EQ(check_mesh(quad, m), "");
  const Loops hexagon{circle({0, 0}, 1, 6)};
  EXPECT_EQ(check_mesh(hexagon, pave_2d(hexagon)), "");
  const Loops small_hole{circle({0, 0}, 1, 16), circle({0.1, 0}, 0.25, 4, true)};
  EXPECT_EQ(check_mesh(small_hole, pave_2d(small_hole)), "");
}

// A four-node loop with a reflex corner is no quad: a quad inside it,
// joined to each corner, splits the reflex angle. The second is a subcap
// between a pocket's corner and two holes (the plan => mesh campaign's
// seed 4 case 155), in its chart: 3.5 long, 0.5 in area.
TEST(Pave2D, AFourNodeDartIsFiveQuads) {
  for (const Loops& dart : {Loops{{{0, 0}, {4, 2}, {0, 4}, {1, 2}}},
                            Loops{{{15.720049149688458, 22.93745093492028},
                                   {16.17322739531179, 25.086411821419915},
                                   {14.985289407762131, 21.832851342615864},
                                   {15.280155434004524, 22.433364055110154}}}}) {
    const QuadMesh2D m = pave_2d(dart);
    EXPECT_EQ(m.quads.size(), 5u);
    EXPECT_EQ(check_mesh(dart, m), "");
    // Moved, it gives the moved mesh.
    const Eigen::Rotation2Dd R(1.7);
    const V2 t(12.5, -3.25);
    Loops moved = dart;
    for (auto& p : moved[0]) p = R * p + t;
    const QuadMesh2D r = pave_2d(moved);
    ASSERT_EQ(r.quads, m.quads);
    for (size_t i = 0; i < m.points.size(); ++i)
      EXPECT_LT((r.points[i] - (R * m.points[i] + t)).norm(), 1e-9) << "node " << i;
  }
}

// A crescent between two circles with tips of about 28 and 40 degrees and
// a collinear node beside a reflex one (the plan => mesh campaign's seed 3
// case 96, surface 13, in its chart). From its first node every attempt
// folds a quad at a tip; from the next node it meshes. The mesh keeps the
// caller's boundary numbering.
TEST(Pave2D, ASliverThatFoldsFromItsFirstNodeIsPavedFromTheNext) {
  const Loops crescent{{{0, 0},
                        {1.083678032045102, 0},
                        {2.6479247530690344, -0.33514975399358737},
                        {4.6902316121791134, -1.5128945461949985},
                        {6.454707595538614, -3.9773385705109043},
                        {6.1627615986129083, -1.4597400366772479},
                        {4.727361439392415, 0.62907810418425369},
                        {2.4817612828912483, 1.8041588587727437},
                        {-0.052682090829506922, 1.7926859304067415},
                        {-2.2875517132615304, 0.5973229673646131},
                        {-1.0494636862264848, 0.94408441029155754},
                        {-0.32152009698471384, 1.147965526870476}}};
  const QuadMesh2D m = pave_2d(crescent);
  EXPECT_EQ(check_mesh(crescent, m), "");
  EXPECT_EQ(m.boundary_count, 12);
}

TEST(Pave2D, RotatedAndTranslatedFaceGivesTheMovedMesh) {
  for (const NamedFace& face : benchmark_faces()) {
    SCOPED_TRACE(face.name);
    const QuadMesh2D m = pave_2d(face.loops);
    for (double angle : {0.3, 1.7, -2.9}) {
      const Eigen::Rotation2Dd R(angle);
      const V2 t(12.5, -3.25);
      Loops moved = face.loops;
      for (auto& l : moved) {
        for (auto& p : l) p = R * p + t;
      }
      const QuadMesh2D r = pave_2d(moved);
      ASSERT_EQ(r.quads, m.quads);
      ASSERT_EQ(r.points.size(), m.points.size());
      double scale = 1.0;
      for (const auto& p : m.points) scale = std::max(scale, p.norm());
      for (size_t i = 0; i < m.points.size(); ++i) {
        EXPECT_LT((r.points[i] - (R * m.points[i] + t)).norm(), 1e-9 * scale) << "node " << i;
      }
    }
  }
}

// Regular polygons are full of cocircular points, whose exact incircle
// tests are ties decided by the last bits of the coordinates: a rotation's
// rounding then changed the triangulation unless every coordinate snapped
// to the same lattice point (a hub's annulus, 62 and 30 nodes, moved 142
// degrees, differed by 0.011 with a lattice of 2^-40 of the face's reach;
// this test then failed for 22 of 40 rotations, with 2^-30 for 0 of 400).
TEST(Pave2D, RotatedRegularAnnulusGivesTheRotatedMesh) {
  const Loops annulus{circle({0, 0}, 1.25, 62), circle({0, 0}, 0.6, 30, true)};
  const QuadMesh2D m = pave_2d(annulus);
  std::mt19937 rng(2026);
  std::uniform_real_distribution<double> U(-M_PI, M_PI);
  int differing = 0;
  for (int k = 0; k < 100; ++k) {
    const Eigen::Rotation2Dd R(U(rng));
    const V2 t(U(rng), U(rng));
    Loops moved = annulus;
    for (auto& l : moved) {
      for (auto& p : l) p = R * p + t;
    }
    const QuadMesh2D r = pave_2d(moved);
    bool same = r.quads == m.quads && r.points.size() == m.points.size();
    for (size_t i = 0; same && i < m.points.size(); ++i)
      same = (r.points[i] - (R * m.points[i] + t)).norm() < 1e-9;
    if (!same) ++differing;
  }
  EXPECT_EQ(differing, 0) << "of 100 rotations";
}

TEST(Pave2D, OddBoundaryCountIsRejected) {
  const Loops odd{polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {3, 3, 3, 4})};
  try {
    pave_2d(odd);
    FAIL() << "an odd boundary was accepted";
  } catch (const MeshingError& e) {
    EXPECT_EQ(e.code(), ErrorCode::InvalidInput);
    EXPECT_NE(std::string(e.what()).find("odd"), std::string::npos) << e.what();
  }
  const Loops two_odd_loops_odd_total{circle({0, 0}, 1, 15), circle({0, 0}, 0.5, 8, true)};
  EXPECT_THROW(pave_2d(two_odd_loops_odd_total), MeshingError);
}

TEST(Pave2D, OddLoopsWithAnEvenTotalAreMeshed) {
  const Loops two{circle({0, 0}, 2, 47), circle({0, 0}, 1, 23, true)};
  const Loops four{polygon({{0, 0}, {4, 0}, {4, 2}, {0, 2}}, {24, 11, 24, 12}),
                   circle({1, 1}, 0.4, 15, true), circle({2.2, 1}, 0.3, 11, true),
                   circle({3.2, 0.8}, 0.25, 5, true)};
  for (const Loops& loops : {two, four}) {
    const QuadMesh2D m = pave_2d(loops);
    EXPECT_EQ(check_mesh(loops, m), "");
    const Stats s = stats(m);
    std::printf("odd loops (%zu): %d quads, min SJ %.3f, median %.3f\n", loops.size(), s.quads,
                s.min_sj, s.median_sj);
    EXPECT_GT(s.min_sj, 0.3);
    EXPECT_GT(s.median_sj, 0.8);
  }
}

// A hole 1 from the reflex corners of a notch, edges 2 long: paving's
// corner template at a reflex corner reaches 2.6 and would cross the hole's
// loop, which no triangulation recovers ("loop edges intersect" in every
// attempt that wraps tips). Such a tip is left unwrapped (the plate under
// gmsh_as1-tu-203's block, issue 15, a nut next to another's notch).
TEST(Pave2D, AHoleNextToANotchIsNotCrossedByTheCornerTemplate) {
  const Loops loops{
      polygon({{0, 0}, {20, 0}, {20, 8}, {10, 8}, {10, 12}, {20, 12}, {20, 20}, {0, 20}},
              {10, 4, 5, 2, 5, 4, 10, 10}),
      polygon({{4, 7}, {4, 13}, {9, 13}, {9, 7}}, {3, 2, 3, 2})};
  const QuadMesh2D m = pave_2d(loops);
  EXPECT_EQ(check_mesh(loops, m), "");
  const Stats s = stats(m);
  std::printf("hole next to a notch: %d quads, min SJ %.3f, median %.3f\n", s.quads, s.min_sj,
              s.median_sj);
  EXPECT_GT(s.min_sj, 0.3);
}

TEST(Pave2D, BadLoopsAreRejected) {
  EXPECT_THROW(pave_2d({}), MeshingError);
  EXPECT_THROW(pave_2d({circle({0, 0}, 1, 12, true)}), MeshingError);  // outer clockwise
  EXPECT_THROW(pave_2d({circle({0, 0}, 1, 12), circle({0, 0}, 0.5, 8)}),
               MeshingError);  // hole counter-clockwise
  EXPECT_THROW(pave_2d({circle({0, 0}, 1, 12), circle({3, 0}, 0.5, 8, true)}),
               MeshingError);                                   // hole outside
  EXPECT_THROW(pave_2d({circle({0, 0}, 1, 2)}), MeshingError);  // too few nodes
}

TEST(Pave2D, StatsAreFilledWhenAskedAndDoNotChangeTheMesh) {
  const Loops square{polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {20, 20, 20, 20})};
  PaveStats stats;
  stats.attempts = 99;  // reset by pave_2d
  PaveOptions options;
  options.stats = &stats;
  const QuadMesh2D with = pave_2d(square, options);
  const QuadMesh2D without = pave_2d(square);
  EXPECT_EQ(with.quads, without.quads);
  EXPECT_EQ(with.points, without.points);
  EXPECT_GE(stats.attempts, 1);  // frontal, then circumcentre unless the first is very good
  EXPECT_LE(stats.attempts, 2);
  EXPECT_TRUE(stats.kept == 0 || stats.kept == 1);
  EXPECT_GT(stats.sweeps, 0);
  for (double t : {stats.boundary, stats.triangulate, stats.recombine, stats.split, stats.cleanup,
                   stats.smooth, stats.check}) {
    EXPECT_GE(t, 0.0);
  }
}

TEST(Pave2D, ThroughputIsPrinted) {
  // About 3k, 12k and 48k quads: the time should grow linearly.
  for (int n : {40, 80, 160}) {
    const Loops big{polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {n, n, n, n})};
    const auto t0 = std::chrono::steady_clock::now();
    const QuadMesh2D m = pave_2d(big);
    const double dt = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("throughput: %zu quads in %.3f s (%.0f quads/s)\n", m.quads.size(), dt,
                m.quads.size() / dt);
    EXPECT_EQ(check_mesh(big, m), "");
  }
}

}  // namespace
}  // namespace cooperage::pave::testing
