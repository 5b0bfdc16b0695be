// The cooper sweep core without CAD: rib propagation (barrel uniqueness),
// the least-squares affine map, and sweep_barrel on synthetic barrels
// (hexes and the wedge path).
#include "schemes/cooper/form_barrels.h"
#include "schemes/cooper/least_squares_map.h"
#include "schemes/cooper/sweep_barrel.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cmath>
#include <numeric>
#include <random>

namespace cooperage::cooper {
namespace {

// A tube of side quads: a ring of m nodes repeated over L + 1 layers; node
// (r, j) gets id perm[j * m + r] so ids carry no order.
struct Tube {
  int m = 0, L = 0;
  std::vector<int> perm;
  std::vector<mesh::Quad> quads;
  int id(int r, int j) const { return perm[static_cast<size_t>(j * m + (r % m))]; }
};

Tube make_tube(int m, int L, unsigned seed) {
  Tube t;
  t.m = m;
  t.L = L;
  t.perm.resize(static_cast<size_t>(m * (L + 1)));
  std::iota(t.perm.begin(), t.perm.end(), 0);
  std::mt19937 rng(seed);
  std::shuffle(t.perm.begin(), t.perm.end(), rng);
  for (int j = 0; j < L; ++j) {
    for (int r = 0; r < m; ++r)
      t.quads.push_back({t.id(r, j), t.id(r + 1, j), t.id(r + 1, j + 1), t.id(r, j + 1)});
  }
  return t;
}

BarrelInput tube_input(const Tube& t) {
  BarrelInput in;
  in.upper_loops.emplace_back();
  for (int r = 0; r < t.m; ++r) in.upper_loops[0].push_back(t.id(r, 0));
  for (int r = 0; r < t.m; ++r) in.stop_nodes.push_back(t.id(r, t.L));
  in.side_quads = t.quads;
  return in;
}

TEST(FormBarrels, RibsRunDownTheTubeOneLayerAtATime) {
  const Tube t = make_tube(12, 5, 7);
  const Barrel b = form_barrels(tube_input(t));
  ASSERT_TRUE(b.ok) << b.why;
  EXPECT_EQ(b.layers, 5);
  EXPECT_TRUE(b.all_ribs_on_stop_nodes);
  ASSERT_EQ(b.ribs.size(), 12u);
  for (int r = 0; r < 12; ++r) {
    for (int j = 0; j <= 5; ++j)
      EXPECT_EQ(b.ribs[static_cast<size_t>(r)][static_cast<size_t>(j)], t.id(r, j));
  }
}

TEST(FormBarrels, PermutedQuadsAndFacesGiveTheSameRibs) {
  const Tube t = make_tube(16, 7, 11);
  const BarrelInput in = tube_input(t);
  const Barrel reference = form_barrels(in);
  ASSERT_TRUE(reference.ok) << reference.why;
  std::mt19937 rng(3);
  for (int trial = 0; trial < 5; ++trial) {
    BarrelInput p = in;
    // Faces: split the quads into 4 "faces" (quarters of the ring) fed in a
    // random order; each quad rotated and possibly reversed.
    std::vector<std::vector<mesh::Quad>> faces(4);
    for (size_t k = 0; k < p.side_quads.size(); ++k) faces[(k % 16) / 4].push_back(p.side_quads[k]);
    std::shuffle(faces.begin(), faces.end(), rng);
    p.side_quads.clear();
    for (auto& f : faces) {
      std::shuffle(f.begin(), f.end(), rng);
      for (auto q : f) {
        std::rotate(q.begin(), q.begin() + static_cast<long>(rng() % 4), q.end());
        if (rng() % 2) std::reverse(q.begin(), q.end());
        p.side_quads.push_back(q);
      }
    }
    std::shuffle(p.stop_nodes.begin(), p.stop_nodes.end(), rng);
    const Barrel b = form_barrels(p);
    ASSERT_TRUE(b.ok) << b.why;
    EXPECT_EQ(b.ribs, reference.ribs);
    EXPECT_EQ(b.layers, reference.layers);
  }
}

TEST(FormBarrels, StopsAtTheFirstCapReachedAndReportsManyToOne) {
  const Tube t = make_tube(8, 6, 5);
  BarrelInput in = tube_input(t);
  in.stop_nodes = {t.id(3, 2)};  // another cap touches the side at layer 2
  const Barrel b = form_barrels(in);
  ASSERT_TRUE(b.ok) << b.why;
  EXPECT_EQ(b.layers, 2);
  EXPECT_FALSE(b.all_ribs_on_stop_nodes);
}

TEST(FormBarrels, IrregularSideMeshIsRejectedWithAReason) {
  const Tube t = make_tube(8, 3, 5);
  BarrelInput in = tube_input(t);
  in.side_quads.push_back({t.id(0, 1), t.id(4, 1), 900, 901});  // a fifth neighbour
  const Barrel b = form_barrels(in);
  EXPECT_FALSE(b.ok);
  EXPECT_NE(b.why.find("unused side neighbours"), std::string::npos) << b.why;
}

TEST(LeastSquaresMap, RecoversARigidMotionOfPlanarLoopsWithAHole) {
  // Outer square and a clockwise square hole in the plane z = 0.
  std::vector<Vec3> x = {{0, 0, 0}, {4, 0, 0}, {4, 3, 0}, {0, 3, 0},
                         {1, 1, 0}, {1, 2, 0}, {2, 2, 0}, {2, 1, 0}};
  const std::vector<size_t> starts = {0, 4};
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  const Vec3 shift(3, -1, 2);
  std::vector<Vec3> y;
  for (const auto& p : x) y.push_back(R * p + shift);
  const AffineMap map = least_squares_map(x.data(), y.data(), x.size(), starts);
  ASSERT_TRUE(map.ok);
  EXPECT_LT((map.A - R).norm(), 1e-12);
  EXPECT_LT((map.apply(Vec3(3, 2, 0)) - (R * Vec3(3, 2, 0) + shift)).norm(), 1e-12);
  // Collinear loops leave the normal equations singular: not ok.
  std::vector<Vec3> line;
  for (int k = 0; k < 8; ++k) line.push_back(Vec3(k, 0, 0));
  EXPECT_FALSE(least_squares_map(line.data(), y.data(), line.size(), starts).ok);
}

// A synthetic barrel: an nx x ny grid cap on z = 0 (quads, or triangles when
// split), ribs of the boundary rotated about the y axis through x = -R0 by
// `bend` over the layers (a curved axis) or straight up when bend == 0.
SweepInput grid_barrel(int nx, int ny, int layers, double bend, bool triangles) {
  SweepInput in;
  std::vector<std::array<int, 2>> ij;
  // Boundary counter-clockwise about +z, then interior.
  for (int i = 0; i < nx; ++i) ij.push_back({i, 0});
  for (int j = 0; j < ny; ++j) ij.push_back({nx, j});
  for (int i = nx; i > 0; --i) ij.push_back({i, ny});
  for (int j = ny; j > 0; --j) ij.push_back({0, j});
  in.boundary = static_cast<int>(ij.size());
  for (int j = 1; j < ny; ++j) {
    for (int i = 1; i < nx; ++i) ij.push_back({i, j});
  }
  in.cap_nodes = static_cast<int>(ij.size());
  in.loop_starts = {0};
  std::map<std::array<int, 2>, int> index;
  for (size_t k = 0; k < ij.size(); ++k) index[ij[k]] = static_cast<int>(k);
  for (const auto& p : ij) in.source.push_back(Vec3(p[0], p[1], 0));
  const double R0 = 3.0;
  auto place = [&](const Vec3& p, int layer) {
    if (bend == 0) return Vec3(p + Vec3(0, 0, layer));
    const double a = bend * layer / layers;
    const Vec3 c(-R0, 0, 0);
    return Vec3(c + Eigen::AngleAxisd(-a, Vec3::UnitY()) * (p - c));
  };
  in.layers = layers;
  for (int r = 0; r < in.boundary; ++r) {
    for (int j = 0; j <= layers; ++j)
      in.ribs.push_back(place(in.source[static_cast<size_t>(r)], j));
  }
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const int a = index[{i, j}], b = index[{i + 1, j}], c = index[{i + 1, j + 1}],
                d = index[{i, j + 1}];
      if (triangles) {
        in.tris.push_back({a, b, c});
        in.tris.push_back({a, c, d});
      } else {
        in.quads.push_back({a, b, c, d});
      }
    }
  }
  return in;
}

