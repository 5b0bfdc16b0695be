// simplify_faces: vertex clustering keeps the budget, the extent and the
// worst value of the faces it merges.
#include "framework/report/simplify_faces.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace cooperage::report {
namespace {

// An n x n grid of unit quads in the z = 0 plane, values 0.9.
FaceSoup plate(int n) {
  FaceSoup s;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) s.points.emplace_back(i, j, 0);
  }
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i;
      s.faces.push_back({a, a + 1, a + n + 2, a + n + 1});
      s.values.push_back(0.9);
    }
  }
  return s;
}

TEST(SimplifyFaces, UnderBudgetIsUnchanged) {
  const FaceSoup in = plate(4);
  const FaceSoup out = simplify_faces(in, 16);
  EXPECT_EQ(out.faces, in.faces);
  EXPECT_EQ(out.points.size(), in.points.size());
}

TEST(SimplifyFaces, KeepsTheBudgetTheExtentAndTheWorstValue) {
  FaceSoup in = plate(100);  // 10000 faces
  in.values[5050] = 0.05;    // one poor element in the middle
  const FaceSoup out = simplify_faces(in, 500);
  ASSERT_FALSE(out.faces.empty());
  EXPECT_LE(out.faces.size(), 500u);
  EXPECT_GE(out.faces.size(), 100u) << "the finest grid within budget is used";
  EXPECT_EQ(out.values.size(), out.faces.size());
  EXPECT_DOUBLE_EQ(*std::min_element(out.values.begin(), out.values.end()), 0.05);
  // Every point is used by a face, and the plate still spans about 0..100.
  std::vector<bool> used(out.points.size(), false);
  for (const auto& f : out.faces) {
    for (int v : f) {
      if (v >= 0) used[static_cast<std::size_t>(v)] = true;
    }
  }
  EXPECT_TRUE(std::all_of(used.begin(), used.end(), [](bool u) { return u; }));
  double lo = 1e9, hi = -1e9;
  for (const auto& p : out.points) {
    lo = std::min(lo, p.x());
    hi = std::max(hi, p.x());
    EXPECT_DOUBLE_EQ(p.z(), 0.0);
  }
  EXPECT_LT(lo, 10.0);
  EXPECT_GT(hi, 90.0);
}

TEST(SimplifyFaces, DropsCollapsedFacesAndKeepsTriangles) {
  FaceSoup in;
  in.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1e-9, 1e-9, 0}, {100, 100, 0}, {0, 100, 0}};
  in.faces = {{0, 1, 2, -1}, {0, 3, 2, -1}, {1, 4, 5, 2}};
  in.values = {0.5, 0.2, 0.7};
  const FaceSoup out = simplify_faces(in, 2);
  EXPECT_LE(out.faces.size(), 2u);
  for (const auto& f : out.faces) {
    const int n = f[3] < 0 ? 3 : 4;
    for (int a = 0; a < n; ++a) {
      for (int b = a + 1; b < n; ++b) EXPECT_NE(f[a], f[b]) << "degenerate face kept";
    }
  }
}

TEST(SimplifyFaces, IsDeterministic) {
  FaceSoup in = plate(60);
  const FaceSoup a = simplify_faces(in, 300);
  const FaceSoup b = simplify_faces(in, 300);
  EXPECT_EQ(a.faces, b.faces);
  EXPECT_EQ(a.values, b.values);
}

}  // namespace
}  // namespace cooperage::report
