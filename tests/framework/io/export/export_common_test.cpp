// The exporters' shared lookups: a surface's node set and the element side
// that carries a surface element, checked against direct enumeration.
#include "framework/io/export/export_common.h"

#include <gtest/gtest.h>

#include <random>
#include <set>
#include <vector>

namespace cooperage::io::detail {
namespace {

TEST(SurfaceNodeSet, IsEveryCornerOnceInAscendingOrder) {
  std::mt19937 rng(3);
  // Nodes spread over a range wider than one word of bits, with repeats.
  std::uniform_int_distribution<int> node(1000, 1000 + 5000);
  mesh::SurfaceMeshData s;
  std::set<int> expected;
  for (int i = 0; i < 400; ++i) {
    mesh::Quad q{node(rng), node(rng), node(rng), node(rng)};
    s.quads.push_back(q);
    expected.insert(q.begin(), q.end());
  }
  for (int i = 0; i < 50; ++i) {
    mesh::Tri t{node(rng), node(rng), node(rng)};
    s.tris.push_back(t);
    expected.insert(t.begin(), t.end());
  }
  s.quads.push_back({1000, 1000, 6000, 6000});  // the range's ends
  expected.insert({1000, 6000});
  EXPECT_EQ(surface_node_set(s), std::vector<int>(expected.begin(), expected.end()));
  EXPECT_TRUE(surface_node_set(mesh::SurfaceMeshData{}).empty());
}

// Two hexes side by side along x (nodes 0-11, x = 0, 1, 2): the shared face
// belongs to the first hex that has it; faces are found in any node order.
TEST(FaceFinder, FindsTheFirstElementSideWithTheNodes) {
  mesh::VolumeMeshData vol;
  // Bottom layer: 0 1 2 (y=0), 3 4 5 (y=1); top layer +6.
  vol.hexes.push_back({0, 1, 4, 3, 6, 7, 10, 9});
  vol.hexes.push_back({1, 2, 5, 4, 7, 8, 11, 10});
  const std::vector<bool> all(12, true);
  const FaceFinder finder(vol, exodus_hex_sides(), exodus_wedge_sides(), all);
  const int shared[4] = {10, 4, 1, 7};  // x = 1
  const FaceHit a = finder.find(shared, 4);
  EXPECT_EQ(a.element, 0);
  EXPECT_EQ(a.side, 1);                  // Exodus side 2: nodes 1 2 6 5 of the first hex
  const int far_end[4] = {11, 5, 2, 8};  // x = 2
  const FaceHit b = finder.find(far_end, 4);
  EXPECT_EQ(b.element, 1);
  EXPECT_EQ(b.side, 1);
  const int bottom[4] = {4, 5, 2, 1};
  EXPECT_EQ(finder.find(bottom, 4).side, 4);
  const int none[4] = {0, 1, 2, 3};
  EXPECT_EQ(finder.find(none, 4).element, -1);
  // Only sides whose nodes are all wanted are indexed.
  std::vector<bool> some(12, false);
  for (int n : {2, 5, 8, 11}) some[static_cast<size_t>(n)] = true;
  const FaceFinder partial(vol, exodus_hex_sides(), exodus_wedge_sides(), some);
  EXPECT_EQ(partial.find(far_end, 4).element, 1);
  EXPECT_EQ(partial.find(shared, 4).element, -1);
}

}  // namespace
}  // namespace cooperage::io::detail
