// Which caps are cut (cap_roles.h) when footprints are circles sampled
// differently: a bolt head's underside, an annulus whose rim a neighbour's
// edge split into three curves, under the head's top, whose rim is two
// curves (gmsh_as1-tu-203, volume 6). The two polylines of one circle
// differ by their chords' sagittas; that is not a cut, so the underside is
// meshed by its surface scheme and the volume beside it can take it.
#include "schemes/cooper/side_lattice.h"
#include "schemes/cooper/cap_roles.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace cooperage::cooper {
namespace {

using geom::Vec3;

constexpr double kPi = 3.14159265358979323846;
const Vec3 kMinusZ(0, 0, -1);

struct FactsBuilder {
  VolumeFacts facts;
  int next_curve = 1;
  int next_vertex = 1;

  // A circle of radius r about (cx, cy) at height z, split at `cuts`
  // (angles in degrees, ascending, the first at the start), walked
  // counter-clockwise or not; 16 segments per curve, as gather_facts().
  std::vector<UseFact> circle(double cx, double cy, double r, double z,
                              const std::vector<double>& cuts, bool ccw) {
    std::vector<int> vertices;
    for (double a : cuts) {
      const double t = a * kPi / 180;
      facts.vertices[next_vertex] = Vec3(cx + r * std::cos(t), cy + r * std::sin(t), z);
      vertices.push_back(next_vertex++);
    }
    std::vector<UseFact> loop;
    for (size_t k = 0; k < cuts.size(); ++k) {
      const double a0 = cuts[k] * kPi / 180;
      const double a1 = (k + 1 < cuts.size() ? cuts[k + 1] : cuts[0] + 360) * kPi / 180;
      CurveFact c;
      c.id = next_curve++;
      c.start = vertices[k];
      c.end = vertices[(k + 1) % vertices.size()];
      c.length = r * (a1 - a0);
      for (int s = 0; s <= 16; ++s) {
        const double t = a0 + (a1 - a0) * s / 16;
        c.samples.emplace_back(cx + r * std::cos(t), cy + r * std::sin(t), z);
      }
      facts.curves[c.id] = c;
      loop.push_back({c.id, true});
    }
    if (!ccw) {
      std::reverse(loop.begin(), loop.end());
      for (UseFact& u : loop) u.forward = false;
    }
    return loop;
  }

  // A polygon of straight curves through `corners` at height z, in their
  // order; 16 segments per curve, as gather_facts().
  std::vector<UseFact> polygon(const std::vector<std::pair<double, double>>& corners, double z) {
    const int first = next_vertex;
    for (const auto& [x, y] : corners) facts.vertices[next_vertex++] = Vec3(x, y, z);
    std::vector<UseFact> loop;
    for (size_t k = 0; k < corners.size(); ++k) {
      CurveFact c;
      c.id = next_curve++;
      c.start = first + static_cast<int>(k);
      c.end = first + static_cast<int>((k + 1) % corners.size());
      const Vec3 a = facts.vertices[c.start], e = facts.vertices[c.end];
      c.length = (e - a).norm();
      for (int s = 0; s <= 16; ++s) c.samples.push_back(a + (e - a) * (s / 16.0));
      facts.curves[c.id] = c;
      loop.push_back({c.id, true});
    }
    return loop;
  }

  void face(int id, std::vector<std::vector<UseFact>> loops, const Vec3& normal) {
    FaceFact f;
    f.id = id;
    f.loops = std::move(loops);
    f.planar = true;
    f.normal = normal;
    type_corners(f);
    facts.faces.push_back(f);
  }
};

// The head's underside (r 5 to 7.5, rim in three curves) and its top
// (r 7.5, two curves), 5 apart along the axis.
VolumeFacts bolt_head(double top_radius, const std::vector<double>& rim_cuts) {
  FactsBuilder b;
  b.face(1, {b.circle(0, 0, 7.5, 0, rim_cuts, true), b.circle(0, 0, 5, 0, {0, 180}, false)},
         Vec3(0, 0, -1));
  b.face(2, {b.circle(0, 0, top_radius, 5, {90, 270}, true)}, Vec3(0, 0, 1));
  return b.facts;
}

bool cut(const VolumeFacts& facts, int cap) {
  const std::vector<int> c = cut_caps(facts, {1, 2}, kMinusZ, 5e-3);
  return std::find(c.begin(), c.end(), cap) != c.end();
}

TEST(CapRoles, TwoSamplingsOfOneRimDoNotCutTheCap) {
  // Split at 0, 30 and 180 degrees: the samples of the two rims differ.
  EXPECT_FALSE(cut(bolt_head(7.5, {0, 30, 180}), 1));
  // The top is cut: the underside's hole lies inside its footprint.
  EXPECT_TRUE(cut(bolt_head(7.5, {0, 30, 180}), 2));
}

TEST(CapRoles, ATopSmallerThanTheRimStillCutsTheUnderside) {
  // A top of radius 7.3 reaches 0.2 into the annulus: a real imprint, far
  // deeper than the 0.036 a chord of the rim can fall inside it.
  EXPECT_TRUE(cut(bolt_head(7.3, {0, 30, 180}), 1));
}

// A pocket floor's leg 0.15 wide (x 13.78-13.93) and a foot's circle of
// radius 4.44 below it (campaign seed 7 case 50): the circle crosses the
// leg, so the floor is cut, though the leg is narrower than twice the
// circle's chord sagitta (0.085) that a sampling of one rim may differ by.
TEST(CapRoles, ACircleCrossingANarrowLegCutsTheCap) {
  FactsBuilder b;
  b.face(1, {b.polygon({{13.78, 5.7}, {13.93, 5.7}, {13.93, 8.32}, {13.78, 8.32}}, 0)},
         Vec3(0, 0, 1));
  b.face(2, {b.circle(17.63, 4.76, 4.44, -5, {0}, true)}, Vec3(0, 0, -1));
  const std::vector<int> c = cut_caps(b.facts, {1, 2}, kMinusZ, 1e-4);
  EXPECT_NE(std::find(c.begin(), c.end(), 1), c.end());
}

}  // namespace
}  // namespace cooperage::cooper
