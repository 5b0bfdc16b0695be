// Reproducers found by fuzz/fuzz_triangulate.cpp (issue 21 item 6): each
// input must end in MeshingError(InvalidInput) or a triangulation whose
// triangles are all counter-clockwise in the input's own coordinates.
#include "framework/core/error.h"
#include "framework/mesh2d/predicates.h"
#include "framework/mesh2d/triangulate.h"

#include <gtest/gtest.h>

#include <cmath>

namespace cooperage::mesh2d {
namespace {

using P = Eigen::Vector2d;

TEST(TriangulateFuzzFindings, ALoopThatTurnsBackOnItselfIsRefused) {
  // crash-461e887053af267dbf4c0133d7f640c5e198e1f6: the loop runs from B to
  // C and back to D between them; the work frame's rotation made a sliver
  // of B, C, D, returned as a zero-area triangle.
  const std::vector<std::vector<P>> loops{{P(-0.843719482421875, 0.046905517578125),
                                           P(0.0, 0.0078125), P(0.98828125, 0.0078125),
                                           P(0.0078125, 0.0078125)}};
  for (bool refine : {false, true}) {
    RefineOptions options;
    options.refine = refine;
    try {
      const Triangulation2D t = triangulate(loops, options);
      for (const auto& tri : t.triangles)
        EXPECT_GT(
            orient2d(t.points[static_cast<size_t>(tri[0])], t.points[static_cast<size_t>(tri[1])],
                     t.points[static_cast<size_t>(tri[2])]),
            0.0);
      ADD_FAILURE() << "accepted a loop that overlaps itself";
    } catch (const MeshingError& e) {
      EXPECT_EQ(e.code(), ErrorCode::InvalidInput);
      EXPECT_NE(std::string(e.what()).find("turns back on itself at point 2"), std::string::npos)
          << e.what();
    }
  }
}

TEST(TriangulateFuzzFindings, StraightSidesWithManyPointsStillTriangulate) {
  // The checks above must not refuse collinear points along a straight side,
  // in any orientation of the input (the work frame is rotated).
  for (double angle : {0.0, 0.3, 1.0, 2.5}) {
    const double c = std::cos(angle), s = std::sin(angle);
    std::vector<P> loop;
    auto add = [&](double x, double y) {
      loop.emplace_back(c * x - s * y + 1e3, s * x + c * y - 7.0);
    };
    for (int i = 0; i < 10; ++i) add(0.1 * i, 0.0);
    for (int i = 0; i < 10; ++i) add(1.0, 0.1 * i);
    for (int i = 0; i < 10; ++i) add(1.0 - 0.1 * i, 1.0);
    for (int i = 0; i < 10; ++i) add(0.0, 1.0 - 0.1 * i);
    const Triangulation2D t = triangulate({loop});
    EXPECT_FALSE(t.triangles.empty());
  }
}

}  // namespace
}  // namespace cooperage::mesh2d
