// MeshDB basics: nodes, owners, chains, per-entity element storage.
#include "framework/mesh/mesh_db.h"

#include <gtest/gtest.h>

namespace cooperage::mesh {
namespace {

TEST(MeshDB, NodesAndOwners) {
  MeshDB db;
  EXPECT_EQ(db.node_count(), 0u);
  const int a = db.add_node(Vec3(1, 2, 3), {0, 4});
  const int b = db.add_node(Vec3(4, 5, 6), {3, 1});
  EXPECT_EQ(a, 0);
  EXPECT_EQ(b, 1);
  EXPECT_EQ(db.node(1), Vec3(4, 5, 6));
  EXPECT_EQ(db.owner(0), (NodeOwner{0, 4}));
  EXPECT_FALSE(db.owner(0) == db.owner(1));
  db.mutable_node(1).x() = 7;
  EXPECT_EQ(db.coords()[1].x(), 7);
  EXPECT_EQ(NodeOwner{}.dim, -1);
}

TEST(MeshDB, VerticesAndCurves) {
  MeshDB db;
  EXPECT_EQ(db.vertex_node(3), -1);
  db.set_vertex_node(3, 0);
  EXPECT_EQ(db.vertex_node(3), 0);
  EXPECT_FALSE(db.curve_meshed(2));
  EXPECT_TRUE(db.curve_nodes(2).empty());
  db.set_curve_nodes(2, {0, 5, 6, 1});
  EXPECT_TRUE(db.curve_meshed(2));
  EXPECT_EQ(db.curve_nodes(2), (std::vector<int>{0, 5, 6, 1}));
  EXPECT_EQ(db.curves().size(), 1u);
}

TEST(MeshDB, ElementsAndCounts) {
  MeshDB db;
  EXPECT_FALSE(db.surface_meshed(1));
  EXPECT_EQ(db.surface(1).size(), 0u);
  EXPECT_EQ(db.volume(1).size(), 0u);
  db.mutable_surface(2).quads.push_back({0, 1, 2, 3});
  db.mutable_surface(1).tris.push_back({0, 1, 2});
  db.mutable_surface(1).quads.push_back({0, 1, 2, 3});
  db.mutable_volume(1).hexes.push_back({0, 1, 2, 3, 4, 5, 6, 7});
  db.mutable_volume(3).wedges.push_back({0, 1, 2, 3, 4, 5});
  db.mutable_volume(3).wedges.push_back({0, 1, 2, 3, 4, 5});
  EXPECT_TRUE(db.surface_meshed(1));
  EXPECT_EQ(db.surface(1).size(), 2u);
  EXPECT_EQ(db.quad_count(), 2u);
  EXPECT_EQ(db.tri_count(), 1u);
  EXPECT_EQ(db.hex_count(), 1u);
  EXPECT_EQ(db.wedge_count(), 2u);
  EXPECT_EQ(db.volume(3).size(), 2u);
  // Ascending id order.
  EXPECT_EQ(db.surfaces().begin()->first, 1);
  EXPECT_EQ(db.volumes().rbegin()->first, 3);
}

// Both paths of append_nodes (taking the new array's storage, or copying
// into existing room) give the same nodes in the same order.
TEST(MeshDB, AppendNodesKeepsOrderAndOwners) {
  for (const bool roomy : {true, false}) {
    MeshDB db;
    db.add_node(Vec3(0, 0, 0), {0, 1});
    db.add_node(Vec3(1, 0, 0), {1, 2});
    if (!roomy) db.reserve_nodes(10);  // db has room: the new nodes are copied
    std::vector<Vec3> fresh;
    fresh.reserve(roomy ? 8 : 3);  // room for the two existing nodes in front
    fresh = {Vec3(2, 0, 0), Vec3(3, 0, 0), Vec3(4, 0, 0)};
    fresh.reserve(roomy ? 8 : 3);
    std::vector<NodeOwner> owners{{3, 1}, {3, 1}, {2, 5}};
    db.append_nodes(std::move(fresh), std::move(owners));
    ASSERT_EQ(db.node_count(), 5u) << roomy;
    for (int i = 0; i < 5; ++i) EXPECT_EQ(db.node(i).x(), i) << roomy;
    EXPECT_EQ(db.owner(1), (NodeOwner{1, 2}));
    EXPECT_EQ(db.owner(4), (NodeOwner{2, 5}));
    EXPECT_TRUE(fresh.empty() && owners.empty());
  }
  MeshDB db;
  EXPECT_THROW(db.append_nodes({Vec3(0, 0, 0)}, {}), std::invalid_argument);
}

}  // namespace
}  // namespace cooperage::mesh
