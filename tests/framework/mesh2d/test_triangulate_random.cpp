// Seeded randomized test of the 2D core: star-shaped outer polygons with
// star-shaped holes, random spacing per loop (so many collinear points).
#include <Eigen/Geometry>
#include <cstdio>
#include <random>

#include "mesh2d_checks.h"

namespace cooperage::mesh2d::test {
namespace {

using V = Eigen::Vector2d;

std::vector<V> star(std::mt19937& rng, const V& c, double r, int n, bool ccw) {
  std::uniform_real_distribution<double> radius(0.6, 1.0);
  std::vector<V> out;
  for (int k = 0; k < n; ++k) {
    const double t = 2.0 * 3.14159265358979323846 * k / n * (ccw ? 1.0 : -1.0);
    out.push_back(c + r * radius(rng) * V(std::cos(t), std::sin(t)));
  }
  return out;
}

Loops random_domain(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> corners(3, 24);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Loops loops;
  const double R = 10.0;
  const int n = corners(rng);
  loops.push_back(subdivide(star(rng, V(0, 0), R, n, true), 0.3 + 1.2 * unit(rng)));
  // Holes: disjoint disks inside a disk the outer polygon surely contains.
  const double inner = 0.6 * R * std::cos(3.14159265358979323846 / n);
  std::vector<std::pair<V, double>> disks;
  const int holes = static_cast<int>(unit(rng) * 5);
  for (int attempt = 0; attempt < 50 && static_cast<int>(disks.size()) < holes; ++attempt) {
    const double rh = 0.5 + 1.5 * unit(rng);
    const double a = 6.283185307179586 * unit(rng);
    const double d = (inner - rh - 0.3) * unit(rng);
    const V c = d * V(std::cos(a), std::sin(a));
    bool ok = d >= 0.0;
    for (const auto& [o, r] : disks) ok = ok && (o - c).norm() > r + rh + 0.3;
    if (!ok) continue;
    disks.emplace_back(c, rh);
    loops.push_back(subdivide(star(rng, c, rh, corners(rng), false), 0.1 + 0.6 * unit(rng)));
  }
  return loops;
}

TEST(Mesh2dRandom, PolygonsWithHoles) {
  double worst = 180.0;
  size_t total = 0;
  for (unsigned seed = 1; seed <= 120; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const Loops loops = random_domain(seed);
    const Triangulation2D t = triangulate(loops);
    expect_valid(loops, t);
    EXPECT_FALSE(t.capped);
    if (::testing::Test::HasFatalFailure()) return;
    worst = std::min(worst, min_angle_deg(t));
    total += t.triangles.size();
  }
  std::printf(
      "[mesh2d] random: 120 domains, %zu triangles, worst min angle %.2f deg "
      "(input angles can be small)\n",
      total, worst);
}

TEST(Mesh2dRandom, CdtOnly) {
  for (unsigned seed = 200; seed < 300; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const Loops loops = random_domain(seed);
    RefineOptions opt;
    opt.refine = false;
    const Triangulation2D t = triangulate(loops, opt);
    expect_valid(loops, t);
    if (::testing::Test::HasFatalFailure()) return;
  }
}

// Rigid motions of random domains give the same connectivity and the moved
// points (the loops' first point and segment fix the working frame).
TEST(Mesh2dRandom, RigidMotionInvariance) {
  int same = 0;
  for (unsigned seed = 400; seed < 430; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const Loops loops = random_domain(seed);
    const Eigen::Rotation2Dd rot(0.1 + 0.2 * (seed - 400));
    const V shift(1.0 * seed, -0.5 * seed);
    Loops moved = loops;
    for (auto& l : moved) {
      for (auto& p : l) p = rot * p + shift;
    }
    const Triangulation2D a = triangulate(loops);
    const Triangulation2D b = triangulate(moved);
    EXPECT_EQ(a.triangles, b.triangles);
    if (a.triangles != b.triangles || a.points.size() != b.points.size()) continue;
    double err = 0.0;
    for (size_t i = 0; i < a.points.size(); ++i)
      err = std::max(err, (rot * a.points[i] + shift - b.points[i]).norm());
    EXPECT_LT(err, 1e-9 * 20.0);
    ++same;
  }
  std::printf("[mesh2d] rigid motion: %d of 30 random domains identical\n", same);
}

}  // namespace
}  // namespace cooperage::mesh2d::test
