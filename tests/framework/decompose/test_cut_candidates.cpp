// cut_candidates.h: the candidate cuts of a volume, from its faces and edges.
#include "framework/decompose/cut_candidates.h"

#include "framework/decompose/volume_samples.h"
#include "framework/geometry/occ/workbench.h"

#include <gtest/gtest.h>

#include <cmath>

namespace cooperage::decompose {
namespace {

geom::Model l_prism() {
  occ::Workbench bench;
  bench.prism("l", {{0, 0, 0}, {3, 0, 0}, {3, 1, 0}, {1, 1, 0}, {1, 3, 0}, {0, 3, 0}}, {},
              {0, 0, 1});
  return bench.build_model();
}

TEST(CutCandidates, AnLPrismOffersThePlanesOfItsEightFaces) {
  const geom::Model m = l_prism();
  const auto c = cut_candidates(m, 1);
  ASSERT_EQ(c.size(), 8u);  // edge planes all coincide with face planes
  for (const auto& k : c) {
    EXPECT_EQ(k.surface.kind, CutSurface::Kind::Plane);
    EXPECT_EQ(k.through.rfind("plane of surface ", 0), 0u) << k.through;
  }
  // Exactly the two planes of the inner faces cross the solid.
  const auto samples = volume_samples(m, 1);
  int crossing = 0;
  for (const auto& k : c) {
    const Span s = span(k.surface, samples);
    if (s.below < -0.5 && s.above > 0.5) ++crossing;
  }
  EXPECT_EQ(crossing, 2);
}

TEST(CutCandidates, SweepAxesAreOrderedByFaceArea) {
  const auto axes = sweep_axes(l_prism(), 1);
  ASSERT_EQ(axes.size(), 3u);
  EXPECT_NEAR(std::abs(axes[0].z()), 1.0, 1e-12);  // top and bottom: area 10
}

TEST(CutCandidates, ACylindricalHoleOffersItsCylinder) {
  occ::Workbench bench;
  bench.brick("b", {-2, -2, 0}, {4, 4, 1});
  bench.cylinder("h", {0, 0, -1}, {0, 0, 1}, 0.5, 3);
  bench.cut("p", {"b", "h"});
  const geom::Model m = bench.build_model();
  int cylinders = 0;
  for (const auto& k : cut_candidates(m, 1)) {
    if (k.surface.kind != CutSurface::Kind::Cylinder) continue;
    ++cylinders;
    EXPECT_NEAR(k.surface.radius, 0.5, 1e-9);
    EXPECT_EQ(k.through.rfind("cylinder of surface ", 0), 0u);
  }
  EXPECT_EQ(cylinders, 1);
}

TEST(CutCandidates, APlaneThroughAnEdgeContainsTheEdgeAndTheAxis) {
  occ::Workbench bench;
  bench.prism("t", {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}}, {}, {0, 0, 1});
  const geom::Model m = bench.build_model();
  const auto axes = sweep_axes(m, 1);
  int through_edges = 0;
  for (const auto& k : cut_candidates(m, 1)) {
    if (k.through.rfind("plane through curve ", 0) != 0) continue;
    ++through_edges;
    const int c = std::stoi(k.through.substr(20));
    const auto& curve = m.curve(c);
    EXPECT_NEAR(signed_distance(k.surface, m.vertex(curve.start_vertex).point), 0.0, 1e-9);
    EXPECT_NEAR(signed_distance(k.surface, m.vertex(curve.end_vertex).point), 0.0, 1e-9);
    bool along_an_axis = false;
    for (const auto& a : axes)
      along_an_axis = along_an_axis || std::abs(a.dot(k.surface.direction)) < 1e-9;
    EXPECT_TRUE(along_an_axis);
  }
  EXPECT_GT(through_edges, 0);
}

TEST(CutCandidates, TheOrderDoesNotDependOnThePlacement) {
  occ::Workbench a, b;
  for (occ::Workbench* w : {&a, &b}) {
    w->prism("l", {{0, 0, 0}, {3, 0, 0}, {3, 1, 0}, {1, 1, 0}, {1, 3, 0}, {0, 3, 0}}, {},
             {0, 0, 1});
    w->cylinder("h", {2, 0.5, -1}, {0, 0, 1}, 0.25, 3);
    w->cut("p", {"l", "h"});
  }
  b.rotate("p", {1, 1, 1}, geom::Vec3(1, 2, 3), 37);
  b.translate("p", {5, -2, 1});
  const auto ca = cut_candidates(a.build_model(), 1);
  const auto cb = cut_candidates(b.build_model(), 1);
  ASSERT_EQ(ca.size(), cb.size());
  for (size_t k = 0; k < ca.size(); ++k) {
    EXPECT_EQ(ca[k].through.substr(0, ca[k].through.find(" along")),
              cb[k].through.substr(0, cb[k].through.find(" along")))
        << k;
    EXPECT_EQ(ca[k].surface.kind, cb[k].surface.kind);
  }
}

}  // namespace
}  // namespace cooperage::decompose