double wedge_volume(const std::vector<Vec3>& x, const mesh::Wedge& w) {
  // Three tetrahedra of the prism (exact for planar quad faces).
  auto tet = [&](int a, int b, int c, int d) {
    const Vec3& p = x[static_cast<size_t>(w[static_cast<size_t>(a)])];
    return (x[static_cast<size_t>(w[static_cast<size_t>(b)])] - p)
               .cross(x[static_cast<size_t>(w[static_cast<size_t>(c)])] - p)
               .dot(x[static_cast<size_t>(w[static_cast<size_t>(d)])] - p) /
           6.0;
  };
  return tet(0, 1, 2, 3) + tet(1, 2, 3, 4) + tet(2, 3, 4, 5);
}

TEST(SweepBarrel, StraightQuadCapGivesUnitCubes) {
  const SweepInput in = grid_barrel(4, 3, 5, 0.0, false);
  const SweepResult r = sweep_barrel(in);
  ASSERT_TRUE(r.ok) << r.why;
  EXPECT_FALSE(r.smoothed);
  EXPECT_EQ(r.hexes.size(), 4u * 3u * 5u);
  EXPECT_NEAR(r.min_scaled_jacobian, 1.0, 1e-12);
  // Interior nodes sit exactly above their source nodes.
  const size_t n = static_cast<size_t>(in.cap_nodes);
  for (size_t i = static_cast<size_t>(in.boundary); i < n; ++i) {
    EXPECT_LT((r.points[3 * n + i] - (in.source[i] + Vec3(0, 0, 3))).norm(), 1e-12);
  }
}

