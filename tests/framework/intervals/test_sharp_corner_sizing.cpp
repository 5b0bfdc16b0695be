// First intervals at sharp corners, on a part whose corner follows from
// its shape: a block with a round lug standing 0.04 proud of one side. The
// lug's bottom face has a horn where the lug's circle (radius 4.92) crosses
// the block's side, at asin(0.6263 / 4.92) = 7.31 degrees, and the circle
// bends towards the side there.
#include "framework/intervals/sharp_corner_sizing.h"

#include "framework/geometry/occ/workbench.h"
#include "framework/intervals/curve_sizing.h"

#include <gtest/gtest.h>

#include <cmath>

namespace cooperage::intervals {
namespace {

using geom::Vec3;

constexpr double kRadius = 4.92;

geom::Model block_with_lug() {
  occ::Workbench wb;
  wb.brick("block", {0, 0, 0}, {62.99, 25.52, 32.12});
  wb.cylinder("lug", {62.99, 20.64, 10.03}, {0, 0, 1}, kRadius, 22.09);
  wb.fuse("part", {"block", "lug"});
  return wb.build_model();
}

/// The corner's angle from the lug's placement: the circle meets the plane
/// y = 25.52 where its radius makes asin(dx / r) with the y axis.
double horn_angle() {
  const double dy = 25.52 - 20.64;
  const double dx = std::sqrt(kRadius * kRadius - dy * dy);
  return std::asin(dx / kRadius);
}

/// The horn vertices: on the block's side and the lug's circle, left of
/// the lug's axis.
bool at_horn(const Vec3& p) {
  return std::abs(p.y() - 25.52) < 1e-6 && p.x() < 62.99 - 0.1 &&
         std::abs(std::hypot(p.x() - 62.99, p.y() - 20.64) - kRadius) < 1e-6;
}

TEST(SharpCornerSizing, AnArcBendingIntoAHornStartsShortEnoughToKeepHalfOfIt) {
  const geom::Model model = block_with_lug();
  const double size = 6.0;
  const auto bounds = sharp_corner_sizes(model, [&](int) { return size; });
  // Two chords of length h, the arc's turning by h / (2 r) towards the side
  // and the side's not at all, close a quarter of the corner at most:
  // h <= 2 * 0.25 * angle * r.
  const double expected = 0.5 * horn_angle() * kRadius;
  int arcs = 0, lines = 0;
  for (const EndSize& e : bounds) {
    const geom::Curve& c = model.curve(e.curve);
    const Vec3 v = model.vertex(e.at_start ? c.start_vertex : c.end_vertex).point;
    EXPECT_TRUE(at_horn(v)) << "curve " << e.curve << " at " << v.transpose();
    EXPECT_NEAR(e.size, expected, 0.02 * expected) << "curve " << e.curve;
    (c.geometry->type() == geom::CurveType::Circle ? arcs : lines) += 1;
  }
  // One horn: on the lug's bottom face, between the lug's arc and the
  // block's side. The lug's top is flush with the block's (one face, whose
  // boundary turns by only 7.31 degrees there), and the faces along the
  // lug's side meet the vertex at right angles.
  EXPECT_EQ(arcs, 1);
  EXPECT_EQ(lines, 1);
}

TEST(SharpCornerSizing, AnArcOpeningTheCornerMakesUpForOneClosingIt) {
  // A pocket's floor (radius 7.7) minus a hole (radius 4.34) whose circles
  // cross at 10.7 degrees (campaign seed 23 case 88). The floor lies inside
  // the pocket's circle and outside the hole's: the pocket's chord cuts
  // into its circle, towards the hole's arc (closing the corner at 1 / 7.7
  // per unit length and half), the hole's chord into the hole, away from
  // the floor (opening it at 1 / 4.34). The corner opens: no bound, where
  // bounding the pocket's arc alone made the tip's quads worse.
  occ::Workbench wb;
  wb.brick("block", {0, 0, 0}, {37.03, 48.07, 36.35});
  wb.cylinder("pocket", {20.1, 13.74, 27.17}, {0, 0, 1}, 7.7, 45.53);
  wb.cylinder("hole", {17.83, 16.44, -36.35}, {0, 0, 1}, 4.34, 109.05);
  wb.cut("part", {"block", "pocket", "hole"});
  const geom::Model model = wb.build_model();
  // The crossing's corner, from the circles alone.
  const double d = std::hypot(20.1 - 17.83, 13.74 - 16.44);
  const double cross = std::acos((7.7 * 7.7 + 4.34 * 4.34 - d * d) / (2 * 7.7 * 4.34));
  ASSERT_NEAR(cross * 180 / M_PI, 10.7, 0.1);
  EXPECT_TRUE(sharp_corner_sizes(model, [](int) { return 4.045; }).empty());
}

TEST(SharpCornerSizing, TheFirstChordKeepsMoreThanHalfOfTheCorner) {
  const geom::Model model = block_with_lug();
  const double size = 6.0;
  const double angle = horn_angle();
  // The discrete corner between an arc's first chord (nodes placed by the
  // sizing) and the straight side, with and without the rule.
  auto discrete_corner = [&](bool rule) {
    SizingOptions options;
    options.sharp_corners = rule;
    const auto sizing = curve_sizing(
        model, [&](int) { return size; }, options);
    double worst = INFINITY;
    for (const geom::Curve& c : model.curves()) {
      if (c.geometry->type() != geom::CurveType::Circle) continue;
      for (bool at_start : {true, false}) {
        const Vec3 v = model.vertex(at_start ? c.start_vertex : c.end_vertex).point;
        if (!at_horn(v)) continue;
        const CurveSizing& z = sizing.at(c.id);
        mesh::CurveSpacing sp;
        sp.kind = mesh::CurveSpacing::Kind::Sized;
        sp.sizes = z.sizes;
        const int n = std::max(z.min, static_cast<int>(whole_goal(z.goal)));
        const auto s = mesh::spacing_fractions(n, c.length, sp);
        const double along = at_start ? s[1] * c.length : (1.0 - s[s.size() - 2]) * c.length;
        const Vec3 q =
            c.geometry->point(c.geometry->parameter_at_length(at_start ? along : c.length - along));
        // The side runs along x into the horn (towards the lug's axis).
        const Vec3 chord = (q - v).normalized();
        worst = std::min(worst, std::atan2(std::abs(chord.y()), chord.x()));
      }
    }
    return worst;
  };
  const double with_rule = discrete_corner(true);
  const double without = discrete_corner(false);
  EXPECT_GE(with_rule, 0.5 * angle);
  // Without it the first chord at this size closes most of the corner
  // (the 0.24-degree corner the lug's cap had).
  EXPECT_LT(without, 0.5 * angle);
}

TEST(SharpCornerSizing, CornersOfRightAnglesAndStraightEdgesAreLeftAlone) {
  occ::Workbench wb;
  wb.brick("block", {0, 0, 0}, {10, 20, 5});
  wb.cylinder("hole", {5, 10, -1}, {0, 0, 1}, 3.0, 7.0);
  wb.cut("part", {"block", "hole"});
  const geom::Model model = wb.build_model();
  EXPECT_TRUE(sharp_corner_sizes(model, [](int) { return 2.0; }).empty());
}

}  // namespace
}  // namespace cooperage::intervals
