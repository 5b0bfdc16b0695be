// to_openmesh / from_openmesh: the surface elements of a MeshDB as an
// OpenMesh half-edge mesh and back, checked against the topology and
// geometry of the boxes of the exporter fixtures.
#include "framework/core/error.h"
#include "framework/openmesh/surface_mesh.h"

#include "export_fixtures.h"

#include <gtest/gtest.h>

#include <set>

namespace cooperage::om {
namespace {

using test::TestMesh;

/// Volume enclosed by the faces (divergence theorem over a triangle fan):
/// positive when they face outward.
double enclosed_volume(const SurfaceMesh& m) {
  double v = 0;
  for (const auto f : m.faces()) {
    std::vector<SurfaceMesh::Point> p;
    for (const auto x : m.fv_range(f)) p.push_back(m.point(x));
    for (size_t k = 1; k + 1 < p.size(); ++k)
      v += OpenMesh::dot(p[0], OpenMesh::cross(p[k], p[k + 1])) / 6.0;
  }
  return v;
}

int node_of(const SurfaceMesh& m, SurfaceMesh::VertexHandle v) {
  OpenMesh::VPropHandleT<int> h;
  EXPECT_TRUE(m.get_property_handle(h, kNodeProperty));
  return m.property(h, v);
}

TEST(ToOpenMesh, ACubeSkinIsAClosedManifoldWithTheMeshDbNodes) {
  const TestMesh t = test::surface_only();  // 2x2x2 cube skin: 26 nodes, 24 quads
  const SurfaceMesh m = to_openmesh(t.db, t.model);
  EXPECT_EQ(m.n_vertices(), 26u);
  EXPECT_EQ(m.n_faces(), 24u);
  EXPECT_EQ(m.n_edges(), 48u);  // Euler: V - E + F = 2 for a sphere
  for (const auto h : m.halfedges()) EXPECT_FALSE(m.is_boundary(h));
  for (const auto f : m.faces()) EXPECT_EQ(m.valence(f), 4u);
  for (const auto v : m.vertices()) {
    const auto& x = t.db.node(node_of(m, v));
    const auto& p = m.point(v);
    EXPECT_EQ(p[0], x.x());  // double coordinates, copied exactly
    EXPECT_EQ(p[1], x.y());
    EXPECT_EQ(p[2], x.z());
  }
  EXPECT_NEAR(enclosed_volume(m), 1.0, 1e-12);  // faces point outward
}

TEST(ToOpenMesh, RoundTripGivesTheSameFacesOnTheSameSurfaces) {
  const TestMesh t = test::surface_only();
  const SurfaceMesh m = to_openmesh(t.db, t.model);
  const mesh::MeshDB back = from_openmesh(m);
  ASSERT_EQ(back.node_count(), m.n_vertices());
  EXPECT_EQ(back.surfaces().size(), t.db.surfaces().size());
  // Every face comes back on its surface, with its nodes in the same order
  // (vertex v of the OpenMesh mesh is node node_of(v) of the original).
  std::vector<int> original(m.n_vertices());
  for (const auto v : m.vertices()) original[static_cast<size_t>(v.idx())] = node_of(m, v);
  for (const auto& [sid, s] : t.db.surfaces()) {
    const auto& b = back.surface(sid);
    ASSERT_EQ(b.quads.size(), s.quads.size()) << "surface " << sid;
    for (size_t i = 0; i < s.quads.size(); ++i) {
      for (int k = 0; k < 4; ++k)
        EXPECT_EQ(original[static_cast<size_t>(b.quads[i][k])], s.quads[i][k]);
    }
  }
  for (size_t i = 0; i < back.node_count(); ++i)
    EXPECT_EQ(back.node(static_cast<int>(i)), t.db.node(original[i]));
}

TEST(ToOpenMesh, BoundaryOfAVolumeMeshLeavesOutTheSharedSurfaceAndFacesOutward) {
  const TestMesh t = test::two_blocks();  // [0,2]x[0,1]^2 in 4x2x2 hexes, two volumes
  const SurfaceMesh m = to_openmesh(t.db, t.model, SurfaceSelection::Boundary);
  EXPECT_EQ(m.n_faces(), 40u);     // 2*8 + 2*8 + 2*4
  EXPECT_EQ(m.n_vertices(), 42u);  // 5*3*3 grid nodes less the 3 inside
  for (const auto h : m.halfedges()) EXPECT_FALSE(m.is_boundary(h));
  EXPECT_NEAR(enclosed_volume(m), 2.0, 1e-12);
}

TEST(ToOpenMesh, TheSecondVolumesSkinIsFlippedWhenTheFirstIsNotMeshed) {
  TestMesh t = test::two_blocks();
  t.db.mutable_volume(1).hexes.clear();  // only volume 2 meshed: the shared face is its skin
  const SurfaceMesh m = to_openmesh(t.db, t.model, SurfaceSelection::Boundary);
  EXPECT_EQ(m.n_faces(), 24u);
  for (const auto h : m.halfedges()) EXPECT_FALSE(m.is_boundary(h));
  EXPECT_NEAR(enclosed_volume(m), 1.0, 1e-12);
}

TEST(ToOpenMesh, NonManifoldEdgesGetCopiedVerticesAndNoFaceIsLost) {
  // All surfaces of the two boxes, the shared one included: its edges carry
  // three faces, which a half-edge mesh cannot hold.
  const TestMesh t = test::two_blocks();
  const SurfaceMesh m = to_openmesh(t.db, t.model, SurfaceSelection::All);
  size_t faces = 0;
  for (const auto& [sid, s] : t.db.surfaces()) faces += s.size();
  EXPECT_EQ(m.n_faces(), faces);
  EXPECT_GT(m.n_vertices(), 45u - 3u);  // copies were made
  for (const auto v : m.vertices()) {
    const auto& x = t.db.node(node_of(m, v));
    EXPECT_EQ(m.point(v), SurfaceMesh::Point(x.x(), x.y(), x.z()));
  }
}

TEST(FromOpenMesh, APentagonIsRefusedNamingTheFace) {
  SurfaceMesh m;
  std::vector<SurfaceMesh::VertexHandle> v;
  for (int i = 0; i < 5; ++i)
    v.push_back(m.add_vertex({std::cos(i * 1.2566), std::sin(i * 1.2566), 0}));
  m.add_face(v);
  try {
    from_openmesh(m);
    ADD_FAILURE() << "no error";
  } catch (const MeshingError& e) {
    EXPECT_NE(std::string(e.what()).find("face 0 has 5 vertices"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace cooperage::om