// A sweep that cannot mend an inverted hex says which one and where: a
// one-cell barrel whose source quad is turned the wrong way round (every
// node a rib node, so nothing can move).
TEST(SweepBarrel, AnInvertedHexIsNamedWithItsCentre) {
  SweepInput in = grid_barrel(1, 1, 2, 0.0, false);
  auto& q = in.quads.front();
  std::swap(q[1], q[3]);
  const SweepResult r = sweep_barrel(in);
  ASSERT_FALSE(r.ok);
  EXPECT_NE(r.why.find("hex 0 of layer 0, at (0.5, 0.5, 0.5), is inverted"), std::string::npos)
      << r.why;
}

TEST(SweepBarrel, CurvedAxisFollowsTheArc) {
  const SweepInput in = grid_barrel(4, 4, 8, 1.2, false);
  const SweepResult r = sweep_barrel(in);
  ASSERT_TRUE(r.ok) << r.why;
  EXPECT_GT(r.min_scaled_jacobian, 0.5);
}

TEST(SweepBarrel, TriangleCapGivesWedgesOfPositiveVolumeSummingToTheSolid) {
  const SweepInput in = grid_barrel(3, 2, 4, 0.0, true);
  const SweepResult r = sweep_barrel(in);
  ASSERT_TRUE(r.ok) << r.why;
  EXPECT_TRUE(r.hexes.empty());
  ASSERT_EQ(r.wedges.size(), 3u * 2u * 2u * 4u);
  double total = 0;
  for (const auto& w : r.wedges) {
    const double v = wedge_volume(r.points, w);
    EXPECT_GT(v, 0);
    total += v;
  }
  EXPECT_NEAR(total, 3.0 * 2.0 * 4.0, 1e-12);
  EXPECT_GT(r.min_scaled_jacobian, 0.5);
}

