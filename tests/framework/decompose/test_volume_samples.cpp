// The points a piece stands for: from its model (volume_samples) and from
// the kernel's solid before any model is built (SolidPieces::
// boundary_samples). The search drops slivers on the second and scores cuts
// as it did on the first, so the two must be the same points.
#include "framework/decompose/volume_samples.h"
#include "framework/geometry/occ/solid_pieces.h"
#include "framework/geometry/occ/workbench.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace cooperage::decompose {
namespace {

std::vector<geom::Vec3> sorted(std::vector<geom::Vec3> points) {
  std::sort(points.begin(), points.end(), [](const geom::Vec3& a, const geom::Vec3& b) {
    return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
  });
  return points;
}

TEST(VolumeSamples, TheSolidsPointsAreItsModelsPoints) {
  occ::Workbench bench;
  bench.brick("block", {0, 0, 0}, {6, 4, 2});
  bench.cylinder("hole", {3, 2, -1}, {0, 0, 1}, 1.0, 4.0);
  bench.cut("part", {"block", "hole"});
  const occ::SolidPieces one = occ::SolidPieces::of(bench);
  // A plane through the hole: two pieces, each with half the hole's wall.
  const occ::SolidPieces pieces =
      one.split(0, {occ::CutSurface::Kind::Plane, {3, 2, 0}, {1, 0, 0}, 0});
  ASSERT_EQ(pieces.size(), 2);
  const geom::Model model = pieces.build_model(false);
  for (int k = 0; k < pieces.size(); ++k) {
    const auto from_model = sorted(volume_samples(model, k + 1));
    const auto from_solid = sorted(pieces.boundary_samples(k, kSamplesPerCurve));
    ASSERT_EQ(from_model.size(), from_solid.size()) << "piece " << k;
    for (size_t i = 0; i < from_model.size(); ++i)
      EXPECT_EQ(from_model[i], from_solid[i]) << "piece " << k << ", point " << i;
  }
}

}  // namespace
}  // namespace cooperage::decompose
