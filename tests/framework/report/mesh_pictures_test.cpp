// build_pictures: a part's skin is the faces used by one of its elements;
// surface parts draw every element; the worst elements are found, inside too.
#include "framework/report/mesh_pictures.h"

#include <gtest/gtest.h>

#include <array>
#include <set>

namespace cooperage::report {
namespace {

// An n x n x n lattice of unit hexes (Exodus order) over (n+1)^3 nodes.
struct Lattice {
  std::vector<Eigen::Vector3d> coords;
  std::vector<std::array<int, 8>> hexes;
  explicit Lattice(int n, double x0 = 0) {
    const auto id = [n](int i, int j, int k) { return (k * (n + 1) + j) * (n + 1) + i; };
    for (int k = 0; k <= n; ++k)
      for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) coords.emplace_back(x0 + i, j, k);
    for (int k = 0; k < n; ++k)
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
          hexes.push_back({id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k),
                           id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1),
                           id(i, j + 1, k + 1)});
  }
};

ElementBlock hex_block(const std::vector<std::array<int, 8>>& hexes, const std::string& name) {
  ElementBlock b;
  b.name = name;
  b.part = name;
  b.type = quality::ElementType::Hex;
  b.connectivity = hexes.front().data();
  b.count = hexes.size();
  b.stride = 8;
  return b;
}

TEST(MeshPictures, SkinOfACubeOfEightHexesHas24Faces) {
  const Lattice cube(2);
  ReportInput in;
  in.coords = &cube.coords;
  in.blocks.push_back(hex_block(cube.hexes, "volume 1"));
  std::vector<std::vector<double>> sj = {std::vector<double>(8, 1.0)};
  const auto pictures = build_pictures(in, sj, ReportOptions{});
  ASSERT_EQ(pictures.size(), 1u);
  EXPECT_EQ(pictures[0].boundary_faces, 24u);
  EXPECT_EQ(pictures[0].surface.faces.size(), 24u);
  EXPECT_EQ(pictures[0].surface.points.size(), 26u) << "every node but the centre";
  EXPECT_EQ(pictures[0].elements, 8u);
  // Every drawn face lies on a side of the cube.
  for (const auto& f : pictures[0].surface.faces) {
    int on_side = 0;
    for (int c = 0; c < 3; ++c) {
      for (double side : {0.0, 2.0}) {
        bool all = true;
        for (int v : f)
          all = all && pictures[0].surface.points[static_cast<std::size_t>(v)][c] == side;
        on_side += all;
      }
    }
    EXPECT_EQ(on_side, 1);
  }
}

TEST(MeshPictures, BoundaryMaskGivesTheSameSkin) {
  const Lattice cube(3);
  ReportInput in;
  in.coords = &cube.coords;
  in.blocks.push_back(hex_block(cube.hexes, "volume 1"));
  std::vector<std::vector<double>> sj = {std::vector<double>(27, 1.0)};
  const auto plain = build_pictures(in, sj, ReportOptions{});
  in.maybe_boundary.assign(cube.coords.size(), true);
  for (std::size_t i = 0; i < cube.coords.size(); ++i) {
    const auto& p = cube.coords[i];
    const bool inside = p.x() > 0 && p.x() < 3 && p.y() > 0 && p.y() < 3 && p.z() > 0 && p.z() < 3;
    in.maybe_boundary[i] = !inside;
  }
  const auto masked = build_pictures(in, sj, ReportOptions{});
  ASSERT_EQ(masked.size(), 1u);
  EXPECT_EQ(masked[0].boundary_faces, 54u);
  EXPECT_EQ(masked[0].surface.faces, plain[0].surface.faces);
}

TEST(MeshPictures, OnePicturePerPartAndTheWorstElementInside) {
  const Lattice a(3), b(1, 5.0);
  // Both lattices index their own coordinates: put b's after a's.
  std::vector<Eigen::Vector3d> coords = a.coords;
  coords.insert(coords.end(), b.coords.begin(), b.coords.end());
  std::vector<std::array<int, 8>> b_hexes = b.hexes;
  for (auto& h : b_hexes)
    for (int& v : h) v += static_cast<int>(a.coords.size());
  ReportInput in;
  in.coords = &coords;
  in.blocks.push_back(hex_block(a.hexes, "volume 1"));
  in.blocks.push_back(hex_block(b_hexes, "volume 2"));
  std::vector<double> a_sj(27, 0.9);
  a_sj[13] = 0.1;  // the centre hex, touching no boundary
  a_sj[0] = 0.5;
  std::vector<std::vector<double>> sj = {a_sj, {0.8}};
  ReportOptions options;
  options.worst_marked = 2;
  const auto pictures = build_pictures(in, sj, options);
  ASSERT_EQ(pictures.size(), 2u);
  EXPECT_EQ(pictures[0].part, "volume 1");
  EXPECT_EQ(pictures[1].part, "volume 2");
  EXPECT_EQ(pictures[1].boundary_faces, 6u);
  ASSERT_EQ(pictures[0].worst.size(), 2u);
  EXPECT_EQ(pictures[0].worst[0].index, 13u);
  EXPECT_DOUBLE_EQ(pictures[0].worst[0].scaled_jacobian, 0.1);
  EXPECT_TRUE(pictures[0].worst[0].centroid.isApprox(Eigen::Vector3d(1.5, 1.5, 1.5)));
  EXPECT_EQ(pictures[0].worst[1].index, 0u);
  // The centre hex has no boundary face, so no drawn face carries 0.1.
  for (double v : pictures[0].surface.values) EXPECT_NE(v, 0.1);
}

TEST(MeshPictures, SurfacePartsDrawEveryElementAndBlocksWithoutPartNone) {
  std::vector<Eigen::Vector3d> coords = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0, 0}};
  std::vector<int> quads = {0, 1, 2, 3};
  std::vector<int> tris = {1, 4, 2};
  ReportInput in;
  in.coords = &coords;
  ElementBlock q;
  q.name = "surface 1";
  q.part = "all surfaces";
  q.type = quality::ElementType::Quad;
  q.connectivity = quads.data();
  q.count = 1;
  q.stride = 4;
  ElementBlock t = q;
  t.name = "surface 2";
  t.type = quality::ElementType::Tri;
  t.connectivity = tris.data();
  t.stride = 3;
  ElementBlock hidden = t;
  hidden.part = "";
  in.blocks = {q, t, hidden};
  const auto pictures = build_pictures(in, {{1.0}, {0.7}, {0.7}}, ReportOptions{});
  ASSERT_EQ(pictures.size(), 1u);
  ASSERT_EQ(pictures[0].surface.faces.size(), 2u);
  EXPECT_EQ(pictures[0].surface.faces[1][3], -1) << "a triangle";
  EXPECT_EQ(pictures[0].worst.front().block, "surface 2");
}

TEST(MeshPictures, BigPartsAreSimplifiedToTheBudget) {
  const Lattice cube(30);  // 5400 boundary faces
  ReportInput in;
  in.coords = &cube.coords;
  in.blocks.push_back(hex_block(cube.hexes, "volume 1"));
  std::vector<std::vector<double>> sj = {std::vector<double>(cube.hexes.size(), 1.0)};
  ReportOptions options;
  options.max_drawn_faces = 1000;
  const auto pictures = build_pictures(in, sj, options);
  ASSERT_EQ(pictures.size(), 1u);
  EXPECT_EQ(pictures[0].boundary_faces, 5400u);
  EXPECT_LE(pictures[0].surface.faces.size(), 1000u);
  EXPECT_GT(pictures[0].surface.faces.size(), 200u);
}

}  // namespace
}  // namespace cooperage::report