TEST(SweepBarrel, HalfAMillionHexesSweepQuickly) {
  const SweepInput in = grid_barrel(100, 100, 50, 0.8, false);
  const auto t0 = std::chrono::steady_clock::now();
  const SweepResult r = sweep_barrel(in);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ASSERT_TRUE(r.ok) << r.why;
  EXPECT_EQ(r.hexes.size(), 500000u);
  RecordProperty("hexes_per_second", std::to_string(static_cast<long>(r.hexes.size() / seconds)));
  std::printf("sweep_barrel: %zu hexes in %.3f s (%.2f M hexes/s, incl. the quality check)\n",
              r.hexes.size(), seconds, r.hexes.size() / seconds * 1e-6);
}

// A seam (Blacker 1996, sec. 5.4) moves one interior rib's far end sideways
// by 0.7 of an element diagonally: the blend with the projected target folds the target
// quads around it (inverted); smoothing the target layer and blending again
// untangles them and beats smoothing every layer, which shears the layers
// next to the source off the source cap's shape.
TEST(SweepBarrel, ASeamedFixedTargetIsSpreadOverTheTargetCap) {
  SweepInput in = grid_barrel(6, 6, 3, 0.0, false);
  const size_t n = static_cast<size_t>(in.cap_nodes);
  in.has_fixed_target.assign(n, 0);
  in.fixed_target.assign(n, Vec3::Zero());
  size_t seamed = n;
  for (size_t i = static_cast<size_t>(in.boundary); i < n; ++i) {
    if ((in.source[i] - Vec3(2, 3, 0)).norm() < 1e-12) seamed = i;
  }
  ASSERT_LT(seamed, n);
  in.has_fixed_target[seamed] = 1;
  in.fixed_target[seamed] = Vec3(2.7, 3.7, 3);
  std::vector<Vec3> blend;
  std::string why;
  ASSERT_TRUE(place_layer_nodes(in, blend, why)) << why;
  std::vector<mesh::Hex> hexes;
  std::vector<mesh::Wedge> wedges;
  make_elements(in, hexes, wedges);
  const double blended = min_scaled_jacobian(blend, hexes, wedges, 0.0, nullptr);
  std::vector<Vec3> layers = blend;
  smooth_layers(in, SweepOptions{}.smoothing_iterations, layers);
  const double every_layer = min_scaled_jacobian(layers, hexes, wedges, 0.0, nullptr);
  const SweepResult r = sweep_barrel(in);
  ASSERT_TRUE(r.ok) << r.why;
  EXPECT_TRUE(r.smoothed);
  EXPECT_LT(blended, 0.0);                        // inverted
  EXPECT_GT(r.min_scaled_jacobian, every_layer);  // 0.381 against 0.285
  EXPECT_GT(r.min_scaled_jacobian, 0.35);
  EXPECT_EQ(r.points[3 * n + seamed], Vec3(2.7, 3.7, 3));  // the seam is kept
  std::printf("seamed target: blend %.3f, every layer smoothed %.3f, target smoothed %.3f\n",
              blended, every_layer, r.min_scaled_jacobian);
}

TEST(SweepBarrel, InvertedPlacementIsNeverEmittedSilently) {
  SweepInput in = grid_barrel(3, 3, 2, 0.0, false);
  // Fold the target ring onto itself: no placement can be valid.
  const size_t J1 = static_cast<size_t>(in.layers) + 1;
  for (int r = 0; r < in.boundary; ++r) {
    Vec3& top = in.ribs[static_cast<size_t>(r) * J1 + 2];
    top = Vec3(3.0 - top.x(), top.y(), 2.0);
  }
  const SweepResult r = sweep_barrel(in);
  EXPECT_FALSE(r.ok);
  EXPECT_FALSE(r.why.empty());
}

}  // namespace
}  // namespace cooperage::cooper
